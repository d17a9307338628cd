#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/base/point.h>
#include <liftoff/base/physical_units.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/foundation_points.h>
#include <liftoff/contact/status_law.h>

#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The bed's pressure at the Gauss points in contact, k (w - e), for one
   * velocity of the plate v = kappa w - o: the stiffness k = Gamma + c kappa
   * and the effective gap e = (Gamma g + c o) / k (Gamma and g when the
   * plate does not move or there are no dashpots). It is what the contact
   * rule tests and what the gap load integrates, and the argument of those
   * calls: nothing depends on which velocity was set last.
   */
  struct SpringPressure
  {
    double stiffness = 1.0;
    /// e at the points; empty: e = 0 everywhere (no gap, no dashpots).
    std::vector<double> gap;
  };


  /**
   * The contact law of the bed: Winkler springs Gamma that push but never
   * pull (or of both signs, `bilateral`), on an initial gap g(x, y), with
   * dashpots c and a Pasternak shear layer G_p beside them. Springs, gap
   * and dashpots are one rule: the pressure k (w - e) of a SpringPressure,
   * acting where w > e (with the round-off band of next_status()). The
   * layer acts over the same points as the springs.
   */
  class ContactLaw
  {
  public:
    enum class Model
    {
      tensionless,
      bilateral,
      none
    };

    static void
    declare_parameters(ParameterHandler &prm);
    /// `mass_per_area`: what the bed carries, in units of the plate's rho
    /// H (1 without a base): it sets the critical damping of Damping
    /// ratio and the rigid body's frequency. `gap_entry`: the entry that
    /// gives the text of Foundation/Initial gap, as its errors name it (the
    /// interface's springs take theirs from Base/Interface gap).
    void
    parse_parameters(ParameterHandler  &prm,
                     const double       mass_per_area = 1.0,
                     const std::string &gap_entry = "Foundation/Initial gap");
    /// A bed in the scene as written requires Units/Subgrade modulus.
    static void
    describe_for_units(ParameterHandler            &scene,
                       PhysicalUnits::SceneOutline &outline);

    /// Evaluate g at `points` (kept), refusing a g that is not finite or,
    /// on a half or quarter model, not symmetric. Collective.
    void
    setup(const FoundationPoints &points);

    Model
    model() const;
    /// Gamma, c and G_p (0 where the model has none).
    double
    stiffness() const;
    double
    damping() const;
    double
    layer_modulus() const;

    /// Whether the pressure is affine, k (w - e) with e != 0 somewhere:
    /// an initial gap or dashpots.
    bool
    has_gap() const;
    /// Whether some Gauss point has g != 0 (an initial gap, not dashpots).
    bool
    has_initial_gap() const;
    /// Whether the bed pushes an unloaded plate (g < 0 at some Gauss point:
    /// a pre-compression), so that a scene without loads still moves.
    bool
    is_pressing_plate() const;
    /// g at a point of the meshed part (0 without a gap), for output.
    double
    gap_at(const Point<2> &p) const;
    /// g at Gauss point i (0 without a gap).
    double
    gap(const unsigned int i) const;
    bool
    has_damping() const;
    bool
    has_layer() const;
    /// sqrt(Gamma / m): the angular frequency of the mass per area on the
    /// bed (parse_parameters()) moving as a rigid body on the springs.
    double
    rigid_body_frequency() const;

    /// Gamma + c kappa: the stiffness of a system matrix whose unknown's
    /// velocity is kappa w + ... (kappa = 0 at a given state).
    double
    matrix_stiffness(const double velocity_factor) const;
    /// The pressure of a plate at rest: Gamma (w - g).
    SpringPressure
    pressure() const;
    /// The pressure for the velocity v = kappa w - o at the points, o the
    /// w of `ghosted_offset` (with dashpots).
    SpringPressure
    pressure(const double           velocity_factor,
             const LA::MPI::Vector &ghosted_offset) const;

    /// The contact rule at a point with the status `status` and w - e =
    /// `compression`, `largest` the largest |w - e| of the plate: in
    /// contact where w - e > delta, out where w - e < -delta, the status
    /// kept in between (delta = band(largest)).
    unsigned char
    next_status(const unsigned char status,
                const double        compression,
                const double        delta) const;
    /// delta: Contact tolerance * largest.
    double
    band(const double largest) const;

    /// Gamma (w - g) + c v at Gauss point i (v read only with dashpots).
    double
    pressure_at(const unsigned int i, const double w, const double v) const;
    /// The springs' pressure and energy per unit area at w - g: 0 without
    /// a foundation, of either sign when bilateral, never tensile else.
    double
    spring_pressure(const double compression) const;
    double
    spring_energy(const double compression) const;

  private:
    Model  model_type        = Model::tensionless;
    double gamma             = 1.0;
    double contact_tolerance = 1e-9;
    /// g(x, y) in full plate coordinates.
    std::string gap_expression = "0";
    /// The entry the gap's errors name.
    std::string gap_entry = "Foundation/Initial gap";
    double      c         = 0;
    double      g_p       = 0;
    /// The mass per area the bed carries (parse_parameters()).
    double mass = 1;

    const FoundationPoints *points = nullptr;
    /// g at the points, if is_gapped: some point on some rank has g != 0.
    std::vector<double> g;
    bool                is_gapped        = false;
    bool                is_precompressed = false;
    /// g(x, y), kept for evaluation off the Gauss points (if is_gapped).
    std::unique_ptr<FunctionParser<2>> gap_function;
  };

  /**
   * The bed's contact rule as the status law of its Gauss points: in
   * contact where w - e > 0 (ContactLaw::next_status()), for the pressure
   * k (w - e) of the plate's velocity that the solve or the state at hand
   * sets (use_pressure()), whose e is the springs' offset.
   */
  class ContactRule : public StatusLaw
  {
  public:
    explicit ContactRule(const ContactLaw &law);

    void
    use_pressure(SpringPressure pressure);
    const SpringPressure &
    pressure() const;

    bool
    switches() const override;
    double
    band(const double largest) const override;
    unsigned char
    next_status(const unsigned char status,
                const double        compression,
                const double        band) const override;
    bool
    may_keep(const unsigned char earlier,
             const double        compression,
             const double        band) const override;
    double
    stiffness(const double velocity_factor) const override;
    bool
    has_offset() const override;
    double
    offset_stiffness() const override;
    double
    offset(const unsigned int i, const unsigned char status) const override;

  private:
    const ContactLaw &law;
    SpringPressure    current;
  };
} // namespace liftoff
