// The quasi-static limit of a moving load (issue 33): a point load that
// crosses a plate on a stiff bed very slowly (speed 0.05 against the bed's
// critical speed (4 Gamma)^(1/4) = 14) gives, at sample positions, the
// static solution (Analysis/Type = static) of the same load standing
// there, on a bilateral and on a tensionless bed. The dynamic run stands
// still until tau = 1 while dashpots (c = 40, a fifth of critical for
// the bed's mode) damp the start's transient, then moves; the difference
// left is the dashpots' force c v dw/dx and the inertia (v / v_cr)^2,
// both below 1e-3 of w here. Same mesh, so the comparison is free of the
// discretisation error.

#include "test_tools.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using liftoff_tests::set;

  constexpr double speed = 0.05, start = -0.35, y_load = 0.05;

  std::string
  base(const std::string &model)
  {
    return set("Plate/Aspect ratio", 0.5) + set("Foundation/Model", model)
           + set("Foundation/Stiffness", 1e4)
           + set("Discretization/Cells along x", 10)
           + set("Discretization/Cells along y", 4)
           + set("Discretization/Polynomial degree", 2)
           + set("Loads/Point load 1/Magnitude", 1)
           + set("Loads/Self weight", 0.2)
           + set("Output/Probe points",
                 "-0.2, 0.05; 0, 0.05; 0.15, 0.05; 0.3, 0.05; 0.1, -0.2; "
                 "-0.45, 0.2");
  }

  void
  check(liftoff_tests::Checks &checks, const std::string &model)
  {
    std::ostringstream path;
    path << start << " + " << speed << "*max(tau - 1, 0); " << y_load;
    const double end_time = 1 + 2 * std::abs(start) / speed;
    const auto   moving   = liftoff_tests::run_scene(
      base(model) + set("Loads/Point load 1/Path", path.str())
      + set("Loads/Point load 1/Time history",
            "if(tau < 1, 0.5*(1 - cos(pi*tau)), 1)")
      + set("Foundation/Damping", 10) + set("Time integration/Time step", 0.01)
      + set("Time integration/End time", end_time));
    for (const double x : {-0.2, 0.0, 0.15, 0.3})
      {
        std::ostringstream position;
        position << x << ", " << y_load;
        const auto standing = liftoff_tests::run_scene(
          base(model) + set("Analysis/Type", "static")
          + set("Loads/Point load 1/Position", position.str()));
        const double tau        = 1 + (x - start) / speed;
        const auto  &rows       = moving->history();
        const auto  &row        = rows[std::lround(tau / 0.01)];
        const auto  &reference  = standing->history().back().probes("w");
        double       difference = 0, scale = 0;
        for (unsigned int k = 0; k < reference.size(); ++k)
          {
            difference =
              std::max(difference, std::abs(row.probes("w")[k] - reference[k]));
            scale = std::max(scale, std::abs(reference[k]));
          }
        std::ostringstream what;
        what << model << ", load at x = " << x << " (tau = " << row["tau"]
             << "): probes against the static solution (relative)";
        checks.less(what.str(), difference / scale, 2e-3);
        if (model == "tensionless")
          checks.less("tensionless, load at x = " + std::to_string(x)
                        + ": the static plate lifts off (contact fraction)",
                      standing->history().back()["contact_fraction"],
                      0.99);
      }
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv, 1);
  check(checks, "bilateral");
  check(checks, "tensionless");
  return checks.exit_code();
}
