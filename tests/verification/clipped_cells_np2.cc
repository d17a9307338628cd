// clipped_cells on two ranks: each rank clips the loads by its own cells (a
// tyre or a line may straddle the ranks' boundary), and the sums must still
// be the exact force and moments (clipped_cells.h).

#include "clipped_cells.h"

int
main(int argc, char **argv)
{
  liftoff_tests::Checks checks(argc, argv, 2);
  clipped_cells::check_all(checks, MPI_COMM_WORLD);
  return checks.exit_code();
}
