// Test 2: the hard simply supported square Mindlin plate under uniform
// pressure against Navier's double series.
//
// Reference. With D = 1 and S = 6 chi (1 - nu) / Delta^2 the equations are
//   -S div(grad w - psi) = q,   L psi + S (grad w - psi) = 0,
//   L psi = ((1 - nu)/2) Lap psi + ((1 + nu)/2) grad div psi.
// The divergence of the second equation with the first gives
// Lap div psi = q and Lap w = div psi - q / S, so Lap Lap w = q - Lap q / S.
// Each Navier mode sin(m pi X) sin(n pi Y) (X = x + 1/2, Y = y + 1/2)
// satisfies the hard support (w = 0, tangential rotation 0, normal moment 0)
// exactly, with
//   w_mn = q_mn / alpha^4 (1 + alpha^2 / S),  alpha^2 = (m pi)^2 + (n pi)^2,
//   psi = grad w_K,  w_K = sum q_mn / alpha^4 sin sin (the Kirchhoff plate),
// q_mn = 16 q / (pi^2 m n) for odd m, n. So w = w_K + w_M / S, w_M the
// membrane deflection (-Lap w_M = q). The double series converges far too
// slowly at the 1e-10 level (its shear part only like 1/N^3), so the sum
// over n is done in closed form (Levy): for a = m pi, the functions
//   g(Y) = sum_n 4/(n pi) sin(n pi Y) / (a^2 + (n pi)^2),
//   h(Y) = sum_n 4/(n pi) sin(n pi Y) / (a^2 + (n pi)^2)^2
// solve -g'' + a^2 g = 1 and -h'' + a^2 h = g with zero end values; at
// Y = 1/2
//   g = (1 - 1/cosh(a/2)) / a^2,
//   h = 1/a^4 - (1/a^4 + tanh(a/2) / (4 a^3)) / cosh(a/2).
// The remaining single series in m is alternating (centre) or decays like
// 1/m^4 (edge rotation) and is summed to below 1e-13. The closed form is
// itself checked against the brute force double series.
//
// Runs: p = 1, 2, 3 on full and quarter models (the quarter model must
// reproduce the full model on the same mesh to round-off: symmetry planes
// and load shares), Delta = 0.1 with full shear integration, and a thin
// plate (Delta = 0.01) where reduced integration must avoid the locking of
// full integration.

#include <deal.II/base/mpi.h>

#include <liftoff/point_functional.h>

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

  constexpr double poisson_ratio    = 0.3; // not the default: must reach S
  constexpr double shear_correction = 5.0 / 6.0;

  double
  shear_stiffness(const double thickness_ratio)
  {
    return 6.0 * shear_correction * (1.0 - poisson_ratio)
           / (thickness_ratio * thickness_ratio);
  }

  // Levy closed forms of the sums over n at Y = 1/2 (see the top).
  double
  levy_g(const double a)
  {
    return (1.0 - 1.0 / std::cosh(a / 2)) / (a * a);
  }

  double
  levy_h(const double a)
  {
    const double a4 = a * a * a * a;
    return 1.0 / a4
           - (1.0 / a4 + std::tanh(a / 2) / (4 * a * a * a)) / std::cosh(a / 2);
  }

  struct Reference
  {
    double centre_deflection;  // w(0, 0)
    double edge_rotation;      // psi_x(1/2, 0)
    double last_term_relative; // size of the last term kept, relative
  };

  Reference
  navier_reference(const double S, const double q = 1.0)
  {
    Reference    r{0, 0, 0};
    double       last = 0;
    const double pi   = M_PI;
    for (unsigned int m = 1; m <= 40001; m += 2)
      {
        const double a    = m * pi;
        const double sign = ((m - 1) / 2) % 2 == 0 ? 1.0 : -1.0;
        // w(centre) = sum_m 4 q/(m pi) sin(m pi/2) [h_m + g_m / S]
        last = 4 * q / (m * pi) * sign * (levy_h(a) + levy_g(a) / S);
        r.centre_deflection += last;
        // psi_x(X = 1, Y = 1/2) = sum_m 4 q cos(m pi) h_m
        r.edge_rotation += -4 * q * levy_h(a);
      }
    r.last_term_relative = std::abs(last / r.centre_deflection);
    return r;
  }

  // The series exactly as written in the brief, truncated at m, n <= N.
  double
  double_series_centre(const double S, const unsigned int N, const double q)
  {
    const double pi  = M_PI;
    double       sum = 0;
    for (unsigned int m = 1; m <= N; m += 2)
      for (unsigned int n = 1; n <= N; n += 2)
        {
          const double alpha2 = pi * pi * (double(m) * m + double(n) * n);
          const double q_mn   = 16 * q / (pi * pi * m * n);
          const double sign =
            (((m - 1) / 2 + (n - 1) / 2) % 2 == 0) ? 1.0 : -1.0;
          sum += sign * q_mn / (alpha2 * alpha2) * (1 + alpha2 / S);
        }
    return sum;
  }

  struct Result
  {
    double w_centre;
    double psi_edge;
  };


  Result
  run_navier(const unsigned int degree,
             const unsigned int cells_full, // cells per side on the full plate
             const bool         quarter,
             const double       thickness_ratio,
             const std::string &shear_integration)
  {
    std::ostringstream scene;
    scene << std::setprecision(17) << "subsection Analysis\n"
          << "  set Type = static\n"
          << "end\n"
          << liftoff_tests::square_plate(thickness_ratio,
                                         poisson_ratio,
                                         shear_correction)
          << "subsection Foundation\n"
          << "  set Model = none\n"
          << "end\n"
          << liftoff_tests::all_edges("hard simply supported");
    const unsigned int cells = quarter ? cells_full / 2 : cells_full;
    scene << "subsection Discretization\n"
          << "  set Symmetry = " << (quarter ? "quarter" : "full") << "\n"
          << "  set Cells along x = " << cells << "\n"
          << "  set Cells along y = " << cells << "\n"
          << "  set Polynomial degree = " << degree << "\n"
          << "  set Shear integration = " << shear_integration << "\n"
          << "end\n"
          << "subsection Loads\n"
          << "  subsection Pressure 1\n"
          << "    set Magnitude = 1\n"
          << "    set Region = whole plate\n"
          << "  end\n"
          << "end\n";
    {
      const auto sim = liftoff_tests::run_scene(scene.str());
      // psi_x at the midpoint of the right edge, through the library's
      // own point functional (component 1).
      const liftoff::PointFunctional rotation(sim->get_discretization(),
                                              Point<2>(0.5, 0.0),
                                              1);
      const double                   psi =
        Utilities::MPI::sum(rotation.local_value(sim->solution()),
                            MPI_COMM_WORLD);
      return Result{sim->deflection_at(Point<2>(0, 0)), psi};
    }
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  liftoff_tests::Checks                    checks;
  std::cout << std::scientific << std::setprecision(4);

  // --- The reference itself -------------------------------------------
  const double    delta = 0.1;
  const double    S     = shear_stiffness(delta);
  const Reference ref   = navier_reference(S);
  std::cout << "Navier reference (Delta = " << delta << ", S = " << S
            << "): w(0,0) = " << std::setprecision(12) << ref.centre_deflection
            << ", psi_x(1/2,0) = " << ref.edge_rotation << std::setprecision(4)
            << std::endl;
  // The series has converged: the last term kept is negligible.
  checks.less("reference: last series term / sum",
              ref.last_term_relative,
              1e-12);
  // The closed form equals the brief's double series (truncated at N, whose
  // own error is O(log N / N^3) relative: ~1e-9 at N = 2001).
  const double brute = double_series_centre(S, 2001, 1.0);
  checks.less("reference: Levy form vs double series, relative",
              std::abs(brute - ref.centre_deflection) / ref.centre_deflection,
              1e-7);
  // Classical limits: the square Kirchhoff plate has the textbook centre
  // deflection 0.00406235 q L^4 / D (Timoshenko & Woinowsky-Krieger), and
  // psi = grad w_K does not depend on S.
  const Reference kirchhoff = navier_reference(1e300);
  checks.less("reference: Kirchhoff limit vs 0.00406235",
              std::abs(kirchhoff.centre_deflection - 0.00406235) / 0.00406235,
              2e-6);
  checks.less("reference: rotation is that of the Kirchhoff plate",
              std::abs(kirchhoff.edge_rotation - ref.edge_rotation)
                / std::abs(ref.edge_rotation),
              1e-14);

  // --- Convergence with h, Delta = 0.1, full shear integration ----------
  // Meshes (cells per side of the full plate) and limits for each degree.
  // The centre is a vertex of every mesh and its deflection superconverges:
  // observed orders are 2, 4 and 6 (h^2p) for p = 1, 2, 3, so the order
  // limits ask for a little less than that and the finest-mesh limits are
  // about twice the errors observed (p = 1: 8.5e-4, p = 2: 1.2e-6,
  // p = 3: 2e-8). p = 1 with full integration converges only like h^2 with
  // a sizeable constant (shear stiffening at Delta = 0.1).
  struct Series
  {
    unsigned int              degree;
    std::vector<unsigned int> cells;
    double                    finest_limit;
    double                    min_order;
  };
  const std::vector<Series> series = {{1, {4, 8, 16, 32, 64, 128}, 1.5e-3, 1.9},
                                      {2, {2, 4, 8, 16, 32}, 3e-6, 3.7},
                                      {3, {2, 4, 8, 16}, 5e-8, 5.5}};

  for (const auto &s : series)
    {
      std::cout << "p = " << s.degree << ": cells/side  w(0,0)  rel.error  "
                << "order  |  psi_x(1/2,0) rel.error  order" << std::endl;
      double previous_w = 0, previous_psi = 0;
      bool   monotone = true;
      double last_w = 0, last_psi = 0, last_order = 0;
      for (unsigned int k = 0; k < s.cells.size(); ++k)
        {
          const unsigned int n = s.cells[k];
          const Result full    = run_navier(s.degree, n, false, delta, "full");
          const Result quarter = run_navier(s.degree, n, true, delta, "full");
          const double error_w = std::abs(full.w_centre - ref.centre_deflection)
                                 / ref.centre_deflection;
          const double error_psi = std::abs(full.psi_edge - ref.edge_rotation)
                                   / std::abs(ref.edge_rotation);
          std::cout << "        " << std::setw(4) << n << "  "
                    << std::setprecision(10) << full.w_centre
                    << std::setprecision(4) << "  " << error_w;
          if (k > 0)
            {
              last_order = liftoff_tests::observed_order(previous_w, error_w);
              std::cout << "  " << std::fixed << std::setprecision(2)
                        << last_order << std::scientific
                        << std::setprecision(4);
              monotone = monotone && (error_w < previous_w);
            }
          std::cout << "  |  " << error_psi;
          if (k > 0)
            std::cout << "  " << std::fixed << std::setprecision(2)
                      << liftoff_tests::observed_order(previous_psi, error_psi)
                      << std::scientific << std::setprecision(4);
          std::cout << std::endl;

          // A quarter model with the same mesh size is the same discrete
          // problem restricted by symmetry: the results agree to round-off.
          checks.less("p = " + std::to_string(s.degree) + ", "
                        + std::to_string(n)
                        + " cells: |w quarter - w full| / w",
                      std::abs(quarter.w_centre - full.w_centre)
                        / ref.centre_deflection,
                      1e-9);
          checks.less("p = " + std::to_string(s.degree) + ", "
                        + std::to_string(n)
                        + " cells: |psi quarter - psi full| / psi",
                      std::abs(quarter.psi_edge - full.psi_edge)
                        / std::abs(ref.edge_rotation),
                      1e-9);
          previous_w   = error_w;
          previous_psi = error_psi;
          last_w       = error_w;
          last_psi     = error_psi;
        }
      const std::string name = "p = " + std::to_string(s.degree);
      checks.less(name + ": centre error falls on every refinement",
                  monotone ? 0.0 : 1.0,
                  0.5);
      checks.less(name + ": finest relative error of w(0,0)",
                  last_w,
                  s.finest_limit);
      checks.within(name + ": order of the last refinement, w(0,0)",
                    last_order,
                    s.min_order,
                    2.0 * s.degree + 0.3);
      checks.less(name + ": finest relative error of psi_x(1/2,0)",
                  last_psi,
                  10 * s.finest_limit);
    }

  // --- Thin plate: locking and reduced integration ----------------------
  // Delta = 0.01 (S ~ 4e4): full integration of the shear term locks for
  // low degrees; reduced (p^2 points) must give the Navier value.
  {
    const double    thin     = 0.01;
    const Reference thin_ref = navier_reference(shear_stiffness(thin));
    std::cout << "thin plate (Delta = " << thin
              << "): reference w(0,0) = " << std::setprecision(10)
              << thin_ref.centre_deflection << std::setprecision(4)
              << std::endl;
    struct ThinCase
    {
      unsigned int degree, cells;
      double       reduced_limit;
    };
    for (const ThinCase &c :
         {ThinCase{1, 32, 1e-3}, ThinCase{2, 16, 2e-5}, ThinCase{3, 8, 1e-6}})
      {
        const Result full = run_navier(c.degree, c.cells, true, thin, "full");
        const Result reduced =
          run_navier(c.degree, c.cells, true, thin, "reduced");
        const double error_full =
          std::abs(full.w_centre - thin_ref.centre_deflection)
          / thin_ref.centre_deflection;
        const double error_reduced =
          std::abs(reduced.w_centre - thin_ref.centre_deflection)
          / thin_ref.centre_deflection;
        std::cout << "p = " << c.degree << ", " << c.cells
                  << " cells/side: rel. error full " << error_full
                  << ", reduced " << error_reduced << std::endl;
        checks.less("thin plate, p = " + std::to_string(c.degree)
                      + ", reduced integration: relative error of w(0,0)",
                    error_reduced,
                    c.reduced_limit);
      }
  }

  return checks.exit_code();
}
