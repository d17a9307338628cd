// Foundation/Initial gap g(x, y): the springs act where w > g with the
// pressure Gamma (w - g). Checks, each against something the gap code does
// not compute itself:
//  - a free plate under a uniform pressure q on a linear gap
//    g = g0 + g1 x + g2 y sits at w = q/Gamma + g exactly (hand solution:
//    a linear w bends nothing, so the springs alone carry q, uniformly),
//    static and tensionless, for any plate stiffness;
//  - a free plate lifting off under an eccentric force: a linear gap is a
//    rigid-body motion of the bed, so the solution on it is the solution
//    without a gap plus g, with the same contact set (compared with a run
//    without the gap, tensionless, static);
//  - a bilateral bed with a gap is an affine system: Newmark's average
//    acceleration rule conserves its energy 1/2 Gamma int (w - g)^2 + ...
//    exactly, so the balance error is round-off (it is not if the gap's
//    force is left out of the initial acceleration or of a step);
//  - static equilibrium with lift-off on a curved gap: Clapeyron's identity
//    E = 1/2 (F.u + Gamma int_S g (g - w)), which only an equilibrium of
//    the affine reaction satisfies;
//  - g = 0 written as an expression takes the path of no gap: bit-identical
//    histories.

#include "energy_checks.h"
#include "test_tools.h"

#include <cmath>

namespace
{
  using dealii::Point;
  using dealii::Utilities::split_string_list;
  using dealii::Utilities::string_to_double;
  using liftoff_tests::set;

  const std::string probes = "0, 0; 0.5, 0.5; -0.5, 0.5; -0.5, -0.5; "
                             "0.2, -0.3; 0.5, 0";

  std::string
  free_plate(const std::string &model, const std::string &gap)
  {
    return set("Analysis/Type", "static") + set("Foundation/Model", model)
           + set("Foundation/Stiffness", 10)
           + set("Foundation/Initial gap", gap)
           + set("Discretization/Cells along x", 6)
           + set("Discretization/Cells along y", 6)
           + set("Discretization/Polynomial degree", 2)
           + set("Output/Probe points", probes);
  }

  double
  linear_gap(const Point<2> &p)
  {
    return 0.01 - 0.03 * p[0] + 0.02 * p[1];
  }
  const std::string linear_gap_text = "0.01 - 0.03*x + 0.02*y";

  std::vector<Point<2>>
  probe_points()
  {
    std::vector<Point<2>> points;
    for (const auto &entry : split_string_list(probes, ';'))
      {
        const auto xy = string_to_double(split_string_list(entry, ','));
        points.emplace_back(xy[0], xy[1]);
      }
    return points;
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks       checks(argc, argv);
  const std::vector<Point<2>> points = probe_points();

  // Uniform pressure on a linear gap: w = q/Gamma + g.
  {
    const double q = 0.2;
    const auto   run =
      liftoff_tests::run_scene(free_plate("tensionless", linear_gap_text)
                               + set("Loads/Pressure 1/Magnitude", q));
    const auto &row   = run->history().back();
    double      error = 0;
    for (unsigned int k = 0; k < points.size(); ++k)
      error = std::max(error,
                       std::abs(row.probes("w")[k]
                                - (q / 10 + linear_gap(points[k]))));
    checks.less("uniform q on a linear gap: max |w - (q/Gamma + g)| / "
                "(q/Gamma)",
                error / (q / 10),
                1e-9);
    checks.within("uniform q on a linear gap: contact fraction",
                  row["contact_fraction"],
                  1,
                  1);
  }

  // Eccentric force, lift-off: on a linear gap the solution is shifted by g.
  {
    const std::string force = set("Loads/Point load 1/Magnitude", 1)
                              + set("Loads/Point load 1/Position", "0.4, 0.3");
    const auto flat =
      liftoff_tests::run_scene(free_plate("tensionless", "0") + force);
    const auto gapped = liftoff_tests::run_scene(
      free_plate("tensionless", linear_gap_text) + force);
    const auto &a = flat->history().back(), &b = gapped->history().back();
    double      error = 0, scale = 0;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        error = std::max(error,
                         std::abs(b.probes("w")[k] - a.probes("w")[k]
                                  - linear_gap(points[k])));
        scale = std::max(scale, std::abs(a.probes("w")[k]));
      }
    checks.less("eccentric force: the plate lifts off (contact fraction)",
                a["contact_fraction"],
                0.95);
    checks.less("eccentric force on a linear gap: max |w_gap - w_flat - g| / "
                "max |w_flat|",
                error / scale,
                1e-8);
    checks.less("eccentric force on a linear gap: |contact fraction - flat "
                "one|",
                std::abs(a["contact_fraction"] - b["contact_fraction"]),
                1e-12);
  }

  // Bilateral, dynamic: an affine system, whose energy the average
  // acceleration rule conserves.
  {
    const auto run = liftoff_tests::run_scene(
      liftoff_tests::small_plate_scene() + set("Foundation/Model", "bilateral")
      + set("Foundation/Stiffness", 200)
      + set("Foundation/Initial gap", "-0.002*(1 + x*x + 2*y*y)")
      + set("Time integration/Time step", 2e-3)
      + set("Time integration/End time", 0.2));
    checks.less("bilateral with a pre-compression, dynamic: max |energy "
                "balance error| / max work",
                liftoff_tests::relative_balance_error(*run),
                1e-10);
  }

  // Static, lift-off on a curved gap: Clapeyron's identity with the gap.
  {
    const auto run = liftoff_tests::run_scene(
      free_plate("tensionless", "0.005*(x*x - y*y) - 0.002")
      + set("Loads/Point load 1/Magnitude", 1)
      + set("Loads/Point load 1/Position", "0.2, 0.1"));
    const auto &row = run->history().back();
    checks.less("static on a curved gap: the plate lifts off (contact "
                "fraction)",
                row["contact_fraction"],
                0.95);
    checks.less("static on a curved gap: |strain + foundation energy - "
                "(F.u + Gamma int_S g (g - w))/2| / that",
                liftoff_tests::clapeyron_error(row),
                1e-10);
  }

  // g = 0 as an expression: the same numbers as no gap at all.
  {
    const std::string scene = liftoff_tests::small_plate_scene()
                              + set("Foundation/Stiffness", 200)
                              + set("Output/Probe points", probes);
    const auto plain  = liftoff_tests::run_scene(scene);
    const auto zeroed = liftoff_tests::run_scene(
      scene + set("Foundation/Initial gap", "0*x + 0*y"));
    double difference = 0;
    for (unsigned int n = 0; n < plain->history().size(); ++n)
      for (unsigned int k = 0; k < points.size(); ++k)
        difference = std::max(difference,
                              std::abs(plain->history()[n].probes("w")[k]
                                       - zeroed->history()[n].probes("w")[k]));
    checks.less("g = 0*x + 0*y against no gap: max |difference of w|",
                difference,
                1e-300);
  }
  return checks.exit_code();
}
