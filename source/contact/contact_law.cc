#include <deal.II/base/mpi.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/contact/contact_law.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace
  {
    using Model                        = ContactLaw::Model;
    const Selection<Model> model_names = {{"tensionless", Model::tensionless},
                                          {"bilateral", Model::bilateral},
                                          {"none", Model::none}};

    /// The springs' entries of `Foundation`.
    void
    declare_spring_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Model",
                        "tensionless",
                        model_names.pattern(),
                        "tensionless: springs act only where w > 0; bilateral: "
                        "linear springs of both signs (for checks); none: no "
                        "foundation.");
      prm.declare_entry("Stiffness",
                        "1",
                        Patterns::Double(0.0, 1e12),
                        "Gamma = K_f L^4 / D, the dimensionless Winkler "
                        "modulus (at most 1e12: beyond it the plate's "
                        "stiffness is lost in the bed's in double precision; "
                        "at 1e16 a static run gave w 3e4 times too large "
                        "with a balanced energy, doc/reliability.md)."
                          + quantity("Gamma"));
      prm.declare_entry(
        "Contact tolerance",
        "1e-9",
        Patterns::Double(0.0, 1e-3),
        "Round-off band of the contact rule, relative to max |w_h| over all "
        "Gauss points of the plate: a point comes into contact when w_h rises "
        "above tolerance * max |w_h| and leaves it when w_h falls below "
        "-tolerance * max |w_h|; inside the band it keeps its status. There "
        "the sign of w_h would depend on the linear solver and the number of "
        "ranks. 0 gives the bare rule w_h > 0. At most 1e-3: a point in the "
        "band may keep or lack a spring force of up to tolerance * Gamma * "
        "max |w_h|, so the band perturbs the foundation pressure by up to "
        "tolerance times its peak; 1e-3 still covers the worst round-off the "
        "Plate bounds admit (6e-4 at Delta = 1e-5), while a tolerance of 1 "
        "freezes every status and makes the foundation bilateral."
          + quantity("number"));
    }


    /// The gap, dashpots and shear layer beside the springs.
    void
    declare_parameters_beside_springs(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Initial gap",
        "0",
        Patterns::Anything(),
        "g(x, y), muParser in x, y of the full plate: the distance between the "
        "unloaded plate and the bed, in the unit of w, F0 L^2 / D (w is "
        "positive into the bed). The springs act where w > g with the pressure "
        "Gamma (w - g): "
        "g > 0 is a gap (a curled slab, a void), g < 0 a pre-compression (a "
        "settled support). Must be finite on the plate, and symmetric on a "
        "half or quarter model. The contact tolerance applies to w - g."
          + quantity("deflection"));
      prm.declare_entry(
        "Damping",
        "0",
        Patterns::Double(0.0, 1e8),
        "c = C_f L^2 / sqrt(rho H D), dashpots per unit area beside the "
        "springs (a viscous subgrade; 0: none; at most 1e8, where the "
        "contact set of a point load no longer settles). They act only in "
        "contact, "
        "and the pressure Gamma (w - g) + c w_dot is never tensile: where "
        "spring and dashpot together would pull, the point is out of contact "
        "(doc/model.md). The dissipated energy becomes a history column."
          + quantity("damping"));
      prm.declare_entry(
        "Damping ratio",
        "0",
        Patterns::Double(0.0, 1e3),
        "zeta, the dashpots as a share of their critical value (instead of "
        "Damping or Units/Dashpot coefficient, which then stay 0): c = zeta "
        "2 sqrt(Gamma m), in SI C = zeta 2 sqrt(k m) per unit area, m the "
        "mass per area on the bed (rho H of the Plate's thickness, plus "
        "rho_b H_b under a Base). Critical is the dashpot at which that "
        "mass moving as a rigid body on the springs, all in contact, no "
        "longer oscillates (doc/model.md)."
          + quantity("number"));
      prm.declare_entry(
        "Shear modulus",
        "0",
        Patterns::Double(0.0, 1e12),
        "G_p = G_f L^2 / D, the dimensionless shear modulus of a Pasternak "
        "shear layer on the springs (0: none, a Winkler bed; at most 1e12: at "
        "1e14 the energy balance is off by 1.4e-3, at 1e20 by its whole "
        "size). The layer "
        "stores 1/2 G_p |grad w|^2 per unit area over the contact region "
        "(the whole plate when bilateral) and adds -G_p Lap w to the "
        "foundation pressure there. Tensionless: the layer acts only where "
        "the plate is in contact, the layer outside is not modelled "
        "(doc/model.md); the contact rule w > g is unchanged."
          + quantity("shear layer"));
    }
  } // namespace


  void
  ContactLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Foundation");
    declare_spring_parameters(prm);
    declare_parameters_beside_springs(prm);
    prm.leave_subsection();
  }


  void
  ContactLaw::describe_for_units(ParameterHandler            &scene,
                                 PhysicalUnits::SceneOutline &outline)
  {
    scene.enter_subsection("Foundation");
    const bool has_bed = scene.get("Model") != "none";
    scene.leave_subsection();
    if (has_bed)
      outline.required.emplace_back("Subgrade modulus",
                                    "a Foundation/Model other than none");
  }


  void
  ContactLaw::parse_parameters(ParameterHandler  &prm,
                               const double       mass_per_area,
                               const std::string &gap_entry_name)
  {
    gap_entry = gap_entry_name;
    prm.enter_subsection("Foundation");
    model_type        = model_names.parse(prm.get("Model"), "Foundation/Model");
    gamma             = prm.get_double("Stiffness");
    contact_tolerance = prm.get_double("Contact tolerance");
    gap_expression    = prm.get("Initial gap");
    c                 = prm.get_double("Damping");
    const double zeta = prm.get_double("Damping ratio");
    g_p               = prm.get_double("Shear modulus");
    prm.leave_subsection();
    // A broken expression is refused now, before any mesh is built.
    parse_expression<2>(gap_entry, gap_expression, 1, "x,y", false);
    AssertThrow(model_type == Model::none || gamma > 0,
                ExcMessage("Foundation/Stiffness (Gamma) must be > 0, or set "
                           "Foundation/Model = none."));
    AssertThrow(zeta == 0 || c == 0,
                ExcMessage("Foundation/Damping ratio = " + format_number(zeta)
                           + " and Foundation/Damping (or Units/Dashpot "
                             "coefficient) are both set: give the dashpots "
                             "one way."));
    // Critical: a rigid body of that mass per area on springs Gamma.
    mass = mass_per_area;
    if (zeta > 0)
      c = zeta * 2 * std::sqrt(gamma * mass);
  }


  void
  ContactLaw::setup(const FoundationPoints &foundation_points)
  {
    points = &foundation_points;
    g.clear();
    is_gapped        = false;
    is_precompressed = false;
    if (model_type == Model::none)
      return;
    const std::string &name = gap_entry;
    const auto         g_of_x =
      parse_expression<2>(name, gap_expression, 1, "x,y", false);
    // A half or quarter model is right only if the bed is symmetric too:
    // compare g at each point with its images in the symmetry planes.
    const Discretization           &disc = points->discretization();
    const std::vector<unsigned int> axes = disc.geometry().symmetry_axes();
    std::vector<double>             values(points->n_points());
    bool is_finite = true, is_symmetric = true, is_zero = true;
    bool is_pressed = false;
    for (unsigned int i = 0; i < values.size(); ++i)
      {
        values[i] = g_of_x->value(points->point(i));
        // Beyond 1e100 the bed's force Gamma g and its energy overflow
        // before anything else does.
        is_finite  = is_finite && std::abs(values[i]) <= 1e100;
        is_zero    = is_zero && values[i] == 0.0;
        is_pressed = is_pressed || values[i] < 0.0;
        for (const unsigned int axis : axes)
          {
            Point<2> image = points->point(i);
            image[axis]    = -image[axis];
            is_symmetric   = is_symmetric
                           && std::abs(g_of_x->value(image) - values[i])
                                <= 1e-12 * (1.0 + std::abs(values[i]));
          }
      }
    const MPI_Comm comm = disc.mpi_communicator;
    AssertThrow(Utilities::MPI::min(int(is_finite), comm) == 1,
                ExcMessage(name + " = <" + abbreviated(gap_expression)
                           + "> is not a finite number of at most 1e100 in "
                             "magnitude at some Gauss point of the plate; it "
                             "must be one everywhere."));
    AssertThrow(Utilities::MPI::min(int(is_symmetric), comm) == 1,
                ExcMessage(name + " = <" + abbreviated(gap_expression)
                           + "> is not symmetric about the symmetry planes "
                             "of Discretization/Symmetry; model the full "
                             "plate or give a symmetric gap."));
    // Decided on all ranks alike: a rank without cells takes part in the
    // collective calls of the gap too.
    is_gapped        = (Utilities::MPI::min(int(is_zero), comm) == 0);
    is_precompressed = (Utilities::MPI::max(int(is_pressed), comm) == 1);
    if (is_gapped)
      {
        g = std::move(values);
        gap_function =
          parse_expression<2>(name, gap_expression, 1, "x,y", false);
      }
  }


  ContactLaw::Model
  ContactLaw::model() const
  {
    return model_type;
  }


  double
  ContactLaw::stiffness() const
  {
    return gamma;
  }


  double
  ContactLaw::damping() const
  {
    return has_damping() ? c : 0.0;
  }


  double
  ContactLaw::layer_modulus() const
  {
    return has_layer() ? g_p : 0.0;
  }


  bool
  ContactLaw::has_gap() const
  {
    // Dashpots make the pressure affine with a moving gap.
    return is_gapped || has_damping();
  }


  bool
  ContactLaw::has_initial_gap() const
  {
    return is_gapped;
  }


  bool
  ContactLaw::is_pressing_plate() const
  {
    return is_precompressed;
  }


  double
  ContactLaw::gap_at(const Point<2> &p) const
  {
    return is_gapped ? gap_function->value(p) : 0.0;
  }


  double
  ContactLaw::gap(const unsigned int i) const
  {
    return is_gapped ? g[i] : 0.0;
  }


  bool
  ContactLaw::has_damping() const
  {
    return model_type != Model::none && c > 0;
  }


  bool
  ContactLaw::has_layer() const
  {
    return model_type != Model::none && g_p > 0;
  }


  double
  ContactLaw::rigid_body_frequency() const
  {
    return model_type == Model::none ? 0.0 : std::sqrt(gamma / mass);
  }


  double
  ContactLaw::matrix_stiffness(const double velocity_factor) const
  {
    return has_damping() ? gamma + c * velocity_factor : gamma;
  }


  SpringPressure
  ContactLaw::pressure() const
  {
    SpringPressure p;
    p.stiffness = gamma;
    if (has_gap())
      p.gap = (is_gapped ? g : std::vector<double>(points->n_points(), 0.0));
    return p;
  }


  SpringPressure
  ContactLaw::pressure(const double           velocity_factor,
                       const LA::MPI::Vector &ghosted_offset) const
  {
    Assert(has_damping(), ExcInternalError());
    // Gamma (w - g) + c (kappa w - o) = (Gamma + c kappa) (w - e).
    SpringPressure p;
    p.stiffness = gamma + c * velocity_factor;
    p.gap.resize(points->n_points());
    const unsigned int  n_q = points->n_q_points();
    std::vector<double> o;
    for (unsigned int cell = 0; cell < points->n_cells(); ++cell)
      {
        points->values_at_points(ghosted_offset, cell, o);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int i = cell * n_q + q;
            p.gap[i] =
              ((is_gapped ? gamma * g[i] : 0.0) + c * o[q]) / p.stiffness;
          }
      }
    return p;
  }


  double
  ContactLaw::band(const double largest) const
  {
    return contact_tolerance * largest;
  }


  unsigned char
  ContactLaw::next_status(const unsigned char status,
                          const double        compression,
                          const double        delta) const
  {
    // Hysteresis: within the round-off band a point keeps its status. A
    // one-sided threshold would let a point in a stiff foundation's tail
    // cycle: held below it by its spring, pushed above it without.
    return status ? compression > -delta : compression > delta;
  }


  double
  ContactLaw::pressure_at(const unsigned int i,
                          const double       w,
                          const double       v) const
  {
    return gamma * (w - gap(i)) + (has_damping() ? c * v : 0.0);
  }


  double
  ContactLaw::spring_pressure(const double compression) const
  {
    return model_type == Model::none ? 0.0
                                     : gamma
                                         * (model_type == Model::bilateral
                                              ? compression
                                              : std::max(compression, 0.0));
  }


  double
  ContactLaw::spring_energy(const double compression) const
  {
    const double active =
      (model_type == Model::bilateral ? compression
                                      : std::max(compression, 0.0));
    return 0.5 * gamma * active * active;
  }


  ContactRule::ContactRule(const ContactLaw &contact_law)
      : law(contact_law)
  {}


  void
  ContactRule::use_pressure(SpringPressure pressure)
  {
    current = std::move(pressure);
  }


  const SpringPressure &
  ContactRule::pressure() const
  {
    return current;
  }


  bool
  ContactRule::switches() const
  {
    return law.model() == ContactLaw::Model::tensionless;
  }


  double
  ContactRule::band(const double largest) const
  {
    return law.band(largest);
  }


  unsigned char
  ContactRule::next_status(const unsigned char status,
                           const double        compression,
                           const double        band) const
  {
    return law.next_status(status, compression, band);
  }


  bool
  ContactRule::may_keep(const unsigned char,
                        const double compression,
                        const double band) const
  {
    return std::abs(compression) <= band;
  }


  double
  ContactRule::stiffness(const double velocity_factor) const
  {
    return law.matrix_stiffness(velocity_factor);
  }


  bool
  ContactRule::has_offset() const
  {
    return law.has_gap();
  }


  double
  ContactRule::offset_stiffness() const
  {
    return current.stiffness;
  }


  double
  ContactRule::offset(const unsigned int i, const unsigned char) const
  {
    Assert(i < current.gap.size(), ExcInternalError());
    return current.gap[i];
  }
} // namespace liftoff
