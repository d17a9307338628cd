// The same scene on two ranks (MPI_COMM_WORLD) and on one (MPI_COMM_SELF of
// rank 0) must give the same history to 1e-10: the distributed mesh, the
// ownership of point loads and probes on partition boundaries, the contact
// status and the energies may not depend on the partition.

#include <deal.II/base/mpi.h>

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  liftoff_tests::Checks checks(argc, argv, 2);
  const unsigned int    rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);

  const std::string scene    = liftoff_tests::symmetric_scene("full", 10, 8);
  const auto        parallel = liftoff_tests::run_scene(scene);
  if (rank == 0)
    {
      const auto serial =
        liftoff_tests::run_scene(scene, nullptr, MPI_COMM_SELF);
      double       contact_difference   = 0;
      unsigned int iteration_mismatches = 0;
      for (unsigned int n = 0; n < serial->history().size(); ++n)
        {
          const auto &a = serial->history()[n], &b = parallel->history()[n];
          contact_difference =
            std::max(contact_difference,
                     std::abs(a.contact_fraction - b.contact_fraction));
          iteration_mismatches += (a.iterations != b.iterations);
        }
      checks.less("1 vs 2 ranks: probe histories (relative)",
                  liftoff_tests::history_difference(*serial, *parallel),
                  1e-10);
      checks.less("1 vs 2 ranks: contact fraction", contact_difference, 1e-10);
      checks.less("1 vs 2 ranks: energies and work (relative to max work)",
                  liftoff_tests::energy_difference(*serial, *parallel),
                  1e-10);
      checks.less("1 vs 2 ranks: steps with a different iteration count",
                  iteration_mismatches,
                  0.5);
    }
  const int code = checks.exit_code();
  return dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
}
