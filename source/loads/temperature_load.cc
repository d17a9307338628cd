#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/loads/temperature_load.h>

#include <cmath>

namespace liftoff
{
  namespace
  {
    /// The base's own temperature, where there is a base (Base).
    void
    declare_base_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Base profile",
        "0, 0",
        Patterns::Anything(),
        "The base's temperature through its thickness per unit of "
        "Magnitude, at equally spaced depths from its top face (against the "
        "slab) to its bed-side face, linear in between (at least two "
        "values), with the same Intensity and Time history as the slab's. "
        "It bends the base by its equivalent linear difference (its own "
        "free curvature alpha_b dT_b / H_b; in a bonded or unbonded section "
        "its free moment joins the slab's) and adds its self-equilibrating "
        "stress at the base's faces. 0, 0: the base has no temperature "
        "gradient of its own. Needs a base (Base/Interface)."
          + quantity("number"));
      prm.declare_entry("Base expansion coefficient",
                        "0",
                        Patterns::Double(),
                        "alpha_b, the base's coefficient of thermal "
                        "expansion (> 0 with a Base profile; 1/K in SI, "
                        "1e-5 by default)."
                          + si_default("1e-5") + quantity("thermal expansion"));
    }


    /// A Profile entry of `name` (Profile, Base profile) read and checked.
    TemperatureProfile
    read_profile(ParameterHandler  &prm,
                 const std::string &name,
                 const std::string &entry)
    {
      const std::string text = prm.get(entry);
      return TemperatureProfile(
        numbers_or_refuse(text,
                          name + "/" + entry + " = <" + text
                            + "> must be a list of numbers, as 1, 0."),
        name + "/" + entry);
    }


    /// Whether a profile bends or stresses (a base's of 0, 0 does not).
    bool
    heats(const TemperatureProfile &profile)
    {
      return profile.equivalent_difference() != 0
             || profile.self_equilibrating_at(0) != 0
             || profile.self_equilibrating_at(1) != 0;
    }


    /// Whether two profiles bend and stress alike.
    bool
    same_parts(const TemperatureProfile &a, const TemperatureProfile &b)
    {
      return a.equivalent_difference() == b.equivalent_difference()
             && a.self_equilibrating_at(0) == b.self_equilibrating_at(0)
             && a.self_equilibrating_at(1) == b.self_equilibrating_at(1);
    }
  } // namespace


  void
  TemperatureLoad::declare_parameters(ParameterHandler  &prm,
                                      const std::string &section)
  {
    declare_load_entries(
      prm,
      section,
      "dT, the temperature of the top face minus that of the bed-side face "
      "(> 0: warmer on top, by day; the plate curls down at its edges) in "
      "the scene's temperature unit (K in SI)",
      "temperature difference",
      [&]() {
        prm.declare_entry("Expansion coefficient",
                          "0",
                          Patterns::Double(),
                          "alpha, the coefficient of thermal expansion "
                          "(> 0; 1/K in SI, concrete's 1e-5 by default): the "
                          "free curvature is alpha dT / H in both directions."
                            + si_default("1e-5")
                            + quantity("thermal expansion"));
        prm.declare_entry("Intensity",
                          "1",
                          Patterns::Anything(),
                          "f(x, y, tau), muParser: dT = Magnitude * f * "
                          "h(tau) over the whole plate."
                            + quantity("number"));
        prm.declare_entry(
          "Profile",
          "1, 0",
          Patterns::Anything(),
          "The temperature through the thickness per unit of Magnitude, at "
          "equally spaced depths from the top face to the bed-side face, "
          "linear in between (at least two values). 1, 0 (linear): "
          "Magnitude is dT. Another profile bends the plate by its "
          "equivalent linear difference and adds its self-equilibrating "
          "stress to the stresses written at the faces."
            + quantity("number"));
        prm.declare_entry("Permanent",
                          "false",
                          Patterns::Bool(),
                          "Whether it acts from before tau = 0, as "
                          "Loads/Self weight does (built-in curl, moisture "
                          "warping as an equivalent dT): a time integration "
                          "starts from the equilibrium under it. Needs Time "
                          "history = 1 and an Intensity without tau.");
        declare_base_entries(prm);
      });
  }


  std::unique_ptr<Load>
  TemperatureLoad::read(ParameterHandler &prm, const std::string &section)
  {
    const std::string name      = "Loads/" + section;
    const double      magnitude = prm.get_double("Magnitude");
    LoadHistory       history   = LoadHistory::read(prm, name);
    Intensity         intensity(prm.get("Intensity"), name + "/Intensity");
    const double      alpha          = prm.get_double("Expansion coefficient");
    const TemperatureProfile profile = read_profile(prm, name, "Profile");
    const bool               on      = magnitude != 0.0;
    AssertThrow(!on || (alpha > 0 && std::isfinite(alpha)),
                ExcMessage(name + "/Expansion coefficient = "
                           + prm.get("Expansion coefficient")
                           + " must be > 0 (and finite) for a temperature "
                             "load that is on."));
    AssertThrow(std::isfinite(magnitude),
                ExcMessage(name + "/Magnitude must be finite."));
    const bool permanent = prm.get_bool("Permanent");
    AssertThrow(!on || !permanent
                  || (!names_tau(history.expression()) && history.at(0) == 1
                      && !intensity.depends_on_time()),
                ExcMessage(name
                           + "/Permanent = true needs Time history = 1 "
                             "and an Intensity without the time."));
    std::unique_ptr<TemperatureLoad> load(
      new TemperatureLoad(name,
                          magnitude,
                          std::move(history),
                          std::move(intensity),
                          alpha,
                          profile));
    load->permanent      = permanent;
    load->base_profile   = read_profile(prm, name, "Base profile");
    load->base_expansion = prm.get_double("Base expansion coefficient");
    const bool base_on   = on && heats(load->base_profile);
    AssertThrow(!base_on
                  || (load->base_expansion > 0
                      && std::isfinite(load->base_expansion)),
                ExcMessage(name + "/Base expansion coefficient = "
                           + prm.get("Base expansion coefficient")
                           + " must be > 0 (and finite) with a Base "
                             "profile that heats the base."));
    if (!base_on)
      load->base_expansion = 0;
    return load;
  }


  TemperatureLoad::TemperatureLoad(const std::string        &name,
                                   const double              magnitude,
                                   LoadHistory             &&history,
                                   Intensity               &&intensity,
                                   const double              expansion,
                                   const TemperatureProfile &profile)
      : DistributedLoad(name,
                        magnitude,
                        std::move(history),
                        nullptr,
                        std::move(intensity))
      , expansion(expansion)
      , profile(profile)
  {}


  void
  TemperatureLoad::use_plate(const MindlinPlate &scene_plate)
  {
    one_plus_nu     = 1 + scene_plate.poisson_ratio;
    thickness_ratio = scene_plate.thickness_ratio;
    plate           = scene_plate;
    AssertThrow(base_expansion == 0 || plate.base.present(),
                ExcMessage(name()
                           + "/Base profile heats a base, but there "
                             "is none (Base/Interface = none): give the base, "
                             "or leave Base profile at 0, 0."));
  }


  bool
  TemperatureLoad::bends_freely() const
  {
    return true;
  }


  FreeBending
  TemperatureLoad::free_bending_at(const Point<2> &x, const double tau) const
  {
    // With F0 = D / L (or alpha in the solver's units), the curvature in
    // units of D / F0 is alpha dT / Delta, and the stress E alpha / (1 -
    // nu) T in units of F0 / L^2 is 12 (1 + nu) alpha T / Delta^3, with a
    // minus sign: a part warmer than its surroundings is compressed.
    const double dt = magnitude * intensity_function().at(x, tau);
    const double stress_scale =
      -12 * one_plus_nu * expansion * dt / std::pow(thickness_ratio, 3);
    FreeBending bending{expansion * dt * profile.equivalent_difference()
                          / thickness_ratio,
                        stress_scale * profile.self_equilibrating_at(1),
                        stress_scale * profile.self_equilibrating_at(0)};
    if (base_expansion != 0)
      {
        // The base's E_b / (1 - nu_b) over the plate's E / (1 - nu).
        const BaseLayer &base = plate.base;
        const double     base_scale =
          -12 * (1 - plate.poisson_ratio * plate.poisson_ratio)
          * base.modulus_ratio / (1 - base.poisson_ratio) * base_expansion * dt
          / std::pow(thickness_ratio, 3);
        bending.base_curvature = base_expansion * dt
                                 * base_profile.equivalent_difference()
                                 / base.thickness;
        bending.base_bottom_stress =
          base_scale * base_profile.self_equilibrating_at(1);
        bending.base_top_stress =
          base_scale * base_profile.self_equilibrating_at(0);
      }
    return bending;
  }


  bool
  TemperatureLoad::touches(const PlateGeometry &, const double) const
  {
    return true;
  }


  void
  TemperatureLoad::require_on_plate(const PlateGeometry &) const
  {}


  void
  TemperatureLoad::add_spatial_part(const Discretization &disc,
                                    const double          tau,
                                    LA::MPI::Vector      &vector) const
  {
    // The thermal moment D (1 + nu) kappa_T (D = 1) against div psi_i, on
    // the rule PatchIntegrator uses on a whole cell, of every layer by its
    // section (a base's own temperature on a base of its own).
    const auto                          &fe = disc.dof_handler.get_fe();
    const QGauss<2>                      rule(fe.degree + 2);
    FEValues<2>                          values(disc.mapping(),
                       fe,
                       rule,
                       update_gradients | update_quadrature_points
                         | update_JxW_values);
    const unsigned int                   layers = PlateFields::n_layers(fe);
    Vector<double>                       cell_rhs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : disc.locally_owned_cells())
      {
        values.reinit(cell);
        cell_rhs = 0;
        std::vector<SectionCoefficients> sections;
        for (unsigned int layer = 0; layer < layers; ++layer)
          sections.push_back(plate.layer_section(cell->material_id(), layer));
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const FreeBending bending =
              free_bending_at(values.quadrature_point(q), tau);
            for (unsigned int layer = 0; layer < layers; ++layer)
              add_moment(values,
                         q,
                         layer,
                         moment_in(sections[layer], bending) * values.JxW(q),
                         cell_rhs);
          }
        cell->get_dof_indices(dofs);
        disc.constraints.distribute_local_to_global(cell_rhs, dofs, vector);
      }
    vector.compress(VectorOperation::add);
  }


  double
  TemperatureLoad::moment_in(const SectionCoefficients &section,
                             const FreeBending         &bending) const
  {
    // The layers' free moments over the plate's D (1 + nu) (the base's
    // only where it has a temperature: + 0 would change the last bits).
    double moment = section.thermal_moment * one_plus_nu * bending.curvature;
    if (bending.base_curvature != 0)
      moment +=
        section.base_thermal_moment * one_plus_nu * bending.base_curvature;
    return moment;
  }


  void
  TemperatureLoad::add_moment(const FEValues<2> &values,
                              const unsigned int q,
                              const unsigned int layer,
                              const double       moment,
                              Vector<double>    &cell_rhs)
  {
    if (moment == 0)
      return;
    const auto fields = PlateFields::extractors(layer);
    for (unsigned int i = 0; i < cell_rhs.size(); ++i)
      cell_rhs(i) += moment
                     * (values[fields.psi_x].gradient(i, q)[0]
                        + values[fields.psi_y].gradient(i, q)[1]);
  }


  void
  TemperatureLoad::integrate(const PatchIntegrator          &integrator,
                             const PatchIntegrator::Density &density,
                             const BoundingBox<2> &,
                             const double,
                             LA::MPI::Vector &vector) const
  {
    integrator.add(density, vector);
  }


  std::vector<Point<2>>
  TemperatureLoad::quadrature_points_of_image(
    const PatchIntegrator &integrator,
    const std::function<Point<2>(const Point<2> &)> &,
    const BoundingBox<2> &plate) const
  {
    return integrator.quadrature_points(plate);
  }


  bool
  TemperatureLoad::mirrors_geometry(const Load &other_load,
                                    const unsigned int,
                                    const BoundingBox<2> &,
                                    const std::vector<double> &) const
  {
    // A scalar field over the whole plate: its image is the same load with
    // the mirrored intensity (compared by DistributedLoad).
    const auto &other = static_cast<const TemperatureLoad &>(other_load);
    return expansion == other.expansion && same_parts(profile, other.profile)
           && base_expansion == other.base_expansion
           && same_parts(base_profile, other.base_profile)
           && permanent == other.permanent;
  }
} // namespace liftoff
