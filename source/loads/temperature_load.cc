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
      });
  }


  std::unique_ptr<Load>
  TemperatureLoad::read(ParameterHandler &prm, const std::string &section)
  {
    const std::string name      = "Loads/" + section;
    const double      magnitude = prm.get_double("Magnitude");
    LoadHistory       history   = LoadHistory::read(prm, name);
    Intensity         intensity(prm.get("Intensity"), name + "/Intensity");
    const double      alpha         = prm.get_double("Expansion coefficient");
    const std::string profile_entry = name + "/Profile";
    const TemperatureProfile profile(
      numbers_or_refuse(prm.get("Profile"),
                        profile_entry + " = <" + prm.get("Profile")
                          + "> must be a list of numbers, as 1, 0."),
      profile_entry);
    const bool on = magnitude != 0.0;
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
    load->permanent = permanent;
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
    return {expansion * dt * profile.equivalent_difference() / thickness_ratio,
            stress_scale * profile.self_equilibrating_at(1),
            stress_scale * profile.self_equilibrating_at(0)};
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
    // the rule PatchIntegrator uses on a whole cell.
    const auto                      &fe = disc.dof_handler.get_fe();
    const QGauss<2>                  rule(fe.degree + 2);
    FEValues<2>                      values(disc.mapping(),
                       fe,
                       rule,
                       update_gradients | update_quadrature_points
                         | update_JxW_values);
    const FEValuesExtractors::Scalar psi_x = PlateFields::rotation_extractor(0),
                                     psi_y = PlateFields::rotation_extractor(1);
    Vector<double>                       cell_rhs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : disc.locally_owned_cells())
      {
        values.reinit(cell);
        cell_rhs = 0;
        // The slab's D_s (1 + nu) alpha dT / H_s over the plate's.
        const double section =
          plate.section(cell->material_id()).thermal_moment;
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const double moment =
              section * one_plus_nu
              * free_bending_at(values.quadrature_point(q), tau).curvature
              * values.JxW(q);
            for (unsigned int i = 0; i < cell_rhs.size(); ++i)
              cell_rhs(i) += moment
                             * (values[psi_x].gradient(i, q)[0]
                                + values[psi_y].gradient(i, q)[1]);
          }
        cell->get_dof_indices(dofs);
        disc.constraints.distribute_local_to_global(cell_rhs, dofs, vector);
      }
    vector.compress(VectorOperation::add);
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
    return expansion == other.expansion
           && profile.equivalent_difference()
                == other.profile.equivalent_difference()
           && profile.self_equilibrating_at(0)
                == other.profile.self_equilibrating_at(0)
           && profile.self_equilibrating_at(1)
                == other.profile.self_equilibrating_at(1)
           && permanent == other.permanent;
  }
} // namespace liftoff
