// Loads/Self weight q: a uniform pressure that acts from before tau = 0; a
// time integration starts from the static equilibrium under it. Checks:
//  - a free plate under its weight alone rests in uniform full contact at
//    w = q/Gamma (exact: a uniform w bends nothing) at every step, with no
//    motion: the start is an equilibrium;
//  - a central force below the lift-off threshold: the plate stays in full
//    contact, so the tensionless run equals the bilateral one, and the
//    bilateral one is linear: w = q/Gamma + (the response to the force
//    alone, from rest, without weight), step by step (superposition);
//  - above the threshold lift-off begins where the rigid plate predicts
//    (a very soft bed, Gamma = 0.01, makes the plate rigid): under q and a
//    force P at x = e the edge x = -1/2 unloads when
//    q mu + P = 6 P e (the kern: e > 1/6), i.e. P* = q mu / (6 e - 1). The
//    status lives at Gauss points: the outermost, at |x| = x_g, opens at
//    P_g = q mu / (12 e x_g - 1). At 0.99 P_g the plate is in full contact
//    with the rigid edge deflection (q mu + P - 6 P e) / (Gamma mu); at
//    1.01 P_g it lifts.

#include "test_tools.h"

#include <cmath>

namespace
{
  using liftoff_tests::set;
  constexpr double gamma_f = 10.0, q = 0.3;

  std::string
  dynamic_scene(const std::string &model)
  {
    return set("Foundation/Model", model) + set("Foundation/Stiffness", gamma_f)
           + set("Discretization/Cells along x", 4)
           + set("Discretization/Cells along y", 4)
           + set("Discretization/Polynomial degree", 2)
           + set("Time integration/Time step", 0.01)
           + set("Time integration/End time", 0.5)
           + set("Output/Probe points", "0, 0; 0.5, 0.5; 0.5, 0; 0.2, -0.1");
  }

  // A pulse at the centre, from rest: h(tau) = sin(pi tau / 0.3) for
  // tau < 0.3.
  std::string
  central_pulse(const double magnitude)
  {
    return set("Loads/Point load 1/Magnitude", magnitude)
           + set("Loads/Point load 1/Time history",
                 "if(tau < 0.3, sin(pi*tau/0.3), 0)");
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  // Weight alone.
  {
    const auto run   = liftoff_tests::run_scene(dynamic_scene("tensionless")
                                              + set("Loads/Self weight", q));
    double     error = 0, kinetic = 0, contact = 1;
    for (const auto &row : run->history())
      {
        for (const double w : row.probes("w"))
          error = std::max(error, std::abs(w - q / gamma_f));
        kinetic = std::max(kinetic, row.energies().kinetic);
        contact = std::min(contact, row["contact_fraction"]);
      }
    checks.less("weight alone: max |w - q/Gamma| / (q/Gamma) over all steps",
                error / (q / gamma_f),
                1e-10);
    checks.less("weight alone: max kinetic energy / strain energy of the "
                "bed",
                kinetic / run->history()[0].energies().supports,
                1e-20);
    checks.within("weight alone: smallest contact fraction", contact, 1, 1);
  }

  // Below the threshold: full contact, linear.
  {
    const double force       = 1.0;
    const auto   tensionless = liftoff_tests::run_scene(
      dynamic_scene("tensionless") + set("Loads/Self weight", q)
      + central_pulse(force));
    const auto bilateral = liftoff_tests::run_scene(
      dynamic_scene("bilateral") + set("Loads/Self weight", q)
      + central_pulse(force));
    const auto force_alone = liftoff_tests::run_scene(dynamic_scene("bilateral")
                                                      + central_pulse(force));
    double     contact = 1, superposed = 0, scale = 0, uplift = 0;
    for (unsigned int n = 0; n < bilateral->history().size(); ++n)
      {
        const auto &row = bilateral->history()[n];
        contact =
          std::min(contact, tensionless->history()[n]["contact_fraction"]);
        for (unsigned int k = 0; k < row.probes("w").size(); ++k)
          {
            const double alone = force_alone->history()[n].probes("w")[k];
            superposed =
              std::max(superposed,
                       std::abs(row.probes("w")[k] - q / gamma_f - alone));
            scale  = std::max(scale, std::abs(alone));
            uplift = std::max(uplift, -alone);
          }
      }
    checks.within("below the threshold: the force alone lifts the weightless "
                  "plate, by less than q/Gamma (max -w / (q/Gamma))",
                  uplift / (q / gamma_f),
                  0.1,
                  0.9);
    checks.within("below the threshold: smallest contact fraction (weight "
                  "holds the plate down)",
                  contact,
                  1,
                  1);
    checks.less("below the threshold: tensionless vs bilateral, max |dw| / "
                "max |w|",
                liftoff_tests::history_difference(*bilateral, *tensionless),
                1e-12);
    checks.less("below the threshold: bilateral(weight + force) - q/Gamma - "
                "bilateral(force), max / max |w of force alone|",
                superposed / scale,
                1e-9);
  }

  // The rigid plate's threshold, static.
  {
    const double gamma_soft = 0.01, e = 1.0 / 3.0, mu = 1.0;
    // 8 cells along x, 3 Gauss points per cell and direction.
    const double x_g       = 0.5 - 0.125 * (1 - std::sqrt(0.6)) / 2;
    const double threshold = q * mu / (12 * e * x_g - 1);
    std::cout << "rigid plate: P* = " << q * mu / (6 * e - 1)
              << ", onset at the outermost Gauss points P_g = " << threshold
              << std::endl;
    const auto scene = [&](const double force) {
      return set("Analysis/Type", "static")
             + set("Foundation/Stiffness", gamma_soft)
             + set("Discretization/Cells along x", 8)
             + set("Discretization/Cells along y", 4)
             + set("Discretization/Polynomial degree", 2)
             + set("Loads/Self weight", q)
             + set("Loads/Point load 1/Magnitude", force)
             + set("Loads/Point load 1/Position", "0.3333333333333333, 0")
             + set("Output/Probe points", "-0.5, 0; 0, 0");
    };
    const double below     = 0.99 * threshold;
    const auto   run_below = liftoff_tests::run_scene(scene(below));
    const auto  &row       = run_below->history().back();
    const double rigid_edge =
      (q * mu + below - 6 * below * e) / (gamma_soft * mu);
    const double rigid_centre = (q * mu + below) / (gamma_soft * mu);
    checks.within("0.99 P_g: contact fraction", row["contact_fraction"], 1, 1);
    checks.less("0.99 P_g: |w(-1/2, 0) - rigid plate| / w(0, 0) of the rigid "
                "plate",
                std::abs(row.probes("w")[0] - rigid_edge) / rigid_centre,
                2e-3);
    const auto above = liftoff_tests::run_scene(scene(1.01 * threshold));
    checks.less("1.01 P_g: contact fraction",
                above->history().back()["contact_fraction"],
                1);
  }
  return checks.exit_code();
}
