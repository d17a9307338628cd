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
        const std::vector<double> x = {a.contact_fraction,
                                       a.max_uplift,
                                       a.resultant,
                                       a.resultant_x,
                                       a.resultant_y,
                                       a.contact_area,
                                       a.energies.foundation};
        const std::vector<double> y = {b.contact_fraction,
                                       b.max_uplift,
                                       b.resultant,
                                       b.resultant_x,
                                       b.resultant_y,
                                       b.contact_area,
                                       b.energies.foundation};
        for (unsigned int k = 0; k < x.size(); ++k)
          {
            difference[k] = std::max(difference[k], std::abs(x[k] - y[k]));
            scale[k]      = std::max(scale[k], std::abs(x[k]));
          }
        mismatches += (a.iterations != b.iterations) || (a.n_cells != b.n_cells)
                      || (a.n_dofs != b.n_dofs);
      }
    const std::vector<std::string> names = {"contact_fraction",
                                            "max_uplift",
                                            "resultant",
                                            "resultant_x",
                                            "resultant_y",
                                            "contact_area",
                                            "foundation energy"};
    for (unsigned int k = 0; k < names.size(); ++k)
      checks.less(label + ", 1 vs 2 ranks: " + names[k] + " (relative)",
                  difference[k] / std::max(scale[k], 1e-300),
                  1e-10);
    checks.less(label + ", 1 vs 2 ranks: probe histories (relative)",
                liftoff_tests::history_difference(*serial, *parallel),
                1e-10);
    checks.less(label + ", 1 vs 2 ranks: energies and work (relative)",
                liftoff_tests::energy_difference(*serial, *parallel),
                1e-10);
    checks.less(label + ", 1 vs 2 ranks: steps with other iterations or mesh",
                mismatches,
                0.5);
    checks.within(
      label
        + ": the layer lifts off somewhere (min contact "
          "fraction)",
      [&]() {
        double smallest = 1;
        for (const auto &row : serial->history())
          smallest = std::min(smallest, row.contact_fraction);
        return smallest;
      }(),
      0.01,
      0.99);
  }
} // namespace


int
main(int argc, char **argv)
{
  liftoff_tests::Checks checks(argc, argv, 2);

  const std::string scene = liftoff_tests::symmetric_scene("full", 10, 8)
                            + set("Foundation/Shear modulus", 5)
                            + set("Foundation/Damping", 0.5)
                            + set("Foundation/Initial gap", "0.001*(x*x + y*y)")
                            + set("Output/Write foundation resultant", "true");
  compare_1_and_2_ranks("Pasternak", scene, checks);
  compare_1_and_2_ranks("Pasternak adaptive",
                        scene + set("Mesh refinement/Adaptive", "true")
                          + set("Mesh refinement/Interval", 5)
                          + set("Mesh refinement/Maximum level", 2)
                          + set("Mesh refinement/Initial refinements", 1),
                        checks);
  const int code = checks.exit_code();
  return dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
}
