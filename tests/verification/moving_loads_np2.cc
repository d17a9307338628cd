// Moving loads on two ranks (issue 33): the same scene on two ranks
// (MPI_COMM_WORLD) and on one (MPI_COMM_SELF of rank 0) must give the same
// history to 1e-10 while a point load, a disc of pressure and a vehicle
// of two rectangle wheels cross the plate, and so the partition boundary,
// on a tensionless bed: the point load's owner, the patch's cut cells and
// the contact status may not depend on the partition. The point load
// passes over a cell vertex every fifth step (y = 0, x on a cell edge),
// among them vertices on the partition boundary.

#include <deal.II/base/mpi.h>

#include "test_tools.h"

#include <cmath>
#include <string>

int
main(int argc, char **argv)
{
  using liftoff_tests::set;
  liftoff_tests::Checks checks(argc, argv, 2);

  const std::string scene =
    set("Plate/Aspect ratio", 0.6) + set("Foundation/Stiffness", 2000)
    + set("Discretization/Cells along x", 10)
    + set("Discretization/Cells along y", 6)
    + set("Discretization/Polynomial degree", 2)
    + set("Time integration/Time step", 0.005)
    + set("Time integration/End time", 0.2)
    + set("Loads/Point load 1/Magnitude", 1)
    + set("Loads/Point load 1/Path", "-0.5 + 4*tau; 0")
    + set("Loads/Patch load 1/Magnitude", 30)
    + set("Loads/Patch load 1/Shape", "disc")
    + set("Loads/Patch load 1/Size", 0.09)
    + set("Loads/Patch load 1/Path", "0.31; 0.25 - 2.5*tau")
    + set("Loads/Vehicle 1/Magnitude", 2)
    + set("Loads/Vehicle 1/Path", "0.6 - 5*tau; -0.1")
    + set("Loads/Vehicle 1/Wheels", "0, 0.07, 0.5; 0, -0.07, 0.5")
    + set("Loads/Vehicle 1/Wheel shape", "rectangle")
    + set("Loads/Vehicle 1/Wheel size", "0.05, 0.03")
    + set("Output/Probe points", "-0.2, 0; 0, 0; 0.2, -0.1; 0.31, 0.1");

  const auto parallel = liftoff_tests::run_scene(scene);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      const auto serial =
        liftoff_tests::run_scene(scene, nullptr, MPI_COMM_SELF);
      double contact = 0, tracks = 0;
      for (unsigned int n = 0; n < serial->history().size(); ++n)
        {
          const auto &a = serial->history()[n], &b = parallel->history()[n];
          contact = std::max(contact,
                             std::abs(a.contact_fraction - b.contact_fraction));
          for (unsigned int k = 0; k < a.moving_loads.size(); ++k)
            tracks =
              std::max(tracks, std::abs(a.moving_loads[k] - b.moving_loads[k]));
        }
      checks.less("1 vs 2 ranks: probe histories (relative)",
                  liftoff_tests::history_difference(*serial, *parallel),
                  1e-10);
      checks.less("1 vs 2 ranks: contact fraction", contact, 1e-10);
      checks.less("1 vs 2 ranks: moving loads' columns", tracks, 1e-14);
      // The contact must change during the run, or the scene tests little.
      double lowest = 1;
      for (const auto &row : serial->history())
        if (row.tau > 0)
          lowest = std::min(lowest, row.contact_fraction);
      checks.less("the plate lifts off (lowest contact fraction)", lowest, 0.9);
    }
  const int code = checks.exit_code();
  return dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
}
