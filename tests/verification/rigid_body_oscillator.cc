// A free plate on a bilateral foundation under a suddenly applied uniform
// pressure q moves as a rigid body: M w'' + Gamma w = q with unit mass, so
// w(tau) = (q / Gamma) (1 - cos(sqrt(Gamma) tau)). The rigid translation lies
// in every finite element space, so the only error is Newmark's: the average
// acceleration rule keeps the amplitude and turns the frequency omega into
// omega_h = (2 / dt) atan(omega dt / 2). Checks:
//  - the computed deflection equals the discrete closed form to round-off,
//    everywhere on the plate, for p = 1 and 2;
//  - against the exact oscillator the error falls with order 2 in dt;
//  - with other Newmark parameters (beta = 0.3025, gamma = 0.6, which damp)
//    the deflection follows the scalar Newmark recursion for the same
//    oscillator, written out independently here;
//  - the envelopes: the largest w at every output point and over the plate is
//    the discrete solution's largest value over the steps, at the step where
//    it occurs; the smallest is 0 at tau = 0, the largest pressure Gamma
//    times the largest w, and the moments of the rigid motion vanish;
//  - the history's max_uplift column: 0 while the bilateral plate is pressed
//    into its bed, and V tau for a plate thrown off a tensionless bed with
//    the upward velocity V (free flight, which Newmark integrates exactly).

#include <liftoff/output/envelopes.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace
{
  constexpr double gamma_f = 10.0, q = 1.0;

  std::string
  scene(const unsigned int p,
        const double       dt,
        const double       beta  = 0.25,
        const double       gamma = 0.5)
  {
    return R"(
subsection Plate
  set Aspect ratio = 0.8
  set Thickness ratio = 0.1
end
subsection Foundation
  set Model = bilateral
  set Stiffness = )"
           + std::to_string(gamma_f) + R"(
end
subsection Discretization
  set Cells along x = 4
  set Cells along y = 3
  set Polynomial degree = )"
           + std::to_string(p) + R"(
end
subsection Loads
  subsection Pressure 1
    set Magnitude = )"
           + std::to_string(q) + R"(
  end
end
subsection Time integration
  set Time step = )"
           + std::to_string(dt) + R"(
  set End time = 3
  set Beta = )"
           + std::to_string(beta) + R"(
  set Gamma = )"
           + std::to_string(gamma) + R"(
end
subsection Output
  set Probe points = 0, 0; 0.5, 0.4; -0.31, 0.17
end
)";
  }

  /// Largest deviation of the probe histories from w(tau) over all steps.
  template <typename Reference>
  double
  max_error(const liftoff::Simulator &simulator, const Reference &w)
  {
    double error = 0;
    for (const auto &row : simulator.history())
      for (const double value : row.probes("w"))
        error = std::max(error, std::abs(value - w(row["tau"])));
    return error / (q / gamma_f);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  const double          omega = std::sqrt(gamma_f);
  const auto            exact = [&](const double tau) {
    return q / gamma_f * (1 - std::cos(omega * tau));
  };

  for (const unsigned int p : {1u, 2u})
    {
      const double dt        = 0.02;
      const auto   simulator = liftoff_tests::run_scene(scene(p, dt));
      const double omega_h   = 2.0 / dt * std::atan(omega * dt / 2.0);
      checks.less("p = " + std::to_string(p)
                    + ": max |w - discrete Newmark solution| / (q/Gamma)",
                  max_error(*simulator,
                            [&](const double tau) {
                              return q / gamma_f
                                     * (1 - std::cos(omega_h * tau));
                            }),
                  1e-9);
    }

  // max |w - exact oscillator| / (q/Gamma) as dt is halved.
  liftoff_tests::OrderTable table;
  for (const double dt : {0.02, 0.01, 0.005})
    {
      table.add_value("dt", dt);
      table.add_value("error",
                      max_error(*liftoff_tests::run_scene(scene(1, dt)),
                                exact));
    }
  const std::vector<double> orders = table.orders("error");
  table.set_scientific("error", true);
  table.write_text(std::cout);
  for (const double order : orders)
    checks.within("observed order in dt", order, 1.9, 2.1);
  // Scalar Newmark for w'' + omega^2 w = q from rest, a_0 = q.
  {
    const double              beta = 0.3025, gamma = 0.6, dt = 0.02;
    const std::vector<double> w_newmark = liftoff_tests::scalar_newmark(
      omega * omega, 0.0, q, beta, gamma, dt, 150);
    const auto simulator = liftoff_tests::run_scene(scene(2, dt, beta, gamma));
    double     error     = 0;
    for (unsigned int n = 0; n < simulator->history().size(); ++n)
      for (const double value : simulator->history()[n].probes("w"))
        error = std::max(error, std::abs(value - w_newmark[n]));
    checks.less("beta = 0.3025, gamma = 0.6: max |w - scalar Newmark| / "
                "(q/Gamma)",
                error / (q / gamma_f),
                1e-9);
    // The damped scheme must actually damp: the last swing is smaller.
    checks.less("beta = 0.3025, gamma = 0.6: amplitude decays (last peak / "
                "q/Gamma - 1)",
                *std::max_element(w_newmark.end() - 50, w_newmark.end())
                    / (q / gamma_f)
                  - 1,
                0.99);
  }
  {
    // The run outlives the loop: a range over the history of a temporary
    // reads freed rows.
    double     uplift = 0;
    const auto run    = liftoff_tests::run_scene(scene(2, 0.02));
    for (const auto &row : run->history())
      uplift = std::max(uplift, row["max_uplift"]);
    checks.less("bilateral, pressed down: max uplift / (q/Gamma)",
                uplift / (q / gamma_f),
                1e-12);
  }
  {
    const double dt = 0.02, omega_h = 2.0 / dt * std::atan(omega * dt / 2.0);
    const auto   simulator = liftoff_tests::run_scene(
      scene(2, dt) + "subsection Output\n set Write envelopes = true\nend\n");
    double largest = 0, when = 0;
    for (const auto &row : simulator->history())
      {
        const double w = q / gamma_f * (1 - std::cos(omega_h * row["tau"]));
        if (w > largest)
          std::tie(largest, when) = std::make_tuple(w, row["tau"]);
      }
    const auto &envelopes = simulator->get_envelopes();
    const auto  extremes  = envelopes.extremes();
    const auto  names     = liftoff::Envelopes::names();
    const auto  extreme   = [&](const std::string &name) {
      return extremes[std::find(names.begin(), names.end(), name)
                      - names.begin()];
    };
    const double scale = q / gamma_f;
    checks.less("envelope: |max w_max - largest discrete w| / (q/Gamma)",
                std::abs(extreme("w_max").value - largest) / scale,
                1e-9);
    checks.within("envelope: time of max w_max - time of the largest w",
                  extreme("w_max").time - when,
                  -1e-12,
                  1e-12);
    double spread = 0;
    for (const double w : envelopes.local_field("w_max"))
      spread = std::max(spread, std::abs(w - largest) / scale);
    for (const double t : envelopes.local_field("w_max_time"))
      spread = std::max(spread, std::abs(t - when));
    checks.less("envelope: max over the output points of |w_max - largest "
                "w| / (q/Gamma) and |its time - when|",
                spread,
                1e-9);
    checks.less("envelope: |min w_min| / (q/Gamma), at tau = 0",
                std::abs(extreme("w_min").value) / scale
                  + extreme("w_min").time,
                1e-12);
    checks.less("envelope: |max pressure - Gamma max w| / q",
                std::abs(extreme("foundation_pressure_max").value
                         - gamma_f * largest)
                  / q,
                1e-9);
    checks.less("envelope: rigid motion, max |M| / (q/Gamma)",
                std::max(std::abs(extreme("M_1_max").value),
                         std::abs(extreme("M_2_min").value))
                  / scale,
                1e-9);
  }
  {
    // w > 0 is into the bed: an upward throw is w_dot = -V.
    const double V         = 0.5;
    const auto   simulator = liftoff_tests::run_scene(R"(
subsection Plate
  set Aspect ratio = 0.8
end
subsection Discretization
  set Cells along x = 4
  set Cells along y = 3
  set Polynomial degree = 2
end
subsection Initial conditions
  set Velocity = -0.5; 0; 0
end
subsection Time integration
  set Time step = 0.05
  set End time = 1
end
)");
    double       error     = 0;
    for (const auto &row : simulator->history())
      error = std::max(error, std::abs(row["max_uplift"] - V * row["tau"]));
    checks.within("free flight: rows", simulator->history().size(), 21, 21);
    checks.less("free flight: max |max uplift - V tau| / V", error / V, 1e-10);
  }
  return checks.exit_code();
}
