// Every entry liftoff declares that could hold a dimension declares its
// quantity where it is declared (base/entry_quantity.h), and a scene in SI
// units gives the solver each such entry divided by the unit of that
// quantity (issue 46, finding 1: Line load N/Segment was read in metres as
// units of L, a line load Units/Length times too strong).
//
// - An entry whose pattern is a Double, a List, a Map or Anything (counts,
//   switches and choices cannot carry a unit) outside Units has a quantity:
//   walked over every entry of Simulator::declare_parameters(), the
//   numbered loads (Point load 1..8, Line load 1..8, ...) each.
// - An SI scene with every entry of a unit set to a value (its default,
//   each zero made 0.25) is converted; each number in the twin is the
//   scene's divided by the unit computed here from doc/model.md's scales
//   (L, t0 = L^2 sqrt(rho H / D), F0 = D / L, w in L, psi in rad), to
//   round-off.
// - A message's numbers tagged with their solver's unit (a point, an
//   energy, a frequency: the messages of PointFunctional, the energy check
//   and the stability limit) read in m, J and rad/s against these scales.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/run/simulator.h>


#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>

#include "test_tools.h"

using namespace dealii;

namespace
{

  void
  set(ParameterHandler &prm, const std::string &path, const std::string &value)
  {
    const auto names = Utilities::split_string_list(path, '/');
    for (unsigned int k = 0; k + 1 < names.size(); ++k)
      prm.enter_subsection(names[k]);
    prm.set(names.back(), value);
    for (unsigned int k = 0; k + 1 < names.size(); ++k)
      prm.leave_subsection();
  }

  std::vector<std::string>
  items(const std::string &text)
  {
    std::vector<std::string> result;
    for (const auto &part : Utilities::split_string_list(text, ';'))
      for (const auto &item : Utilities::split_string_list(part, ','))
        result.push_back(item);
    return result;
  }

  bool
  is_number(const std::string &text)
  {
    return Patterns::Double().match(text);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  ParameterHandler prm;
  liftoff::Simulator::declare_parameters(prm);
  liftoff::PhysicalUnits units;
  units.watch(prm);
  const auto entries = liftoff::declared_entries(prm);

  unsigned int missing = 0, tagged = 0;
  for (const auto &[path, entry] : entries)
    {
      if (path.rfind("Units/", 0) == 0)
        continue;
      bool could_hold_a_unit = false;
      for (const std::string kind : {"[Double", "[List", "[Map", "[Anything"})
        could_hold_a_unit |= entry.pattern.rfind(kind, 0) == 0;
      if (!liftoff::declared_quantities(entry.documentation).empty())
        ++tagged;
      else if (could_hold_a_unit)
        {
          std::cout << "no quantity declared: " << path << ' ' << entry.pattern
                    << std::endl;
          ++missing;
        }
    }
  std::cout << entries.size() << " entries, " << tagged
            << " with a declared quantity" << std::endl;
  checks.less("entries that could hold a dimension and declare no quantity",
              missing,
              0.5);

  // The SI plate and doc/model.md's units of each quantity.
  const double L = 5, H = 0.25, E = 30e9, nu = 0.2, rho = 2400;
  const double D  = E * H * H * H / (12 * (1 - nu * nu));
  const double F0 = D / L, t0 = L * L * std::sqrt(rho * H / D);
  using Q                                        = liftoff::Quantity;
  const std::map<liftoff::Quantity, double> unit = {
    {Q::number, 1},
    {Q::length, L},
    {Q::position, L},
    {Q::deflection, L},
    {Q::rotation, 1},
    {Q::time, t0},
    {Q::force, F0},
    {Q::pressure, F0 / (L * L)},
    {Q::force_per_length, F0 / L},
    {Q::velocity, L / t0},
    {Q::angular_velocity, 1 / t0}};
  for (const auto &[path, value] :
       std::map<std::string, std::string>{{"Units/System", "SI"},
                                          {"Units/Length", "5"},
                                          {"Units/Thickness", "0.25"},
                                          {"Units/Young's modulus", "30e9"},
                                          {"Units/Density", "2400"},
                                          {"Units/Subgrade modulus", "5e7"},
                                          {"Plate/Poisson ratio", "0.2"}})
    set(prm, path, value);

  // Every entry of a unit, each zero of its default made 0.25 (on the
  // plate, and not a value every unit leaves alone).
  std::map<std::string, std::pair<std::vector<liftoff::Quantity>, std::string>>
    probes;
  for (const auto &[path, entry] : entries)
    {
      const auto quantities = liftoff::declared_quantities(entry.documentation);
      bool       has_unit = false, is_known = true;
      for (const auto &q : quantities)
        {
          is_known &= unit.count(q) == 1;
          has_unit |= q != Q::number;
        }
      has_unit &= is_known;
      if (!has_unit || path.rfind("Units/", 0) == 0)
        continue;
      std::string value = entry.value.empty() ? "0, 0, 0, 0" : entry.value;
      // An empty list of points x, y takes one point.
      if (entry.value.empty()
          && entry.pattern.find("length 2...2") != std::string::npos)
        value = "0, 0";
      std::string probe;
      for (const auto &part : Utilities::split_string_list(value, ';'))
        {
          std::string group;
          for (const auto &item : Utilities::split_string_list(part, ','))
            group +=
              (group.empty() ? "" : ", ")
              + (is_number(item) && Utilities::string_to_double(item) == 0
                   ? std::string("0.25")
                   : item);
          probe += (probe.empty() ? "" : "; ") + group;
        }
      set(prm, path, probe);
      probes[path] = {quantities, probe};
    }

  units.parse_parameters(prm, liftoff::SceneParts::outline_for_units(prm));
  const auto twin = liftoff::declared_entries(
    units.solver_scene(prm, liftoff::Simulator::declare_parameters));

  double       worst     = 0;
  unsigned int converted = 0, numbers = 0;
  for (const auto &[path, probe] : probes)
    {
      const auto &[quantities, value] = probe;
      const auto si = items(value), dimensionless = items(twin.at(path).value);
      bool       ok = si.size() == dimensionless.size();
      for (unsigned int i = 0; ok && i < si.size(); ++i)
        if (is_number(si[i]))
          {
            const double expected =
              Utilities::string_to_double(si[i])
              / unit.at(quantities[i % quantities.size()]);
            ok = is_number(dimensionless[i]);
            const double error =
              ok ? std::abs(Utilities::string_to_double(dimensionless[i])
                            - expected)
                     / std::abs(expected)
                 : 1;
            worst = std::max(worst, error);
            ok    = error < 1e-14;
            ++numbers;
          }
      if (!ok)
        std::cout << "not converted by its quantity: " << path << " = " << value
                  << " gives " << twin.at(path).value << std::endl;
      converted += ok;
    }
  std::cout << probes.size() << " entries of a unit, " << numbers
            << " numbers, largest relative error " << worst << std::endl;
  checks.less("entries of a unit an SI scene gives unconverted",
              probes.size() - converted,
              0.5);
  // A number a message tags with its solver's unit (tagged(): a class that
  // knows no units) in the SI scene's: a point in L, an energy in
  // F0^2 L^2 / D = F0 L here (F0 = D / L), a frequency in 1 / t0.
  const std::string message = units.in_scene_terms(
    "The point " + liftoff::tagged("(0.25, -0.125)", Q::position)
    + " lies outside; error " + liftoff::tagged("2e-06", Q::energy)
    + "; omega = " + liftoff::tagged("100", Q::frequency) + ".");
  std::cout << message << std::endl;
  std::smatch found;
  const bool  is_read = std::regex_match(
    message,
    found,
    std::regex(R"(The point \((\S+), (\S+)\) m lies outside; error (\S+) J; )"
                R"(omega = (\S+) rad/s\.)"));
  double tag_error = 1;
  if (is_read)
    {
      tag_error                          = 0;
      const std::vector<double> expected = {1.25,
                                            -0.625,
                                            2e-6 * F0 * L,
                                            100 / t0};
      for (unsigned int i = 0; i < expected.size(); ++i)
        tag_error =
          std::max(tag_error,
                   std::abs(std::stod(found[i + 1].str()) - expected[i])
                     / std::abs(expected[i]));
    }
  checks.less("tagged numbers of a message in the SI scene's units (m, J, "
              "rad/s), relative error",
              tag_error,
              1e-7);

  // Eight of each numbered load kind, whose entries of a unit are about
  // five each: a walk that missed the families would see a dozen.
  checks.within("entries of a unit in the scene (every numbered load)",
                probes.size(),
                100,
                1000);
  return checks.exit_code();
}
