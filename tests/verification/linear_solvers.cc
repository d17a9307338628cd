// The linear solvers are interchangeable: a fresh sparse direct
// factorisation at every change of the contact set (KLU, threshold 0) is the
// reference; the default (on one rank CHOLMOD's Cholesky factor, factorised
// once, preconditioning CG on the changed matrices), the same with KLU's LU,
// and conjugate gradients with algebraic multigrid must give the same
// history on a scene with lift-off. CG works to a relative residual of 1e-12,
// so the histories agree to about that. The reuse must also be real: one
// factorisation only.

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  const std::string     scene = liftoff_tests::symmetric_scene("quarter", 5, 4);

  const auto solver = [&](const std::string &settings) {
    return liftoff_tests::run_scene(scene + "subsection Linear solver\n"
                                    + settings + "end\n");
  };
  const auto reference = solver(" set Direct solver package = klu\n"
                                " set Refactorisation threshold = 0\n");
  const auto standard  = solver("");
  const auto klu       = solver(" set Direct solver package = klu\n");
  const auto cg        = solver(" set Type = cg\n");

  checks.less("default (CHOLMOD), reused factor vs fresh factorisations: "
              "histories",
              liftoff_tests::history_difference(*standard, *reference),
              1e-10);
  checks.less("KLU, reused factor vs fresh factorisations: histories",
              liftoff_tests::history_difference(*klu, *reference),
              1e-10);
  checks.less("CG + AMG vs fresh factorisations: histories",
              liftoff_tests::history_difference(*cg, *reference),
              1e-8);
  checks.within("factorisations with reuse",
                standard->n_factorizations(),
                1,
                1);
  checks.within("fresh factorisations: one per set change (more than 10)",
                reference->n_factorizations(),
                11,
                1e9);
  return checks.exit_code();
}
