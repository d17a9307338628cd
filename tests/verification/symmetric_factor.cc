// The symmetric factors and the LU are interchangeable: CHOLMOD's Cholesky
// factor (the default on one rank, with its own rule for when to factorise
// anew) and MUMPS's Cholesky factor must give the histories of MUMPS's LU,
// and of KLU's LU factorised afresh at every change of the contact set, to
// 1e-10 on scenes with
// lift-off: the plate of the symmetry tests (many set changes per step) and
// the paper's Example 2 beam under its pulsating force (a set that changes
// seldom, where CHOLMOD factorises again instead of iterating CG). So must
// CHOLMOD's factor with trial solves (`Trial tolerance`, the default).

#include "symmetric_scene.h"
#include "test_tools.h"

#include <fstream>
#include <sstream>

namespace
{
  // The first quarter of a period of prm/example-2-beam-pulse.prm, without
  // its output files.
  std::string
  pulse_scene()
  {
    std::ifstream     file(std::string(LIFTOFF_SOURCE_DIR)
                       + "/prm/example-2-beam-pulse.prm");
    std::stringstream text;
    text << file.rdbuf();
    AssertThrow(file, dealii::ExcMessage("Cannot read the pulse scene."));
    return text.str()
           + "subsection Time integration\n set End time = 0.625\nend\n"
             "subsection Output\n set Directory =\n set VTU interval = "
             "0\nend\n";
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  for (const auto &[name, scene] :
       {std::make_pair("plate",
                       liftoff_tests::symmetric_scene("quarter", 5, 4)),
        std::make_pair("pulse", pulse_scene())})
    {
      const auto solver = [&](const std::string &settings) {
        return liftoff_tests::run_scene(scene + "subsection Linear solver\n"
                                        + settings + "end\n");
      };
      // Every solve to `Tolerance`, except in `trials` (the default).
      const std::string full = " set Trial tolerance = 0\n";
      const auto        cholmod =
        solver(full + " set Direct solver package = cholmod\n");
      const auto mumps =
        solver(full + " set Direct solver package = mumps lu\n");
      const auto mumps_cholesky =
        solver(full + " set Direct solver package = mumps\n");
      const auto        fresh  = solver(full
                                + " set Direct solver package = klu\n"
                                          " set Refactorisation threshold = 0\n");
      const auto        trials = solver("");
      const std::string what   = std::string(name) + ": ";
      checks.within(what + "CHOLMOD's Cholesky factor is the one used",
                    cholmod->linear_solver().factor_name()
                      == "CHOLMOD Cholesky",
                    1,
                    1);
      checks.within(what + "MUMPS's LU is the one used",
                    mumps->linear_solver().factor_name() == "MUMPS LU",
                    1,
                    1);
      checks.within(what + "MUMPS's Cholesky factor is the one used",
                    mumps_cholesky->linear_solver().factor_name()
                      == "MUMPS Cholesky",
                    1,
                    1);
      checks.less(what + "CHOLMOD vs MUMPS LU: histories",
                  liftoff_tests::history_difference(*cholmod, *mumps),
                  1e-10);
      checks.less(what + "MUMPS Cholesky vs MUMPS LU: histories",
                  liftoff_tests::history_difference(*mumps_cholesky, *mumps),
                  1e-10);
      checks.less(what + "CHOLMOD vs fresh KLU factors: histories",
                  liftoff_tests::history_difference(*cholmod, *fresh),
                  1e-10);
      // Solves to 1e-6 while the set changes, to 1e-12 once it holds: the
      // same histories, fewer substitutions where the set changes often.
      checks.less(what + "trial solves vs MUMPS LU: histories",
                  liftoff_tests::history_difference(*trials, *mumps),
                  1e-10);
      if (std::string(name) == "plate")
        checks.within(what
                        + "trial solves: substitutions / those of "
                          "CHOLMOD without",
                      double(trials->linear_solver().n_substitutions)
                        / cholmod->linear_solver().n_substitutions,
                      0,
                      0.95);
      // CG takes A p from the change of the springs and starts a solve
      // that continues the last one from its residual, so on the plate,
      // whose steps take several solves, it multiplies by the whole matrix
      // about twice per time step instead of once per iteration and solve
      // (the pulse's steps are mostly one solve of one iteration: two
      // products either way). A wrong shortcut fails its check against the
      // true residual, and CG goes on with whole products.
      for (const auto &[label, run] :
           {std::make_pair("CHOLMOD", &cholmod),
            std::make_pair("trial solves", &trials),
            std::make_pair("MUMPS Cholesky", &mumps_cholesky)})
        {
          const auto &solver = (*run)->linear_solver();
          checks.within(what + label
                          + ": solutions whose true residual missed what "
                            "CG's own said",
                        solver.n_failed_checks,
                        0,
                        0);
          if (std::string(name) == "plate")
            checks.within(what + label
                            + ": products with the whole matrix per CG "
                              "iteration",
                          double(solver.n_products) / solver.n_cg_iterations,
                          0,
                          0.7);
        }
      if (std::string(name) == "pulse")
        checks.within("pulse: CHOLMOD factorised again when CG had paid "
                      "for it (more than one factorisation)",
                      cholmod->n_factorizations(),
                      2,
                      1e9);
    }
  return checks.exit_code();
}
