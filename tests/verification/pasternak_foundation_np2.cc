// The foundation with everything issue 13 added (a Pasternak shear layer,
// dashpots, a gap) and the resultant columns, on two ranks (MPI_COMM_WORLD)
// and on one (MPI_COMM_SELF of rank 0): every history column must agree to
// 1e-10, on a uniform mesh and on an adaptive one (hanging nodes, whose
// layer terms are condensed on the rank that owns the cell).

#include <deal.II/base/mpi.h>

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  using liftoff_tests::set;

  void
  compare_1_and_2_ranks(const std::string     &label,
                        const std::string     &scene,
                        liftoff_tests::Checks &checks)
  {
    const auto parallel = liftoff_tests::run_scene(scene);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const auto serial = liftoff_tests::run_scene(scene, nullptr, MPI_COMM_SELF);
    // Each column relative to its largest value in the serial run.
    std::vector<double> difference(7, 0.0), scale(7, 0.0);
    unsigned int        mismatches = 0;
    for (unsigned int n = 0; n < serial->history().size(); ++n)
      {
        const auto &a = serial->history()[n], &b = parallel->history()[n];
        const std::vector<double> x = {a["contact_fraction"],
                                       a["max_uplift"],
                                       a["resultant"],
                                       a["resultant_x"],
                                       a["resultant_y"],
                                       a["contact_area"],
                                       a.energies().supports};
        const std::vector<double> y = {b["contact_fraction"],
                                       b["max_uplift"],
                                       b["resultant"],
                                       b["resultant_x"],
                                       b["resultant_y"],
                                       b["contact_area"],
                                       b.energies().supports};
        for (unsigned int k = 0; k < x.size(); ++k)
          {
            difference[k] = std::max(difference[k], std::abs(x[k] - y[k]));
            scale[k]      = std::max(scale[k], std::abs(x[k]));
          }
        mismatches += (a["active_set_iterations"] != b["active_set_iterations"])
                      || (a["cells"] != b["cells"]) || (a["dofs"] != b["dofs"]);
      }
    const std::vector<std::string> names = {"contact_fraction",
                                            "max_uplift",
                                            "resultant",
                                            "resultant_x",
                                            "resultant_y",
                                            "contact_area",
                                            "foundation energy"};
    // The centre is a length (in L): compared absolutely; the others
    // relative to their size.
    for (unsigned int k = 0; k < names.size(); ++k)
      {
        const bool is_centre =
          (names[k] == "resultant_x") || (names[k] == "resultant_y");
        checks.less(label + ", 1 vs 2 ranks: " + names[k]
                      + (is_centre ? " (absolute)" : " (relative)"),
                    difference[k]
                      / (is_centre ? 1.0 : std::max(scale[k], 1e-300)),
                    1e-10);
      }
    checks.less(label + ", 1 vs 2 ranks: probe histories (relative)",
                liftoff_tests::history_difference(*serial, *parallel),
                1e-10);
    checks.less(label + ", 1 vs 2 ranks: energies and work (relative)",
                liftoff_tests::energy_difference(*serial, *parallel),
                1e-10);
    checks.less(label + ", 1 vs 2 ranks: steps with other iterations or mesh",
                mismatches,
                0.5);
    unsigned int n_partial = 0;
    for (const auto &row : serial->history())
      n_partial +=
        (row["contact_fraction"] > 0.01 && row["contact_fraction"] < 0.99);
    checks.within(label + ": steps with partial contact",
                  n_partial,
                  1,
                  serial->history().size());
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv, 2);

  const std::string scene = liftoff_tests::symmetric_scene("full", 10, 8)
                            + set("Foundation/Shear modulus", 5)
                            + set("Foundation/Damping", 0.5)
                            + set("Foundation/Initial gap", "0.001*(x*x + y*y)")
                            + set("Output/Write foundation resultant", "true");
  // Off-centre, so that the resultant's centre leaves the axes.
  compare_1_and_2_ranks("Pasternak",
                        scene + set("Loads/Point load 8/Magnitude", 0.6)
                          + set("Loads/Point load 8/Position", "0.3, 0.1"),
                        checks);
  // Symmetric on the adaptive mesh: with the off-centre force the
  // adaptive run of branch `adaptive` hangs on two ranks at the fifth
  // refinement (without any of the layer's entries; left to its owner).
  compare_1_and_2_ranks("Pasternak adaptive",
                        scene + set("Mesh refinement/Adaptive", "true")
                          + set("Mesh refinement/Interval", 5)
                          + set("Mesh refinement/Maximum level", 2)
                          + set("Mesh refinement/Initial refinements", 1),
                        checks);
  const int code = checks.exit_code();
  return dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
}
