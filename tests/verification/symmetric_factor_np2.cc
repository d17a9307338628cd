// MUMPS's Cholesky factor (the default on several ranks) and MUMPS's LU
// (Trilinos Amesos) are interchangeable. On two ranks: the histories of the
// plate of the symmetry tests (many set changes per step) with the Cholesky
// factor, with the LU and with KLU's LU factorised afresh at every change
// must agree to 1e-10. On two ranks and, on each rank alone, on one: one
// solve with the effective matrix of a partly clamped plate (constrained
// rows included) must give the LU's solution to round-off, with a residual
// of round-off, the independent check.

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/section_timer.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_matrices.h>
#include <liftoff/solver/linear_solver.h>

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>
#include <sstream>

using namespace dealii;

namespace
{
  struct OneSolve
  {
    std::string cholesky_name, lu_name;
    /// |x_Cholesky - x_LU| / |x_LU| and |A x_Cholesky - b| / |b|.
    double difference, residual;
  };

  /// Factorise K + c M + K_f of a plate with a clamped and a simply
  /// supported edge (c of a time step of 5e-3) on the ranks of `comm`, once
  /// with MUMPS's Cholesky factor and once with its LU, and solve for one
  /// right-hand side.
  OneSolve
  one_solve(const MPI_Comm comm)
  {
    ParameterHandler prm;
    for (const auto declare :
         {&liftoff::MindlinPlate::declare_parameters,
          &liftoff::Discretization::declare_parameters,
          &liftoff::TensionlessWinklerFoundation::declare_parameters,
          &liftoff::LinearSolver::declare_parameters})
      declare(prm);
    using liftoff_tests::set;
    std::istringstream scene(
      set("Discretization/Symmetry", "full")
      + set("Discretization/Cells along x", 10)
      + set("Discretization/Cells along y", 12)
      + set("Discretization/Polynomial degree", 2)
      + set("Boundary conditions/Right", "clamped")
      + set("Boundary conditions/Top", "hard simply supported")
      + set("Foundation/Stiffness", 37));
    prm.parse_input(scene, "test scene");
    liftoff::MindlinPlate plate;
    plate.parse_parameters(prm);
    liftoff::Discretization discretization(comm);
    discretization.parse_parameters(prm, plate);
    discretization.setup();
    liftoff::PlateMatrices matrices;
    matrices.assemble(discretization, plate);
    liftoff::TensionlessWinklerFoundation foundation;
    foundation.parse_parameters(prm);
    foundation.setup(discretization);

    liftoff::LA::MPI::SparseMatrix A;
    discretization.reinit_matrix(A);
    A.copy_from(matrices.stiffness);
    A.add(1 / (0.25 * 5e-3 * 5e-3), matrices.mass);
    foundation.add_to_matrix({}, A); // all points in contact

    liftoff::LA::MPI::Vector b, x_cholesky, x_lu;
    discretization.reinit_vector(b);
    for (const auto i : b.locally_owned_elements())
      b(i) = std::sin(1.0 + i);
    b.compress(VectorOperation::insert);

    OneSolve result;
    for (const bool cholesky : {true, false})
      {
        std::istringstream package(set("Linear solver/Direct solver package",
                                       cholesky ? "mumps" : "mumps lu"));
        prm.parse_input(package, "package");
        liftoff::SectionTimer timer;
        liftoff::LinearSolver solver(timer);
        solver.parse_parameters(prm);
        solver.prepare(A, discretization);
        liftoff::LA::MPI::Vector &x = cholesky ? x_cholesky : x_lu;
        discretization.reinit_vector(x);
        solver.solve(x, b);
        (cholesky ? result.cholesky_name : result.lu_name) =
          solver.factor_name();
      }
    liftoff::LA::MPI::Vector r(b);
    A.vmult(r, x_cholesky);
    r -= b;
    result.residual = r.l2_norm() / b.l2_norm();
    x_cholesky -= x_lu;
    result.difference = x_cholesky.l2_norm() / x_lu.l2_norm();
    return result;
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv, 2);

  for (const auto &[ranks, comm] : {std::make_pair("2 ranks", MPI_COMM_WORLD),
                                    std::make_pair("1 rank", MPI_COMM_SELF)})
    {
      const OneSolve    solve = one_solve(comm);
      const std::string what  = std::string("one solve on ") + ranks + ": ";
      checks.within(what + "MUMPS's Cholesky factor is the one used",
                    solve.cholesky_name == "MUMPS Cholesky",
                    1,
                    1);
      checks.within(what + "MUMPS's LU is the one used",
                    solve.lu_name == "MUMPS LU",
                    1,
                    1);
      checks.less(what + "Cholesky vs LU solution (relative)",
                  solve.difference,
                  1e-12);
      checks.less(what + "Cholesky's residual (relative)",
                  solve.residual,
                  1e-12);
    }

  const std::string scene  = liftoff_tests::symmetric_scene("quarter", 5, 4);
  const auto        solver = [&](const std::string &settings) {
    return liftoff_tests::run_scene(scene + "subsection Linear solver\n"
                                    + settings + "end\n");
  };
  const auto standard = solver("");
  const auto lu       = solver(" set Direct solver package = mumps lu\n");
  const auto fresh    = solver(" set Direct solver package = klu\n"
                               " set Refactorisation threshold = 0\n");
  checks.within("plate on 2 ranks: the default is MUMPS's Cholesky factor",
                standard->linear_solver().factor_name() == "MUMPS Cholesky",
                1,
                1);
  checks.less("plate on 2 ranks: MUMPS Cholesky vs MUMPS LU: histories",
              liftoff_tests::history_difference(*standard, *lu),
              1e-10);
  checks.less("plate on 2 ranks: MUMPS Cholesky vs fresh KLU factors: "
              "histories",
              liftoff_tests::history_difference(*standard, *fresh),
              1e-10);
  return checks.exit_code();
}
