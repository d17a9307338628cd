// pressure_patches on two ranks: each rank integrates the patches over its
// own cells (a patch may straddle the ranks' boundary), and the sums must
// still be the exact force and moments (pressure_patches.h).

#include "pressure_patches.h"

int
main(int argc, char **argv)
{
  liftoff_tests::Checks checks(argc, argv, 2);
  pressure_patches::check_load_vectors(checks, MPI_COMM_WORLD);
  pressure_patches::check_static_resultants(checks, MPI_COMM_WORLD);
  return checks.exit_code();
}
