// Adaptive meshes on bilateral scenes with a known solution
// (manufactured_fields.h: clamped square plate, Gamma = 10, Delta = 0.2).
//
// (a) Static, a steep layer: w, psi_x, psi_y are all
//       A_c X(1-X) tanh(k (X - 0.4)) Y(1-Y) tanh(k (Y - 0.55)),  k = 40,
//     a cross of two layers of width about 1/40 not aligned with any mesh
//     line. From a 4 x 4 mesh, `Static cycles` of Kelly refinement (30 % of
//     the cells per cycle, no coarsening) against uniform refinement. On
//     uniform meshes the layer is unresolved until h is below its width;
//     refining where the error is must reach the theoretical rate in the
//     number of dofs N: L2 error of w ~ N^(-(p+1)/2), H1 error of
//     (w, psi) ~ N^(-p/2), fitted over the last four meshes, cycles 8 to
//     11 (Q1, 8301 to 55959 dofs) and 6 to 9 (Q2, 10695 to 74631)
//     (measured: Q1 0.98 and 0.54, Q2 1.52 and 1.00; one cycle more, in
//     about 1.6 times the time of (a), gave 1.08 and 0.55, 1.47 and 0.97),
//     and the finest uniform mesh's L2 error with fewer dofs (measured:
//     0.54 (Q1) and 0.51 (Q2) of them).
// (b) Dynamic, smooth: the trigonometric fields of manufactured_solution.cc
//     (omega = 2, 250 steps), Q2 from 4 x 4 cells, Kelly every 10 steps up
//     to a finest level 1, 2, 3, the mesh first adapted 3 x level times to
//     the initial displacement (`Initial refinements`): the same error as
//     the uniform mesh of that level (measured: ratio 1.00, 1.00, 1.04).
//     Without the initial adaptation the state starts as its interpolant on
//     the 4 x 4 mesh and the waves carry that error to the end: 7.7, 49
//     and 477 times the uniform error at levels 1, 2, 3 (measured while
//     this test was written, then with a limit of half the uniform cells;
//     with only `level` initial adaptations still 6.4 to 42 times).
// (c) Dynamic, the steep layer of (a) with omega = 2, Q2 from 4 x 4,
//     `Initial refinements` 2 to 8, then Kelly (10 % refined, 5 % coarsened)
//     every 25 of 125 steps: the mesh changes during the run (refined and
//     coarsened, u, v, a transferred), and the end error must still
//     converge (measured: from 0.29 down to 5.4e-3, below the uniform
//     8 x 8 error 5.0e-2). Generalized-alpha with rho_inf = 1 is Newmark's
//     rule and must stay equal to it through the transfers (6.2e-14); it
//     weights the last step's force balance, so an acceleration left as
//     interpolated (out of balance on the new mesh) makes them differ
//     (4.5e-2, seen before TimeStepper::equilibrate ran after a transfer).
//
// Seen to fail: `liftoff_tests adaptive_convergence "point loads"` (an
// indicator that marks no cell here) keeps the coarse mesh: 13 checks fail.

#include <deal.II/base/function.h>

#include "manufactured_fields.h"
#include "test_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace liftoff_tests::manufactured;
  using liftoff_tests::set;

  std::string indicator = "kelly";

  struct Sample
  {
    double n_dofs;
    double l2_w;   // L2 error of w
    double h1_all; // H1 seminorm error of (w, psi_x, psi_y)
  };

  Sample
  errors(const liftoff::Simulator &sim, const Fields &fields, const double t)
  {
    ManufacturedField exact(fields, exact_values);
    exact.set_time(t);
    return {static_cast<double>(sim.get_discretization().dof_handler.n_dofs()),
            error_of(sim, exact, ComponentSelectFunction<2>(0, 3)),
            error_of(sim,
                     exact,
                     ComponentSelectFunction<2>(std::make_pair(0u, 3u), 3),
                     VectorTools::H1_seminorm)};
  }

  std::string
  adaptive(const double refine_fraction, const double coarsen_fraction)
  {
    return set("Mesh refinement/Adaptive", "true")
           + set("Mesh refinement/Indicators", indicator)
           + set("Mesh refinement/Refine fraction", refine_fraction)
           + set("Mesh refinement/Coarsen fraction", coarsen_fraction)
           + set("Mesh refinement/Maximum number of cells", 0);
  }

  /// Least-squares slope of log(error) against log(N).
  double
  slope(const std::vector<Sample> &s,
        const unsigned int         first,
        double Sample::*error)
  {
    double       mx = 0, my = 0, sxx = 0, sxy = 0;
    const double n = s.size() - first;
    for (unsigned int k = first; k < s.size(); ++k)
      {
        mx += std::log(s[k].n_dofs) / n;
        my += std::log(s[k].*error) / n;
      }
    for (unsigned int k = first; k < s.size(); ++k)
      {
        const double dx = std::log(s[k].n_dofs) - mx;
        sxx += dx * dx;
        sxy += dx * (std::log(s[k].*error) - my);
      }
    return sxy / sxx;
  }

  void
  print(const std::string &name, const std::vector<Sample> &samples)
  {
    std::cout << name << "\n      dofs   L2 error w   H1 error (w, psi)\n";
    for (const Sample &s : samples)
      std::cout << std::setw(10) << s.n_dofs << "   " << s.l2_w << "   "
                << s.h1_all << "\n";
  }

  /// The cross of two steep layers (see the top), times T.
  Fields
  layer_fields(const TimeFactor T)
  {
    const double k = 40;
    return {"layer",
            T,
            {{1.0, 0.6, -0.35}},
            {{layer(k, 0.4), layer(k, 0.4), layer(k, 0.4)}},
            {{layer(k, 0.55), layer(k, 0.55), layer(k, 0.55)}}};
  }

  void
  static_layer(liftoff_tests::Checks &checks, const unsigned int degree)
  {
    const Fields      fields = layer_fields(TimeFactor{0.0});
    ManufacturedField force(fields, strong_form);
    const std::string scene =
      set("Analysis/Type", "static")
      + set("Initial conditions/Displacement", "0; 0; 0")
      + set("Initial conditions/Velocity", "0; 0; 0");

    std::vector<Sample>             uniform, refined;
    const std::vector<unsigned int> cells =
      degree == 1 ? std::vector<unsigned int>{4, 8, 16, 32, 64}
                  : std::vector<unsigned int>{4, 8, 16, 32};
    for (const unsigned int n : cells)
      uniform.push_back(
        errors(*liftoff_tests::run_scene(plate_scene(fields, degree, n) + scene,
                                         &force),
               fields,
               0.0));
    const unsigned int n_cycles = degree == 1 ? 11 : 9;
    for (unsigned int cycles = 0; cycles <= n_cycles; ++cycles)
      refined.push_back(
        errors(*liftoff_tests::run_scene(
                 plate_scene(fields, degree, 4) + scene + adaptive(0.3, 0.03)
                   + set("Mesh refinement/Maximum level", 10)
                   + set("Mesh refinement/Static cycles", cycles),
                 &force),
               fields,
               0.0));

    const std::string p = "(a) Q" + std::to_string(degree);
    print(p + " uniform", uniform);
    print(p + " adaptive (" + indicator + ")", refined);
    const unsigned int last = 4; // the cycles the rates are fitted on
    const double       l2_rate =
      -slope(refined, refined.size() - last, &Sample::l2_w);
    const double h1_rate =
      -slope(refined, refined.size() - last, &Sample::h1_all);
    const double uniform_l2_rate =
      -slope(uniform, uniform.size() - 2, &Sample::l2_w);
    std::cout << p << ": rates in N over the last " << last
              << " adaptive meshes: L2 " << l2_rate << ", H1 " << h1_rate
              << "; uniform (last two meshes) L2 " << uniform_l2_rate
              << std::endl;
    checks.within(p + " adaptive: rate of the L2 error of w in N",
                  l2_rate,
                  0.9 * 0.5 * (degree + 1),
                  1.5 * 0.5 * (degree + 1));
    checks.within(p + " adaptive: rate of the H1 error of (w, psi) in N",
                  h1_rate,
                  0.9 * 0.5 * degree,
                  1.5 * 0.5 * degree);

    // The dofs the adaptive sequence needs to reach the finest uniform
    // mesh's L2 error of w (log-linear between the two cycles around it).
    const Sample &target = uniform.back();
    double        needed = std::numeric_limits<double>::infinity();
    for (unsigned int k = 1; k < refined.size(); ++k)
      if (refined[k].l2_w <= target.l2_w)
        {
          const Sample &a = refined[k - 1], &b = refined[k];
          const double  s =
            std::log(target.l2_w / a.l2_w) / std::log(b.l2_w / a.l2_w);
          needed = a.n_dofs * std::pow(b.n_dofs / a.n_dofs, s);
          break;
        }
    checks.less(p + " adaptive dofs to the finest uniform error / its dofs",
                needed / target.n_dofs,
                0.75);
  }

  void
  dynamic_smooth(liftoff_tests::Checks &checks)
  {
    const double       c1 = 0.6, c2 = -0.35, end_time = 0.5, dt = 2e-3;
    const unsigned int degree = 2, coarse = 4;
    const Fields       fields{"trigonometric",
                        TimeFactor{2.0},
                        {{1.0, c1, c2}},
                        {{sine(1), sine(2), sine(1)}},
                        {{sine(1), sine(1), sine(2)}}};
    ManufacturedField  force(fields, strong_form);
    const std::string  scene = set("Analysis/Type", "dynamic")
                              + set("Time integration/Time step", dt)
                              + set("Time integration/End time", end_time);
    std::vector<Sample> uniform, refined;
    for (unsigned int level = 0; level <= 3; ++level)
      {
        const unsigned int n = coarse << level;
        uniform.push_back(
          errors(*liftoff_tests::run_scene(
                   plate_scene(fields, degree, n) + scene, &force),
                 fields,
                 end_time));
        if (level == 0)
          continue;
        refined.push_back(
          errors(*liftoff_tests::run_scene(
                   plate_scene(fields, degree, coarse) + scene
                     + adaptive(0.3, 0.03) + set("Mesh refinement/Interval", 10)
                     + set("Mesh refinement/Maximum level", level)
                     + set("Mesh refinement/Initial refinements", 3 * level)
                     + set("Mesh refinement/Maximum number of cells", n * n),
                   &force),
                 fields,
                 end_time));
      }
    print("(b) Q2 uniform, 4 x 4 to 32 x 32", uniform);
    print("(b) Q2 adaptive, finest level 1 to 3", refined);
    for (unsigned int level = 1; level <= 3; ++level)
      {
        const Sample     &a = refined[level - 1], &u = uniform[level];
        const std::string l = std::to_string(level);
        checks.less("(b) level " + l + ": adaptive L2 error of w / uniform",
                    a.l2_w / u.l2_w,
                    1.1);
        if (level > 1)
          checks.less("(b) level " + l
                        + ": adaptive L2 error of w / that of level "
                        + std::to_string(level - 1),
                      a.l2_w / refined[level - 2].l2_w,
                      0.25);
      }
  }

  void
  dynamic_layer(liftoff_tests::Checks &checks)
  {
    const double       end_time = 0.25, dt = 2e-3;
    const unsigned int degree = 2;
    const Fields       fields = layer_fields(TimeFactor{2.0});
    ManufacturedField  force(fields, strong_form);
    const std::string  scene = set("Analysis/Type", "dynamic")
                              + set("Time integration/Time step", dt)
                              + set("Time integration/End time", end_time);
    std::vector<Sample> uniform, refined;
    for (const unsigned int n : {4, 8, 16, 32})
      uniform.push_back(
        errors(*liftoff_tests::run_scene(plate_scene(fields, degree, n) + scene,
                                         &force),
               fields,
               end_time));
    const auto adaptive_scene = [&](const unsigned int cycles) {
      return plate_scene(fields, degree, 4) + scene + adaptive(0.1, 0.05)
             + set("Mesh refinement/Interval", 25)
             + set("Mesh refinement/Maximum level", 10)
             + set("Mesh refinement/Initial refinements", cycles);
    };
    std::unique_ptr<liftoff::Simulator> newmark;
    for (unsigned int cycles = 2; cycles <= 8; ++cycles)
      {
        auto sim = liftoff_tests::run_scene(adaptive_scene(cycles), &force);
        refined.push_back(errors(*sim, fields, end_time));
        std::cout << "(c) " << cycles << " initial refinements: "
                  << static_cast<unsigned long>(sim->history()[1]["dofs"])
                  << " dofs in step 1, "
                  << static_cast<unsigned long>(sim->history().back()["dofs"])
                  << " at the end" << std::endl;
        if (cycles == 8)
          newmark = std::move(sim);
      }
    print("(c) Q2 uniform", uniform);
    print("(c) Q2 adaptive, Initial refinements 2 to 8 (dofs at the end)",
          refined);
    std::cout << "(c) rates in N over the last 4: L2 "
              << -slope(refined, refined.size() - 4, &Sample::l2_w) << ", H1 "
              << -slope(refined, refined.size() - 4, &Sample::h1_all)
              << std::endl;
    checks.less("(c) adaptive: L2 error of w, last / first",
                refined.back().l2_w / refined.front().l2_w,
                0.05);
    checks.less("(c) adaptive, 8 initial refinements: L2 error of w / "
                "uniform 8 x 8",
                refined.back().l2_w / uniform[1].l2_w,
                0.2);

    // Generalized-alpha keeps the force balance of the last step, which a
    // new mesh must rebuild. With rho_inf = 1 it is Newmark's rule
    // (alpha_m = alpha_f = 1/2, and the balance enters each step with
    // weight 1/2; tests/verification/generalized_alpha.cc), so the two
    // runs must agree to round-off through every transfer. Compared at
    // sample points, relative to the largest |w|.
    const auto alpha = liftoff_tests::run_scene(
      adaptive_scene(8) + set("Time integration/Scheme", "generalized-alpha")
        + set("Time integration/Spectral radius", 1),
      &force);
    double difference = 0, largest = 0;
    for (double x = -0.45; x < 0.5; x += 0.05)
      for (double y = -0.45; y < 0.5; y += 0.05)
        {
          const Point<2> p(x, y);
          difference = std::max(difference,
                                std::abs(alpha->deflection_at(p)
                                         - newmark->deflection_at(p)));
          largest    = std::max(largest, std::abs(newmark->deflection_at(p)));
        }
    checks.less("(c) 8 initial refinements: generalized-alpha vs Newmark, "
                "largest difference of w / largest w",
                difference / largest,
                1e-10);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  if (argc > 1)
    indicator = argv[1];
  std::cout << std::scientific << std::setprecision(3);
  checks.less("layer fields: analytic vs finite-difference derivatives",
              finite_difference_check(layer_fields(TimeFactor{1.0})),
              1e-4);
  static_layer(checks, 1);
  static_layer(checks, 2);
  dynamic_smooth(checks);
  dynamic_layer(checks);
  return checks.exit_code();
}
