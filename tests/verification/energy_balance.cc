// Energy balance of the discrete dynamics, from the history the simulator
// writes (kinetic + strain + foundation energy - initial energy - work of
// the loads):
//  - bilateral springs, Newmark beta = 1/4, gamma = 1/2: the average
//    acceleration rule conserves the energy of a linear system exactly, so
//    the balance holds to round-off;
//  - tensionless springs: the stiffness changes within a step, the balance
//    error is no longer zero but small, and falls as dt falls;
//  - static, tensionless: the response is positively homogeneous in the
//    load, so the stored energy equals half the work F.u (Clapeyron).

#include "energy_checks.h"
#include "test_tools.h"

#include <cmath>

namespace
{
  std::string
  scene(const std::string &foundation,
        const double       dt,
        const std::string &analysis  = "dynamic",
        const double       stiffness = 200)
  {
    using liftoff_tests::set;
    return liftoff_tests::small_plate_scene() + set("Analysis/Type", analysis)
           + set("Foundation/Model", foundation)
           + set("Foundation/Stiffness", stiffness)
           + set("Time integration/Time step", dt)
           + set("Time integration/End time", 0.2);
  }

  using liftoff_tests::relative_balance_error;
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  checks.less("bilateral: max |energy balance error| / max work",
              relative_balance_error(
                *liftoff_tests::run_scene(scene("bilateral", 2e-3))),
              1e-10);

  double previous = 0;
  for (const double dt : {4e-3, 2e-3, 1e-3})
    {
      const auto simulator = liftoff_tests::run_scene(scene("tensionless", dt));
      const double error   = relative_balance_error(*simulator);
      double       contact = 1;
      for (const auto &row : simulator->history())
        contact = std::min(contact, row["contact_fraction"]);
      std::cout << "tensionless, dt = " << dt << ": balance error " << error
                << ", smallest contact fraction " << contact << std::endl;
      if (previous > 0)
        checks.less("tensionless: balance error falls when dt is halved "
                    "(ratio to the previous dt)",
                    error / previous,
                    0.8);
      else
        checks.less("tensionless: the scene does lift off (smallest contact "
                    "fraction)",
                    contact,
                    0.9);
      previous = error;
    }
  checks.less("tensionless: balance error at dt = 1e-3", previous, 1e-4);

  const auto statics =
    liftoff_tests::run_scene(scene("tensionless", 1, "static", 2e4));
  const auto &row = statics->history().back();
  checks.less(
    "static tensionless: |strain + foundation energy - F.u/2| / (F.u/2)",
    std::abs(row.energies().strain + row.energies().supports
             - row.energies().work)
      / row.energies().work,
    1e-10);
  checks.less("static tensionless: the plate lifts off (contact fraction)",
              row["contact_fraction"],
              0.99);
  return checks.exit_code();
}
