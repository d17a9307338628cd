// Thin plates: the three treatments of the transverse shear term (full,
// reduced, MITC) against independent references.
//
// 1. Locking. The hard simply supported square under uniform pressure on a
//    fixed 16 x 16 mesh, Delta = 1e-1 ... 1e-4, p = 1 and 2, against the
//    Mindlin Navier series (navier_plate.h): MITC must stay within 1 % at
//    every Delta and within 1 % of the Kirchhoff value 0.00406235 once
//    Delta <= 1e-3; full integration must be seen to lock (else this part
//    could not tell the treatments apart).
// 2. Spurious modes. A free plate has exactly three zero-energy modes (w =
//    a + b x + c y, psi = grad w). The eigenvalues of the stiffness matrix
//    of a free 4 x 4 mesh (LAPACK) count them: three for full and MITC,
//    more for reduced integration, whose extra modes are what makes a free
//    plate under a point load deflect many times too much.
//
// The table printed here is the one in doc/thin-plates.md.

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/fem/plate_matrices.h>

#include "navier_plate.h"

#include <algorithm>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;

  const std::vector<std::string> treatments = {"full", "reduced", "mitc"};

  // Eigenvalues of the stiffness of a free square plate, ascending.
  std::vector<double>
  free_plate_eigenvalues(const unsigned int degree,
                         const unsigned int cells,
                         const double       thickness_ratio,
                         const std::string &treatment,
                         const std::string &element = "lagrange")
  {
    ParameterHandler prm;
    liftoff::MindlinPlate::declare_parameters(prm);
    liftoff::Discretization::declare_parameters(prm);
    std::istringstream scene(
      liftoff_tests::square_plate(thickness_ratio, 0.3, 5.0 / 6.0)
      + "subsection Discretization\n"
        "  set Cells along x = "
      + std::to_string(cells) + "\n  set Cells along y = "
      + std::to_string(cells) + "\n  set Polynomial degree = "
      + std::to_string(degree) + "\n  set Shear integration = " + treatment
      + "\n  set Element = " + element + "\nend\n");
    prm.parse_input(scene, "free plate");
    liftoff::MindlinPlate plate;
    plate.parse_parameters(prm);
    liftoff::Discretization discretization(MPI_COMM_WORLD);
    discretization.parse_parameters(prm, plate);
    discretization.setup();
    liftoff::PlateMatrices matrices;
    matrices.assemble(discretization, plate);

    const unsigned int       n = discretization.dof_handler.n_dofs();
    LAPACKFullMatrix<double> stiffness(n, n);
    for (auto entry = matrices.stiffness.begin();
         entry != matrices.stiffness.end();
         ++entry)
      stiffness(entry->row(), entry->column()) = entry->value();
    stiffness.compute_eigenvalues();
    std::vector<double> eigenvalues(n);
    for (unsigned int i = 0; i < n; ++i)
      eigenvalues[i] = stiffness.eigenvalue(i).real();
    std::sort(eigenvalues.begin(), eigenvalues.end());
    return eigenvalues;
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  // --- 1. Locking ------------------------------------------------------
  const unsigned int cells = 16;
  const double kirchhoff   = navier::navier_reference(1e300).centre_deflection;
  std::ostringstream table;
  table << std::scientific << std::setprecision(2);
  for (const unsigned int degree : {1u, 2u})
    for (const double delta : {1e-1, 1e-2, 1e-3, 1e-4})
      {
        const double reference =
          navier::navier_reference(navier::shear_stiffness(delta))
            .centre_deflection;
        std::map<std::string, double> error;
        double                        mitc_deflection = 0;
        for (const auto &treatment : treatments)
          {
            const double w =
              navier::run_navier(degree, cells, false, delta, treatment)
                .w_centre;
            error[treatment] = std::abs(w - reference) / reference;
            if (treatment == "mitc")
              mitc_deflection = w;
          }
        table << "| " << degree << " | " << std::defaultfloat << delta << " | "
              << std::setprecision(8) << reference << std::scientific
              << std::setprecision(2) << " | " << error["full"] << " | "
              << error["reduced"] << " | " << error["mitc"] << " |\n";

        std::ostringstream name;
        name << "p = " << degree << ", Delta = " << delta;
        checks.less(name.str() + ", mitc: error against Navier",
                    error["mitc"],
                    1e-2);
        // Once the shear part of the deflection (~Delta^2) is below the
        // discretisation error, MITC gives the Kirchhoff plate.
        if (delta <= 1e-3)
          checks.less(name.str() + ", mitc: error against Kirchhoff",
                      std::abs(mitc_deflection - kirchhoff) / kirchhoff,
                      1e-2);
        if (degree == 1 && delta <= 1e-3)
          checks.less(name.str() + ": full integration locks (error > 50 %)",
                      0.5,
                      error["full"]);
      }
  std::cout << "\nRelative error of w(0,0) against the Mindlin Navier "
               "series, hard simply supported square, uniform load, "
            << cells << " x " << cells
            << " cells\n\n| p | Delta | Navier w(0,0) | full | reduced | "
               "mitc |\n|---|---|---|---|---|---|\n"
            << table.str() << std::endl;

  // --- 2. Zero-energy modes of a free plate ------------------------------
  std::ostringstream modes;
  for (const unsigned int degree : {1u, 2u})
    {
      std::map<std::string, unsigned int> zero;
      for (const auto &treatment : treatments)
        {
          const auto lambda = free_plate_eigenvalues(degree, 4, 0.1, treatment);
          const double largest =
            *std::max_element(lambda.begin(), lambda.end());
          zero[treatment] =
            std::count_if(lambda.begin(), lambda.end(), [&](const double l) {
              return std::abs(l) < 1e-8 * largest;
            });
          // The gap: the smallest non-zero eigenvalue is far above the
          // threshold, so the count does not hinge on it.
          if (treatment != "reduced")
            checks.less("p = " + std::to_string(degree) + ", " + treatment
                          + ": 4th eigenvalue / largest is well above 1e-8",
                        1e-6,
                        lambda[3] / largest);
        }
      modes << "| " << degree << " | " << zero["full"] << " | "
            << zero["reduced"] << " | " << zero["mitc"] << " |\n";
      const std::string p = "p = " + std::to_string(degree);
      checks.within(p + ", mitc: zero-energy modes", zero["mitc"], 3, 3);
      checks.within(p + ", full: zero-energy modes", zero["full"], 3, 3);
      checks.less(p + ", reduced: has spurious modes (more than 3)",
                  3.5,
                  zero["reduced"]);
    }
  // The eight-node serendipity element (mitc is refused for it).
  {
    std::map<std::string, unsigned int> zero;
    for (const std::string treatment : {"full", "reduced"})
      {
        const auto lambda =
          free_plate_eigenvalues(2, 4, 0.1, treatment, "serendipity");
        const double largest = *std::max_element(lambda.begin(), lambda.end());
        zero[treatment] =
          std::count_if(lambda.begin(), lambda.end(), [&](const double l) {
            return std::abs(l) < 1e-8 * largest;
          });
        checks.within("S2, " + treatment + ": zero-energy modes",
                      zero[treatment],
                      3,
                      3);
        checks.less("S2, " + treatment
                      + ": 4th eigenvalue / largest is well above 1e-8",
                    1e-6,
                    lambda[3] / largest);
      }
    // Even one cell alone has no spurious mode: only the shear term is
    // integrated with 2 x 2 points, and the 3 x 3 bending term holds what
    // 2 x 2 shear points leave free.
    const auto one_cell =
      free_plate_eigenvalues(2, 1, 0.1, "reduced", "serendipity");
    const double largest_one =
      *std::max_element(one_cell.begin(), one_cell.end());
    const auto zero_one =
      std::count_if(one_cell.begin(), one_cell.end(), [&](const double l) {
        return std::abs(l) < 1e-8 * largest_one;
      });
    std::cout << "S2, reduced, a single cell: " << zero_one
              << " zero-energy modes" << std::endl;
    checks.within("S2, reduced, one cell: the 3 rigid modes only",
                  zero_one,
                  3,
                  3);
    modes << "| 2 (S2, serendipity) | " << zero["full"] << " | "
          << zero["reduced"] << " | refused |\n";
  }
  std::cout << "\nEigenvalues below 1e-8 x the largest, free plate, 4 x 4 "
               "cells, Delta = 0.1\n\n| p | full | reduced | mitc |\n"
               "|---|---|---|---|\n"
            << modes.str() << std::endl;
  return checks.exit_code();
}
