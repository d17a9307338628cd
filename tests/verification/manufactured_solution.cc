// Test 7: manufactured solution of the dynamic Mindlin plate on a bilateral
// Winkler foundation, clamped on all edges (manufactured_fields.h: the
// fields, the forcing from the strong form, the scene), with
//   T(t) = cos(omega t) + 0.5 sin(omega t)  (T'(0) != 0: the initial
//          velocity is exercised too).
// Trigonometric fields, for the spatial error:
//   w = T sin(pi X) sin(pi Y), psi_x = T c1 sin(2 pi X) sin(pi Y),
//   psi_y = T c2 sin(pi X) sin(2 pi Y).
// Bubble fields, for the time error: B = X(1-X) Y(1-Y) and
//   w = T B, psi_x = T c1 B, psi_y = T c2 B,
// which lie in the Q2 space (the spatial error is zero for p >= 2).
// strong_form() is checked against a closed form derived by hand for the
// trigonometric fields, and its derivatives against finite differences.
//
// (a) Space: trigonometric fields, small time step and slow T, so the L2
//     error of w at the end time is the spatial error; expected order p + 1.
// (b) Time: bubble fields, p = 2 (no spatial error at all), fast T, dt
//     halved three times; Newmark's average acceleration rule is second
//     order.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include "manufactured_fields.h"
#include "test_tools.h"

#include <array>
#include <chrono>
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
  constexpr double c1 = 0.6;   // amplitudes of the rotations,
  constexpr double c2 = -0.35; // unequal so x/y mix-ups show

  /// Trigonometric fields: not in any FE space, so the spatial error shows.
  Fields
  trigonometric_fields(const TimeFactor T)
  {
    return {"trigonometric",
            T,
            {{1.0, c1, c2}},
            {{sine(1), sine(2), sine(1)}},
            {{sine(1), sine(1), sine(2)}}};
  }

  /// Bubble fields X(1-X) Y(1-Y): they lie in the Q2 space, all integrals
  /// of the scheme are exact for them, and so the spatial error is zero on
  /// any mesh for p >= 2: only the time error remains.
  Fields
  bubble_fields(const TimeFactor T)
  {
    return {"bubble",
            T,
            {{1.0, c1, c2}},
            {{bubble(), bubble(), bubble()}},
            {{bubble(), bubble(), bubble()}}};
  }

  /// The forcing of the trigonometric fields derived by hand from the
  /// energy (an independent transcription of strong_form()):
  ///   f_w = (T'' + (2 S pi^2 + Gamma) T) sx1 sy1
  ///         + 2 pi S T (c1 cx2 sy1 + c2 sx1 cy2)
  ///   m_x = (I T'' + ((4 + (1-nu)/2) pi^2 + S) T) c1 sx2 sy1
  ///         - (1+nu) pi^2 T c2 cx1 cy2 - S pi T cx1 sy1
  ///   m_y = the same with x <-> y and c1 <-> c2,
  /// sxk = sin(k pi X), cxk = cos(k pi X), etc. The cross terms come from
  /// nu psi_y,yx + (1-nu)/2 psi_y,xy = (1+nu)/2 psi_y,xy, psi_y,xy =
  /// 2 pi^2 T c2 cx1 cy2. Returns the largest difference to strong_form()
  /// relative to the largest forcing.
  double
  hand_derivation_check(const TimeFactor T)
  {
    const Fields fields = trigonometric_fields(T);
    const double pi = M_PI, nu = poisson_ratio, G = gamma_foundation;
    double       max_difference = 0, max_forcing = 0;
    for (const double t : {0.0, 0.37, 1.1})
      for (const double x : {-0.41, -0.13, 0.05, 0.33})
        for (const double y : {-0.37, -0.02, 0.21, 0.44})
          {
            const double X = x + 0.5, Y = y + 0.5;
            const double sx1 = std::sin(pi * X), cx1 = std::cos(pi * X);
            const double sx2 = std::sin(2 * pi * X), cx2 = std::cos(2 * pi * X);
            const double sy1 = std::sin(pi * Y), cy1 = std::cos(pi * Y);
            const double sy2 = std::sin(2 * pi * Y), cy2 = std::cos(2 * pi * Y);
            const double T0 = T.value(t), T2 = T.second(t);
            const double own =
              I * T2 + ((4 + 0.5 * (1 - nu)) * pi * pi + S) * T0;
            const std::array<double, 3> hand = {
              {(T2 + (2 * S * pi * pi + G) * T0) * sx1 * sy1
                 + 2 * pi * S * T0 * (c1 * cx2 * sy1 + c2 * sx1 * cy2),
               own * c1 * sx2 * sy1 - (1 + nu) * pi * pi * T0 * c2 * cx1 * cy2
                 - S * pi * T0 * cx1 * sy1,
               own * c2 * sx1 * sy2 - (1 + nu) * pi * pi * T0 * c1 * cx2 * cy1
                 - S * pi * T0 * sx1 * cy1}};
            const auto generic = strong_form(derivatives(fields, {x, y}, t));
            for (unsigned int k = 0; k < 3; ++k)
              {
                max_difference =
                  std::max(max_difference, std::abs(hand[k] - generic[k]));
                max_forcing = std::max(max_forcing, std::abs(generic[k]));
              }
          }
    return max_difference / max_forcing;
  }

  struct Errors
  {
    double w;       // L2 error of w at the end time
    double psi;     // L2 error of (psi_x, psi_y) at the end time
    double seconds; // wall time of the run
  };


  Errors
  run_manufactured(const unsigned int degree,
                   const unsigned int cells,
                   const Fields      &fields,
                   const double       time_step,
                   const double       end_time,
                   const std::string &shear_treatment = "full",
                   const std::string &element         = "lagrange")
  {
    std::ostringstream scene;
    scene << std::setprecision(17) << plate_scene(fields, degree, cells)
          << "subsection Analysis\n"
          << "  set Type = dynamic\n"
          << "end\n"
          << "subsection Discretization\n"
          << "  set Shear integration = " << shear_treatment << "\n"
          << "  set Element = " << element << "\n"
          << "end\n"
          << "subsection Time integration\n"
          << "  set Time step = " << time_step << "\n"
          << "  set End time = " << end_time << "\n"
          << "end\n";

    const auto        start = std::chrono::steady_clock::now();
    ManufacturedField force(fields, strong_form);
    {
      const auto        sim = liftoff_tests::run_scene(scene.str(), &force);
      ManufacturedField exact(fields, exact_values);
      exact.set_time(end_time);
      const double w_error =
        error_of(*sim, exact, ComponentSelectFunction<2>(0, 3));
      const double psi_error =
        error_of(*sim,
                 exact,
                 ComponentSelectFunction<2>(std::make_pair(1u, 3u), 3));
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      return Errors{w_error, psi_error, seconds};
    }
  }

  // One row of an order table: the errors of a run and its wall time.
  void
  add_errors(liftoff_tests::OrderTable &table, const Errors &e)
  {
    table.add_value("L2 error w", e.w);
    table.add_value("L2 error psi", e.psi);
    table.add_value("time [s]", e.seconds);
  }

  // Print the table with the observed orders of both errors (against the
  // column `reference`, or one halving per row); return those of w.
  std::vector<double>
  write_orders(liftoff_tests::OrderTable &table, const std::string &reference)
  {
    const std::vector<double> w_orders = table.orders("L2 error w", reference);
    table.orders("L2 error psi", reference);
    for (const std::string key : {"L2 error w", "L2 error psi"})
      {
        table.set_scientific(key, true);
        table.set_precision(key, 4);
      }
    table.set_precision("time [s]", 1);
    table.write_text(std::cout);
    return w_orders;
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  std::cout << std::scientific << std::setprecision(4);
  std::cout << "S = " << S << ", I = " << I << ", Gamma = " << gamma_foundation
            << ", nu = " << poisson_ratio << std::endl;

  const auto       total_start = std::chrono::steady_clock::now();
  const TimeFactor slow{2.0}, fast{10.0};
  const Fields     space_fields = trigonometric_fields(slow);
  const Fields     time_fields  = bubble_fields(fast);

  // The forcing is what it claims to be.
  checks.less("forcing: hand derivation vs strong_form(), relative",
              hand_derivation_check(slow),
              1e-13);
  for (const Fields &f : {space_fields, time_fields})
    checks.less("forcing: analytic vs finite-difference derivatives (" + f.name
                  + " fields), relative",
                finite_difference_check(f),
                1e-5);

  // (a) Convergence in space, trigonometric fields, omega = 2, end time
  // 0.25 (50 steps, T from 1 to 1.12) and dt = 5e-3. The time error must
  // be far below the finest spatial error (4.3e-6 for p = 2); the bubble
  // fields, which have no spatial error, measure it at these settings
  // (4.2e-9; 1.7e-10 at dt = 1e-3). dt = 1e-3 changed the finest errors
  // of w by 7.7e-4 (p = 2) and 7.3e-3 (p = 1) of themselves and no order
  // by more than 0.06, in 3.8 times the time. The coarsest meshes are
  // pre-asymptotic for p = 1 (order 1.66 from 4 to 8 cells) and are not used.
  // An end time of 0.5 gave the same orders to within 0.1 in twice the time;
  // 0.1 left the coarsest Q2 pair pre-asymptotic (order 3.56).
  {
    const double end_time = 0.25, dt = 5e-3;
    const double time_error =
      run_manufactured(2, 4, bubble_fields(slow), dt, end_time).w;
    std::cout << "(a) time error at these settings (bubble fields, p = 2): "
              << time_error << std::endl;
    checks.less("(a) time error (bubble fields)", time_error, 1e-7);
    struct Series
    {
      unsigned int              degree;
      std::vector<unsigned int> cells;
      std::string               shear_treatment;
      std::string               element = "lagrange";
    };
    // MITC replaces the shear strain by an interpolant: a consistent but
    // non-conforming change, which must keep the optimal order. The
    // serendipity element holds the complete quadratics, so it must reach
    // order 3 like Q2, with full and with reduced shear integration (32
    // cells, left out for time, gave 3.05 for both, doc/model.md).
    for (const Series &s : {Series{1, {8, 16, 32, 64}, "full"},
                            Series{2, {4, 8, 16, 32}, "full"},
                            Series{1, {8, 16, 32, 64}, "mitc"},
                            Series{2, {4, 8, 16, 32}, "mitc"},
                            Series{2, {4, 8, 16}, "full", "serendipity"},
                            Series{2, {4, 8, 16}, "reduced", "serendipity"}})
      {
        std::cout << "(a) p = " << s.degree << ", " << s.element << ", "
                  << s.shear_treatment << " shear, " << space_fields.name
                  << " fields, omega = " << slow.omega << ", dt = " << dt
                  << ", end time " << end_time << std::endl;
        liftoff_tests::OrderTable table;
        for (const unsigned int cells : s.cells)
          {
            table.add_value("cells", cells);
            add_errors(table,
                       run_manufactured(s.degree,
                                        cells,
                                        space_fields,
                                        dt,
                                        end_time,
                                        s.shear_treatment,
                                        s.element));
          }
        const std::vector<double> orders = write_orders(table, "cells");
        for (unsigned int k = 1; k < s.cells.size(); ++k)
          checks.within("(a) p = " + std::to_string(s.degree) + ", " + s.element
                          + ", " + s.shear_treatment + ", "
                          + std::to_string(s.cells[k - 1]) + " -> "
                          + std::to_string(s.cells[k])
                          + " cells: order of the L2 error of w",
                        orders[k - 1],
                        s.degree + 0.8,
                        s.degree + 1.5);
      }
  }

  // (b) Convergence in time, bubble fields (exact in Q2: the spatial error
  // vanishes on any mesh, so what is measured is the time error alone),
  // p = 2 on 8 x 8 cells, omega = 10, end time 1, dt from 0.01 down to
  // 0.00125 (omega dt <= 0.1, in the asymptotic range).
  {
    const double       end_time = 1.0;
    const unsigned int degree = 2, cells = 8;
    std::cout << "(b) p = " << degree << ", " << cells << " cells, "
              << time_fields.name << " fields, omega = " << fast.omega
              << ", end time " << end_time << std::endl;
    liftoff_tests::OrderTable table;
    for (unsigned int k = 0; k < 4; ++k)
      {
        const double dt = 0.01 / std::pow(2.0, k);
        table.add_value("dt", dt);
        add_errors(table,
                   run_manufactured(degree, cells, time_fields, dt, end_time));
      }
    table.set_precision("dt", 5);
    const std::vector<double> orders = write_orders(table, "");
    for (unsigned int k = 1; k <= orders.size(); ++k)
      checks.within("(b) dt halved (" + std::to_string(k)
                      + "): order of the L2 error of w",
                    orders[k - 1],
                    1.8,
                    2.3);
  }

  std::cout << "total run time "
            << std::chrono::duration<double>(std::chrono::steady_clock::now()
                                             - total_start)
                 .count()
            << " s" << std::endl;
  return checks.exit_code();
}
