// Quarter, half and full models of a scene that is symmetric about x = 0 and
// y = 0 must give the same histories (to solver tolerance) at the same
// element size; in the full model, mirrored probes must agree with each
// other. This checks the symmetry planes (normal rotation zero), the shares
// of loads on the planes, the mapping of probes into the meshed part and the
// factors on the energies.

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  using liftoff_tests::run_scene;
  using liftoff_tests::symmetric_scene;

  const auto full    = run_scene(symmetric_scene("full", 10, 8));
  const auto half    = run_scene(symmetric_scene("half", 5, 8));
  const auto quarter = run_scene(symmetric_scene("quarter", 5, 4));

  double min_contact = 1;
  for (const auto &row : full->history())
    min_contact = std::min(min_contact, row["contact_fraction"]);
  checks.less("the scene lifts off (smallest contact fraction)",
              min_contact,
              0.95);

  checks.less("half vs full: probe histories",
              liftoff_tests::history_difference(*half, *full),
              1e-9);
  checks.less("quarter vs full: probe histories",
              liftoff_tests::history_difference(*quarter, *full),
              1e-9);
  checks.less("quarter vs full: energies and work",
              liftoff_tests::energy_difference(*quarter, *full),
              1e-9);

  double contact_difference = 0;
  for (unsigned int n = 0; n < full->history().size(); ++n)
    contact_difference =
      std::max(contact_difference,
               std::abs(full->history()[n]["contact_fraction"]
                        - quarter->history()[n]["contact_fraction"]));
  checks.less("quarter vs full: contact fraction", contact_difference, 1e-12);

  // Global refinement of a coarser mesh gives the same mesh, hence the same
  // history.
  checks.less("quarter, 10 x 8 cells vs 5 x 4 cells refined once",
              liftoff_tests::history_difference(
                *run_scene(symmetric_scene("quarter", 10, 8)),
                *run_scene(symmetric_scene("quarter", 5, 4, 2, 1))),
              1e-12);

  // Probes 1-4 are (+-0.3, +-0.2): mirror images of each other.
  double mirror_difference = 0, scale = 0;
  for (const auto &row : full->history())
    for (unsigned int k = 2; k <= 4; ++k)
      {
        mirror_difference =
          std::max(mirror_difference,
                   std::abs(row.probes("w")[k] - row.probes("w")[1]));
        scale = std::max(scale, std::abs(row.probes("w")[1]));
      }
  checks.less("full model: mirrored probes agree",
              mirror_difference / scale,
              1e-9);
  return checks.exit_code();
}
