#pragma once

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * What a value is, for its unit: the one vocabulary of quantities. An
   * output asks PhysicalUnits for the scale and unit of the quantity of each
   * value it writes; an entry declares the quantity of its value at the end
   * of its documentation (quantity()), by which a scene in SI units is
   * converted. Each has one name (name_of(): the spelling of quantity() and
   * of the messages) and the units of doc/model.md (si_symbol(),
   * dimensionless_scales()).
   */
  enum class Quantity
  {
    number,                 ///< dimensionless in both systems (nu, fractions)
    text,                   ///< names, not converted
    length,                 ///< L
    position,               ///< a length that is a point on the plate
    deflection,             ///< w, gaps: F0 L^2 / D
    rotation,               ///< psi, F0 L / D (radians)
    time,                   ///< t0
    force,                  ///< F0
    pressure,               ///< F0 / L^2
    force_per_length,       ///< a line load, a shear force per length: F0 / L
    pressure_per_length,    ///< F0 / L^3
    velocity,               ///< of w, F0 L^2 / (D t0)
    angular_velocity,       ///< of psi, F0 L / (D t0)
    area,                   ///< L^2
    energy,                 ///< F0^2 L^2 / D
    moment,                 ///< a moment per unit length, F0
    angle_degrees,          ///< degrees in both systems
    temperature_difference, ///< K in both systems
    thermal_expansion,      ///< per K, in units of F0 L / D
    frequency,              ///< an angular frequency, 1 / t0
    // The dimensionless groups an SI scene gives by the entries of Units
    // (is_group()).
    mu,
    Delta,
    Gamma,
    damping,
    shear_layer,
    self_weight
  };

  /// The name of `quantity`: "force per length", "self weight", ...
  const std::string &
  name_of(const Quantity quantity);

  /// The quantity named `name` (name_of()); a name that is none is refused.
  Quantity
  quantity_named(const std::string &name);

  /// The SI unit of one unit of the solver's `quantity`: "m", "Pa", ...;
  /// "1" for a number or a group.
  const std::string &
  si_symbol(const Quantity quantity);

  /// The dimensionless scales one unit of `quantity` is made of, as
  /// doc/model.md writes them ("F0*L^2/D").
  const std::string &
  dimensionless_scales(const Quantity quantity);

  /// Whether `quantity` is a dimensionless group of doc/model.md that a
  /// scene in SI units gives by the entries of Units (mu, Delta, ...).
  bool
  is_group(const Quantity quantity);

  /**
   * The last words of an entry's documentation that declare the quantity
   * of its value, " [quantity: ...]": the class that declares the entry
   * gives it, as in
   *
   *   prm.declare_entry("Time step", "5e-4", Patterns::Double(0.0),
   *                     "dtau > 0, in units of t0." + quantity("time"));
   *
   * It says how a scene in SI units (Units/System = SI) writes the entry
   * and how PhysicalUnits converts it into the dimensionless scene the
   * solver reads. ParameterHandler keeps nothing per entry beyond its
   * value, pattern and documentation, so the quantity is kept there:
   * `liftoff --parameters` shows it, and the converter and the test
   * `entry_quantities` read it back (declared_quantities()).
   *
   * `names` is one name of a Quantity (name_of()), or several separated by
   * ", " that the items of the value take in turn (the items are the
   * numbers or expressions separated by ',' or ';' outside parentheses):
   * "length, length, number" for "dx, dy, share; ...". A name that is not
   * known is refused, so a misspelt quantity fails every run.
   */
  std::string
  quantity(const std::string &names);

  /// The quantities, in the order the items of the value take them, that
  /// quantity() put at the end of `documentation`; empty if none.
  std::vector<Quantity>
  declared_quantities(const std::string &documentation);

  /// Whether declared_quantities() reads " (if set)" after the quantity: the
  /// entry's default is dimensionless in both systems (a radius of L / 2),
  /// and only a value the scene sets is in SI units.
  bool
  converts_only_if_set(const std::string &documentation);

  /**
   * A number (or a point "(x, y)") in a message, tagged with the
   * dimensionless scales of its `quantity` (dimensionless_scales()):
   * "(0.6, 0.25) [L]", "3.1e-05 [F0^2*L^2/D]". A dimensionless scene reads
   * it so, in the units of doc/model.md; PhysicalUnits::in_scene_terms()
   * writes it in an SI scene's units ("(8.7, 3.6) m", "0.012 J"), so a
   * message of a class that knows no units speaks the scene's.
   */
  std::string
  tagged(const std::string &number, const Quantity quantity);

  /**
   * The words of an entry's documentation, before its quantity(), that give
   * its default in a scene in SI units, " [SI default: 200e9]": a value
   * that only SI fixes (a steel's modulus in Pa, concrete's expansion in
   * 1/K), which a dimensionless scene, whose units are the slab's, must
   * give itself (the declared default stays its default). The class that
   * declares the entry gives it, as in
   *
   *   prm.declare_entry("Steel modulus", "0", Patterns::Double(0.0),
   *                     "E_d." + si_default("200e9") + quantity("pressure"));
   *
   * and PhysicalUnits writes it, converted, into the dimensionless twin of
   * an SI scene that leaves the entry out. `liftoff --parameters` shows it.
   */
  std::string
  si_default(const std::string &value);

  /// The value si_default() put in `documentation`; empty if none.
  std::string
  si_default_of(const std::string &documentation);

  /// An entry as ParameterHandler declares it.
  struct DeclaredEntry
  {
    std::string value, default_value, pattern, documentation;
  };

  /// Every entry of `prm` by its path "Subsection/.../Entry", from
  /// ParameterHandler's own tree in its JSON form: what the converter and
  /// the test of declared quantities walk.
  std::map<std::string, DeclaredEntry>
  declared_entries(const ParameterHandler &prm);
} // namespace liftoff
