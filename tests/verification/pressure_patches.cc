// Pressure patches at arbitrary positions and sizes: the load vector's force
// and first moments against their exact values, and the scenes run
// statically (pressure_patches.h). pressure_patches_np2 runs the same on two
// ranks.

#include "pressure_patches.h"

LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  pressure_patches::check_load_vectors(checks, MPI_COMM_WORLD);
  pressure_patches::check_static_resultants(checks, MPI_COMM_WORLD);
  return checks.exit_code();
}
