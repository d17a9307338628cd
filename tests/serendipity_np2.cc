// The eight-node serendipity element on two ranks (MPI_COMM_WORLD) and on
// one (MPI_COMM_SELF of rank 0): the scene of mpi_consistency_np2 (every
// kind of load, supported edges, lift-off) with Element = serendipity and
// reduced shear integration must give the same history to 1e-10, so the
// element's vertex and line degrees of freedom are shared correctly across
// the partition.

#include <deal.II/base/mpi.h>

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  liftoff_tests::Checks                    checks;
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  AssertThrow(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 2,
              dealii::ExcMessage("Run this test on two ranks."));

  const std::string scene = liftoff_tests::symmetric_scene("full", 10, 8)
                            + "subsection Discretization\n"
                              "  set Element = serendipity\n"
                              "  set Shear integration = reduced\n"
                              "end\n";
  const auto parallel = liftoff_tests::run_scene(scene);
  if (rank == 0)
    {
      const auto serial =
        liftoff_tests::run_scene(scene, nullptr, MPI_COMM_SELF);
      // 10 x 8 cells: 11 x 9 vertices and 10 x 9 + 8 x 11 edges, three
      // fields on each node and none inside the cells.
      checks.less("S2: unknowns vs 3 (vertices + edges) = 831",
                  std::abs(
                    double(parallel->get_discretization().dof_handler.n_dofs())
                    - 831.0),
                  0.5);
      checks.less(
        "S2, 1 vs 2 ranks: unknowns",
        std::abs(double(serial->get_discretization().dof_handler.n_dofs())
                 - double(parallel->get_discretization().dof_handler.n_dofs())),
        0.5);
      double contact_difference = 0;
      for (unsigned int n = 0; n < serial->history().size(); ++n)
        contact_difference =
          std::max(contact_difference,
                   std::abs(serial->history()[n].contact_fraction
                            - parallel->history()[n].contact_fraction));
      checks.less("S2, 1 vs 2 ranks: probe histories (relative)",
                  liftoff_tests::history_difference(*serial, *parallel),
                  1e-10);
      checks.less("S2, 1 vs 2 ranks: contact fraction",
                  contact_difference,
                  1e-10);
      checks.less("S2, 1 vs 2 ranks: energies and work (relative)",
                  liftoff_tests::energy_difference(*serial, *parallel),
                  1e-10);
    }
  const int code = checks.exit_code();
  return dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
}
