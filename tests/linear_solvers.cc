// The linear solvers are interchangeable: sparse direct KLU, sparse direct
// MUMPS and conjugate gradients with algebraic multigrid must give the same
// history on a scene with lift-off (a second method for each). CG works to
// a relative residual of 1e-12, so the histories agree to about that.

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  liftoff_tests::Checks                    checks;
  const std::string scene = liftoff_tests::symmetric_scene("quarter", 5, 4);

  const auto klu   = liftoff_tests::run_scene(scene);
  const auto mumps = liftoff_tests::run_scene(
    scene
    + "subsection Linear solver\n set Direct solver package = mumps\nend\n");
  const auto cg =
    liftoff_tests::run_scene(scene
                             + "subsection Linear solver\n set Type = cg\n set "
                               "Tolerance = 1e-12\nend\n");

  checks.less("MUMPS vs KLU: probe histories",
              liftoff_tests::history_difference(*mumps, *klu),
              1e-10);
  checks.less("CG + AMG vs KLU: probe histories",
              liftoff_tests::history_difference(*cg, *klu),
              1e-8);
  return checks.exit_code();
}
