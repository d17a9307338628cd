// Generalized-alpha (Chung and Hulbert 1993), checked three ways:
//  - A free plate on bilateral springs under a suddenly applied uniform
//    pressure is the oscillator w'' + Gamma w = q (see
//    rigid_body_oscillator.cc). Its deflection must follow the scalar
//    generalized-alpha recursion, written out independently here from the
//    published formulas, to round-off, for several rho_inf, both at low
//    frequency and far above 1/dtau.
//  - That recursion, with omega dtau = 1e6, must damp at the rate rho_inf
//    per step: the definition of the spectral radius at infinite frequency.
//  - With rho_inf = 1 the scheme is Newmark's average acceleration rule: on
//    a scene with lift-off the two histories must agree to round-off.

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace
{
  constexpr double q = 1.0;

  std::string
  oscillator_scene(const double rho, const double gamma_f, const double dt)
  {
    std::ostringstream text;
    text.precision(17);
    text << "subsection Plate\n  set Aspect ratio = 0.8\nend\n"
         << "subsection Foundation\n  set Model = bilateral\n"
         << "  set Stiffness = " << gamma_f << "\nend\n"
         << "subsection Discretization\n  set Cells along x = 3\n"
         << "  set Cells along y = 2\n  set Polynomial degree = 2\nend\n"
         << "subsection Loads\n  subsection Pressure 1\n"
         << "    set Magnitude = " << q << "\n  end\nend\n"
         << "subsection Time integration\n"
         << "  set Scheme = generalized-alpha\n"
         << "  set Spectral radius = " << rho << "\n"
         << "  set Time step = " << dt << "\n"
         << "  set End time = " << 40 * dt << "\nend\n"
         << "subsection Output\n  set Probe points = 0.3, -0.2\nend\n";
    return text.str();
  }

  struct State
  {
    double u, v, a;
  };

  // One step of m a + k u = f (m = 1) by generalized-alpha with weighted
  // forces: (1 - am) a1 + am a0 + (1 - af) k u1 + af k u0 = f.
  State
  scalar_step(const State &s,
              const double rho,
              const double k,
              const double dt,
              const double f)
  {
    const double am = (2 * rho - 1) / (rho + 1), af = rho / (rho + 1);
    const double beta      = 0.25 * (1 - am + af) * (1 - am + af);
    const double gamma     = 0.5 - am + af;
    const double predictor = s.u + dt * s.v + dt * dt * (0.5 - beta) * s.a;
    const double a1 = (f - am * s.a - af * k * s.u - (1 - af) * k * predictor)
                      / ((1 - am) + (1 - af) * k * beta * dt * dt);
    return {predictor + beta * dt * dt * a1,
            s.v + dt * ((1 - gamma) * s.a + gamma * a1),
            a1};
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  for (const double rho : {1.0, 0.8, 0.3, 0.0})
    for (const double omega_dt : {0.3, 30.0})
      {
        const double gamma_f = 100.0, dt = omega_dt / std::sqrt(gamma_f);
        const auto   plate =
          liftoff_tests::run_scene(oscillator_scene(rho, gamma_f, dt));
        State  s{0.0, 0.0, q}; // a0 from the force balance at rest
        double difference = 0, scale = 0;
        for (const auto &record : plate->history())
          {
            difference =
              std::max(difference, std::abs(record.probes("w")[0] - s.u));
            scale = std::max(scale, std::abs(s.u));
            s     = scalar_step(s, rho, gamma_f, dt, q);
          }
        std::ostringstream what;
        what << "rho_inf = " << rho << ", omega dt = " << omega_dt
             << ": plate vs scalar recursion (relative)";
        checks.less(what.str(), difference / scale, 1e-9);
      }

  // Spectral radius at omega dt = 1e6: growth of the free response over
  // steps 100 to 200 (the double root adds a factor (200/100)^(1/100)).
  for (const double rho : {0.8, 0.5})
    {
      const double k = 1e12, dt = 1e-0;
      State        s{1.0, 0.0, -k};
      double       norm_100 = 0;
      for (unsigned int n = 1; n <= 200; ++n)
        {
          s = scalar_step(s, rho, k, dt, 0.0);
          if (n == 100)
            norm_100 = std::abs(s.u) + std::abs(s.v) * dt;
        }
      const double rate =
        std::pow((std::abs(s.u) + std::abs(s.v) * dt) / norm_100, 0.01);
      std::ostringstream what;
      what << "rho_inf = " << rho << ": damping per step at omega dt = 1e6";
      checks.within(what.str(), rate, 0.98 * rho, 1.03 * rho);
    }

  // rho_inf = 1 against Newmark 1/4, 1/2 on a scene with lift-off; fresh
  // factorisations so that only round-off separates them.
  const std::string scene = liftoff_tests::symmetric_scene("quarter", 5, 4)
                            + "subsection Linear solver\n"
                              "  set Refactorisation threshold = 0\nend\n";
  const auto newmark = liftoff_tests::run_scene(scene);
  const auto alpha   = liftoff_tests::run_scene(
    scene
    + "subsection Time integration\n  set Scheme = generalized-alpha\n"
        "  set Spectral radius = 1\nend\n");
  checks.less("rho_inf = 1 vs Newmark with lift-off: probe histories",
              liftoff_tests::history_difference(*alpha, *newmark),
              1e-11);
  return checks.exit_code();
}
