// Loads/Temperature load: a temperature difference dT through the
// thickness bends the plate as the free curvature kappa_T = alpha dT / H in
// both directions (doc/model.md, "Temperature"). Checks against closed
// forms:
//  - a free plate curls to w = kappa_T (x^2 + y^2) / 2 with no moment. A
//    plate needs something to hold its rigid motions; here a bilateral bed
//    Gamma with the pressure Gamma kappa_T (x^2 + y^2) / 2 on top, which the
//    curled shape carries by the bed alone: the exact solution is the
//    curled shape, which Q2 holds, so w and every moment are exact to
//    round-off (the shape's sign is that of the derivation: dT > 0, warm
//    on top, bends the edges into the bed). Full plate, quarter model and
//    two ranks (the _np2 run) give the same;
//  - dT linear in x on a narrow strip (mu = 0.05): the curvature follows
//    kappa_T(x) along the strip, as a beam's does (a plate's free curvature
//    that is not constant is not a curvature field, so the moments are
//    not zero but of the order of the width);
//  - a linear Profile equals the default; a nonlinear one bends the plate
//    as its equivalent linear difference and adds its self-equilibrating
//    stress (closed form) to sigma_xx at the bed-side face.

#include "test_tools.h"

#include <cmath>

namespace
{
  using liftoff_tests::set;
  constexpr double gamma_f = 10, delta = 0.05, nu = 0.2, alpha = 1e-3;

  std::string
  curling_scene(const std::string &symmetry,
                const double       dt,
                const std::string &profile    = "1, 0",
                const double       difference = 1)
  {
    // kappa_T = alpha dT / Delta; the pressure Gamma kappa_T r^2 / 2.
    const double kappa = alpha * dt * difference / delta;
    return set("Loads/Temperature load 1/Profile", profile)
           + set("Analysis/Type", "static")
           + set("Foundation/Model", "bilateral")
           + set("Foundation/Stiffness", gamma_f)
           + set("Plate/Thickness ratio", delta)
           + set("Plate/Poisson ratio", nu)
           + set("Discretization/Symmetry", symmetry)
           + set("Discretization/Cells along x", 4)
           + set("Discretization/Cells along y", 4)
           + set("Discretization/Polynomial degree", 2)
           + set("Loads/Temperature load 1/Magnitude", dt)
           + set("Loads/Temperature load 1/Expansion coefficient", alpha)
           + set("Loads/Pressure 1/Magnitude", gamma_f * kappa / 2)
           + set("Loads/Pressure 1/Intensity", "x^2 + y^2")
           + set("Output/Probe points", "0, 0; 0.5, 0.5; 0.5, 0; 0.2, -0.1")
           + set("Output/Probe quantities",
                 "M_xx(0.2; 0.3), M_yy(0.2; 0.3), M_xy(0.2; 0.3), "
                 "M_xx(0.5; 0.1), M_yy(0.5; 0.5), sigma_max(0.1; 0.1), "
                 "Q_x(0.3; 0.2)");
  }

  // Largest |w - kappa (x^2 + y^2) / 2| over the probes, over kappa / 4,
  // and the largest |moment| (sigma_max: times Delta^2 / 6) over the
  // restrained moment (1 + nu) kappa.
  std::pair<double, double>
  curling_errors(const liftoff::Simulator &run, const double kappa)
  {
    const auto                              &row     = run.history().back();
    const std::vector<std::array<double, 2>> points  = {{{0, 0}},
                                                        {{0.5, 0.5}},
                                                        {{0.5, 0}},
                                                        {{0.2, -0.1}}};
    double                                   w_error = 0, m_error = 0;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const double x = points[k][0], y = points[k][1];
        w_error =
          std::max(w_error,
                   std::abs(row.probes("w")[k] - kappa * (x * x + y * y) / 2));
      }
    for (const std::string name : {"M_xx", "M_yy", "M_xy", "Q_x"})
      for (const double m : row.probes(name))
        m_error = std::max(m_error, std::abs(m));
    for (const double s : row.probes("sigma_max"))
      m_error = std::max(m_error, std::abs(s) * delta * delta / 6);
    return {w_error / (std::abs(kappa) / 4),
            m_error / ((1 + nu) * std::abs(kappa))};
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  const double          dt = 10, kappa = alpha * dt / delta;

  // The free plate curls, with no moment, on the full plate and a quarter.
  for (const std::string symmetry : {"full", "quarter"})
    {
      const auto run = liftoff_tests::run_scene(curling_scene(symmetry, dt));
      const auto [w_error, m_error] = curling_errors(*run, kappa);
      checks.less(symmetry + ": max |w - kappa_T r^2 / 2| / (kappa_T / 4)",
                  w_error,
                  1e-11);
      checks.less(symmetry + ": max |M| / ((1 + nu) kappa_T)", m_error, 1e-10);
    }
  // Night (dT < 0): the edges curl up, w < 0 at the corner.
  {
    const auto run = liftoff_tests::run_scene(curling_scene("full", -dt));
    const auto [w_error, m_error] = curling_errors(*run, -kappa);
    checks.less("night: max |w - kappa_T r^2 / 2| / (|kappa_T| / 4)",
                w_error,
                1e-11);
    checks.less("night: max |M| / ((1 + nu) |kappa_T|)", m_error, 1e-10);
  }

  // dT = dT_0 (1 + x) on a strip 0.05 wide: a beam's curvature follows
  // kappa_T(x) exactly, w = kappa_0 (x^2 / 2 + x^3 / 6) (+ the same across,
  // (1 + x) y^2 / 2); the bed carries the pressure that shape needs. The
  // plate's twist, kappa_0 y, is not free, so it differs by the order of
  // the width.
  {
    const double mu    = 0.05;
    const auto   shape = [&](const double x, const double y) {
      return kappa * (x * x / 2 + x * x * x / 6 + (1 + x) * y * y / 2);
    };
    const auto run = liftoff_tests::run_scene(
      set("Analysis/Type", "static") + set("Foundation/Model", "bilateral")
      + set("Foundation/Stiffness", gamma_f) + set("Plate/Aspect ratio", mu)
      + set("Plate/Thickness ratio", delta) + set("Plate/Poisson ratio", nu)
      + set("Discretization/Cells along x", 32)
      + set("Discretization/Cells along y", 2)
      + set("Discretization/Polynomial degree", 2)
      + set("Loads/Temperature load 1/Magnitude", dt)
      + set("Loads/Temperature load 1/Intensity", "1 + x")
      + set("Loads/Temperature load 1/Expansion coefficient", alpha)
      + set("Loads/Pressure 1/Magnitude", gamma_f * kappa)
      + set("Loads/Pressure 1/Intensity",
            "x^2 / 2 + x^3 / 6 + (1 + x) * y^2 / 2")
      + set("Output/Probe points", "-0.5, 0; -0.25, 0; 0, 0; 0.25, 0; 0.5, 0"));
    const std::vector<double> xs = {-0.5, -0.25, 0, 0.25, 0.5};
    const auto               &w  = run->history().back().probes("w");
    // The curvature (w(x - h) - 2 w(x) + w(x + h)) / h^2 at x = -0.25, 0,
    // 0.25 against kappa_0 (1 + x) (exact for the cubic).
    double error = 0;
    for (unsigned int k = 1; k < 4; ++k)
      error = std::max(error,
                       std::abs((w[k - 1] - 2 * w[k] + w[k + 1]) / 0.0625
                                - kappa * (1 + xs[k]))
                         / kappa);
    std::cout << "dT (1 + x) on the strip: w(0.5) " << w[4] << " (beam "
              << shape(0.5, 0) << ")" << std::endl;
    checks.less("dT (1 + x) on a strip mu = 0.05: max |curvature - kappa_0 "
                "(1 + x)| / kappa_0 along its axis",
                error,
                1e-3);
  }

  // Profiles: a linear one is the default; a nonlinear one bends as its
  // equivalent linear difference and adds its self-equilibrating stress.
  {
    const auto run = liftoff_tests::run_scene(
      curling_scene("full", dt / 2, "2, 1.5, 1, 0.5, 0", 2));
    const auto [w_error, m_error] = curling_errors(*run, kappa);
    checks.less("linear profile 2, ..., 0 at dT / 2: max |w - kappa_T r^2 / "
                "2| / (kappa_T / 4)",
                w_error,
                1e-11);
    checks.less("linear profile: max |M| and |sigma_max| (Delta^2 / 6) / "
                "((1 + nu) kappa_T)",
                m_error,
                1e-10);
  }
  {
    // T(s) = 1 - s^3 by points at s = k / 4; the closed forms of the
    // piecewise-linear profile by a fine midpoint rule.
    const std::vector<double> t = {1, 1 - 1 / 64., 1 - 1 / 8., 1 - 27 / 64., 0};
    const auto                profile_at = [&](const double s) {
      const unsigned int k = std::min(3u, static_cast<unsigned int>(s * 4));
      const double       f = s * 4 - k;
      return (1 - f) * t[k] + f * t[k + 1];
    };
    double             mean = 0, difference = 0;
    const unsigned int n = 400000;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double s = (i + 0.5) / n;
        mean += profile_at(s) / n;
        difference += -12 * profile_at(s) * (s - 0.5) / n;
      }
    const auto self_equilibrating = [&](const double s) {
      return profile_at(s) - mean + difference * (s - 0.5);
    };
    // -E alpha T / (1 - nu) in F0 / L^2: -12 (1 + nu) alpha T / Delta^3.
    const double bottom =
      -12 * (1 + nu) * alpha * dt * self_equilibrating(1) / std::pow(delta, 3);
    const double top =
      -12 * (1 + nu) * alpha * dt * self_equilibrating(0) / std::pow(delta, 3);
    std::cout << "profile 1 - s^3: mean " << mean << ", dT_eq " << difference
              << ", T_se(0) " << self_equilibrating(0) << ", T_se(1) "
              << self_equilibrating(1) << std::endl;
    const auto run = liftoff_tests::run_scene(
      curling_scene("full", dt, "1, 0.984375, 0.875, 0.578125, 0", difference)
      + set("Output/Probe quantities",
            "M_xx(0.2; 0.3), sigma_xx(0.2; 0.3), sigma_yy(-0.1; 0.4), "
            "sigma_max(0.1; 0.1)"));
    const auto [w_error, m_error] = curling_errors(*run, kappa * difference);
    const auto &row               = run->history().back();
    checks.less("profile 1 - s^3: max |w - kappa_eq r^2 / 2| / (kappa_eq / "
                "4)",
                w_error,
                1e-11);
    checks.less("profile 1 - s^3: |sigma_xx - closed form| / |closed form| "
                "(bed side)",
                std::abs(row.probes("sigma_xx")[0] - bottom) / std::abs(bottom),
                1e-9);
    checks.less("profile 1 - s^3: |sigma_yy - closed form| / |closed form|",
                std::abs(row.probes("sigma_yy")[0] - bottom) / std::abs(bottom),
                1e-9);
    checks.less("profile 1 - s^3: |sigma_max - max(faces)| / max(faces)",
                std::abs(row.probes("sigma_max")[0] - std::max(bottom, top))
                  / std::max(bottom, top),
                1e-9);
  }
  return checks.exit_code();
}
