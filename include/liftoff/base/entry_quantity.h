#pragma once

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

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
   * `names` is one name of quantity_names(), or several separated by ", "
   * that the items of the value take in turn (the items are the numbers or
   * expressions separated by ',' or ';' outside parentheses): "length,
   * length, number" for "dx, dy, share; ...". A name that is not known is
   * refused, so a misspelt quantity fails every run.
   */
  std::string
  quantity(const std::string &names);

  /// The quantities, in the order the items of the value take them, that
  /// quantity() put at the end of `documentation`; empty if none.
  std::vector<std::string>
  declared_quantities(const std::string &documentation);

  /// Whether declared_quantities() reads " (if set)" after the quantity: the
  /// entry's default is dimensionless in both systems (a radius of L / 2),
  /// and only a value the scene sets is in SI units.
  bool
  converts_only_if_set(const std::string &documentation);

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

  /**
   * The names quantity() knows: "number" (the same in both systems;
   * expressions in x, y, t are rewritten), "text" (not converted), the
   * units of PhysicalUnits ("length", "deflection", "rotation", "time",
   * "force", "pressure", "force per length", "velocity", "angular
   * velocity"), "position" (a length that is a point on the plate, checked
   * there) and the dimensionless groups an SI scene gives by the entries of
   * Units ("mu", "Delta", "Gamma", "damping", "shear layer", "self
   * weight").
   */
  const std::vector<std::string> &
  quantity_names();
} // namespace liftoff
