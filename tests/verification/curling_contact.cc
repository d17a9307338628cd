// A slab under its weight q on a tensionless bed, curled by a temperature
// difference at night (dT < 0: the corners lift): as long as the bilateral
// answer presses every point of the bed, the tensionless one is the same
// (to round-off); beyond that the corners lift and the contact fraction
// falls as |dT| grows. The bed carries the weight in every case (the
// temperature load has no resultant). The threshold is found from the
// bilateral answers alone: w = q / Gamma + dT w_1, linear in dT, so the
// corner opens at dT_c = -(q / Gamma) / w_1(corner).

#include "test_tools.h"

#include <cmath>

namespace
{
  using liftoff_tests::set;
  constexpr double gamma_f = 100, q = 1;

  std::string
  scene(const std::string &model, const double weight, const double dt)
  {
    return set("Analysis/Type", "static") + set("Foundation/Model", model)
           + set("Foundation/Stiffness", gamma_f)
           + set("Plate/Poisson ratio", 0.15)
           + set("Discretization/Symmetry", "quarter")
           + set("Discretization/Cells along x", 8)
           + set("Discretization/Cells along y", 8)
           + set("Discretization/Polynomial degree", 2)
           + set("Loads/Self weight", weight)
           + set("Loads/Temperature load 1/Magnitude", dt)
           + set("Loads/Temperature load 1/Expansion coefficient", 1e-3)
           + set("Output/Write foundation resultant", "true")
           + set("Output/Probe points", "0.5, 0.5; 0, 0; 0.5, 0; 0.2, 0.3");
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  const auto   unit = liftoff_tests::run_scene(scene("bilateral", 0, 1));
  const double w_1  = unit->history().back().probes("w")[0];
  const double dt_c = -(q / gamma_f) / w_1;
  std::cout << "bilateral, dT = 1 without weight: w(corner) = " << w_1
            << "; the corner opens at dT_c = " << dt_c << std::endl;
  checks.less("night curls the corner up: dT_c < 0", dt_c, 0);

  double previous_fraction = 1;
  for (const double factor : {0.9, 2.0, 4.0})
    {
      const double dt = factor * dt_c;
      const auto   tensionless =
        liftoff_tests::run_scene(scene("tensionless", q, dt));
      const auto       &row = tensionless->history().back();
      const std::string at  = "dT = " + std::to_string(factor) + " dT_c: ";
      checks.less(at + "|bed resultant - weight| / weight",
                  std::abs(row["resultant"] - q) / q,
                  1e-9);
      const double fraction = row["contact_fraction"];
      std::cout << at << "contact fraction " << fraction << ", w(corner) "
                << row.probes("w")[0] << std::endl;
      if (factor < 1)
        {
          const auto bilateral =
            liftoff_tests::run_scene(scene("bilateral", q, dt));
          checks.less(at + "tensionless vs bilateral, max |dw| / max |w|",
                      liftoff_tests::history_difference(*bilateral,
                                                        *tensionless),
                      1e-12);
          checks.within(at + "contact fraction", fraction, 1, 1);
        }
      else
        checks.less(at + "contact fraction below the previous one",
                    fraction,
                    previous_fraction - 1e-3);
      previous_fraction = fraction;
    }
  // Permanent (built-in curl): a time integration starts from the static
  // equilibrium under the weight and the temperature together.
  {
    const double dt = 2 * dt_c;
    const auto   static_run =
      liftoff_tests::run_scene(scene("tensionless", q, dt));
    const auto dynamic_run = liftoff_tests::run_scene(
      scene("tensionless", q, dt) + set("Analysis/Type", "dynamic")
      + set("Loads/Temperature load 1/Permanent", "true")
      + set("Time integration/Time step", 1e-3)
      + set("Time integration/End time", 2e-3));
    double difference = 0, scale = 0;
    for (const auto &row : dynamic_run->history())
      for (unsigned int k = 0; k < 4; ++k)
        {
          const double w = static_run->history().back().probes("w")[k];
          difference = std::max(difference, std::abs(row.probes("w")[k] - w));
          scale      = std::max(scale, std::abs(w));
        }
    checks.less("permanent at 2 dT_c: the dynamic run rests at the static "
                "equilibrium, max |w - w_static| / max |w_static| over its "
                "steps",
                difference / scale,
                1e-9);
  }
  return checks.exit_code();
}
