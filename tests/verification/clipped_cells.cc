// Loads clipped by cells that are not axis-aligned rectangles, on one rank
// (clipped_cells.h says what is checked against what).

#include "clipped_cells.h"

LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  clipped_cells::check_all(checks, MPI_COMM_WORLD);
  return checks.exit_code();
}
