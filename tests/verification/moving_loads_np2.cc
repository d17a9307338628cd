// Moving loads on two ranks (issue 33): the same scene on two ranks
// (MPI_COMM_WORLD) and on one (MPI_COMM_SELF of rank 0) must give the same
// history to 1e-10 while a point load, a disc of pressure and a vehicle
// of two rectangle wheels cross the plate, and so the partition boundary,
// on a tensionless bed: the point load's owner, the patch's cut cells, the
// riding probes and the contact status may not depend on the partition.
// The point load passes over a cell vertex every fifth step (y = 0, x on a
// cell edge), among them vertices on the partition boundary. The test
// checks that the point load, the disc and the vehicle each stand in cells
// of one rank only at some steps and of the other rank only at others, so
// that they do cross from one rank's cells to the other's.

#include <deal.II/base/mpi.h>

#include <liftoff/fem/discretization.h>

#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  /// The number of steps at which the moving load `load` (its column
  /// triple in the history) stands in a cell of this rank and of no other.
  unsigned int
  steps_held_alone(const liftoff::Simulator &run, const std::string &load)
  {
    const auto  &triangulation = run.get_discretization().triangulation;
    unsigned int alone         = 0;
    for (const auto &row : run.history())
      {
        const dealii::Point<2> p(row[load + "_x"], row[load + "_y"]);
        unsigned int           here = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && cell->point_inside(p))
            here = 1;
        const unsigned int ranks =
          dealii::Utilities::MPI::sum(here, MPI_COMM_WORLD);
        alone += (here == 1 && ranks == 1);
      }
    return alone;
  }

  /// Largest difference of the riding probes' columns of two runs,
  /// relative to the largest value of each column.
  double
  riding_difference(const liftoff::Simulator &a, const liftoff::Simulator &b)
  {
    const auto &ha = a.history(), &hb = b.history();
    double      worst = 0;
    for (const std::string column : {"w@point_load_1",
                                     "w@patch_load_1",
                                     "M_xx@patch_load_1",
                                     "Q_y@patch_load_1",
                                     "M_yy@vehicle_1"})
      {
        double difference = 0, scale = 0;
        for (unsigned int n = 0; n < ha.size(); ++n)
          {
            difference =
              std::max(difference, std::abs(ha[n][column] - hb[n][column]));
            scale = std::max(scale, std::abs(ha[n][column]));
          }
        worst = std::max(worst, difference / scale);
      }
    return worst;
  }
} // namespace

LIFTOFF_TEST_MAIN(argc, argv)
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
    + set("Loads/Patch load 1/Path", "0.31 - 3*tau; 0.25 - 2.5*tau")
    + set("Loads/Vehicle 1/Magnitude", 2)
    + set("Loads/Vehicle 1/Path", "0.6 - 5*tau; -0.1")
    + set("Loads/Vehicle 1/Wheels", "0, 0.07, 0.5; 0, -0.07, 0.5")
    + set("Loads/Vehicle 1/Wheel shape", "rectangle")
    + set("Loads/Vehicle 1/Wheel size", "0.05, 0.03")
    + set("Output/Probe points", "-0.2, 0; 0, 0; 0.2, -0.1; 0.31, 0.1")
    + set("Output/Riding probes",
          "w@point_load_1, w@patch_load_1, M_xx@patch_load_1, "
          "Q_y@patch_load_1, M_yy@vehicle_1");

  const auto parallel = liftoff_tests::run_scene(scene);
  // Collective: each rank counts the steps at which it alone holds a load;
  // the fewer of the two counts must be several steps.
  for (const auto &[load, name] :
       {std::pair<std::string, std::string>{"point_load_1", "point load"},
        {"patch_load_1", "disc (patch load 1)"},
        {"vehicle_1", "vehicle's path point"}})
    checks.within("steps with the " + name
                    + " in one rank's cells only (the fewer of the 2 ranks)",
                  dealii::Utilities::MPI::min(steps_held_alone(*parallel, load),
                                              MPI_COMM_WORLD),
                  3,
                  1e9);

  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      const auto serial =
        liftoff_tests::run_scene(scene, nullptr, MPI_COMM_SELF);
      double contact = 0, tracks = 0;
      for (unsigned int n = 0; n < serial->history().size(); ++n)
        {
          const auto &a = serial->history()[n], &b = parallel->history()[n];
          contact =
            std::max(contact,
                     std::abs(a["contact_fraction"] - b["contact_fraction"]));
          for (const std::string load :
               {"point_load_1", "patch_load_1", "vehicle_1"})
            for (const std::string column : {"_x", "_y", "_on"})
              tracks =
                std::max(tracks, std::abs(a[load + column] - b[load + column]));
        }
      checks.less("1 vs 2 ranks: probe histories (relative)",
                  liftoff_tests::history_difference(*serial, *parallel),
                  1e-10);
      checks.less("1 vs 2 ranks: contact fraction", contact, 1e-10);
      checks.less("1 vs 2 ranks: moving loads' columns", tracks, 1e-14);
      checks.less("1 vs 2 ranks: riding probes (relative to each column)",
                  riding_difference(*serial, *parallel),
                  1e-10);
      // The contact must change during the run, or the scene tests little.
      double lowest = 1;
      for (const auto &row : serial->history())
        if (row["tau"] > 0)
          lowest = std::min(lowest, row["contact_fraction"]);
      checks.less("the plate lifts off (lowest contact fraction)", lowest, 0.9);
    }
  const int code = checks.exit_code();
  return dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
}
