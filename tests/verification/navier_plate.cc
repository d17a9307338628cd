// Test 2: the hard simply supported square Mindlin plate under uniform
// pressure against Navier's series (navier_plate.h derives the reference).
//
// Runs: p = 1, 2, 3 on full and quarter models (the quarter model must
// reproduce the full model on the same mesh to round-off: symmetry planes
// and load shares), Delta = 0.1 with full shear integration. Thin plates
// and the shear treatments are the test thin_plates.

#include <deal.II/base/mpi.h>

#include "navier_plate.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace navier;


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
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
      liftoff_tests::OrderTable table;
      std::vector<double>       w_errors, psi_errors;
      for (const unsigned int n : s.cells)
        {
          const Result full    = run_navier(s.degree, n, false, delta, "full");
          const Result quarter = run_navier(s.degree, n, true, delta, "full");
          w_errors.push_back(std::abs(full.w_centre - ref.centre_deflection)
                             / ref.centre_deflection);
          psi_errors.push_back(std::abs(full.psi_edge - ref.edge_rotation)
                               / std::abs(ref.edge_rotation));
          table.add_value("cells/side", n);
          table.add_value("w(0,0)", full.w_centre);
          table.add_value("rel.error w", w_errors.back());
          table.add_value("rel.error psi_x(1/2,0)", psi_errors.back());

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
        }
      const std::vector<double> w_orders =
        table.orders("rel.error w", "cells/side");
      table.orders("rel.error psi_x(1/2,0)", "cells/side");
      table.set_precision("w(0,0)", 10);
      for (const std::string key : {"rel.error w", "rel.error psi_x(1/2,0)"})
        table.set_scientific(key, true);
      std::cout << "p = " << s.degree << ":" << std::endl;
      table.write_text(std::cout);
      // No refinement whose error is not below the coarser one's.
      const bool monotone =
        std::adjacent_find(w_errors.begin(),
                           w_errors.end(),
                           [](const double coarse, const double fine) {
                             return !(fine < coarse);
                           })
        == w_errors.end();
      const std::string name = "p = " + std::to_string(s.degree);
      checks.less(name + ": centre error falls on every refinement",
                  monotone ? 0.0 : 1.0,
                  0.5);
      checks.less(name + ": finest relative error of w(0,0)",
                  w_errors.back(),
                  s.finest_limit);
      checks.within(name + ": order of the last refinement, w(0,0)",
                    w_orders.back(),
                    s.min_order,
                    2.0 * s.degree + 0.3);
      checks.less(name + ": finest relative error of psi_x(1/2,0)",
                  psi_errors.back(),
                  10 * s.finest_limit);
    }

  return checks.exit_code();
}
