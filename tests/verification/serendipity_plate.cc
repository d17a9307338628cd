// The eight-node serendipity element in liftoff's plate: the hard simply
// supported square Mindlin plate under uniform pressure (Delta = 0.1, a
// smooth solution) against Navier's series (navier_plate.h) and against the
// nine-node element FE_Q(2) on the same meshes, with full and with reduced
// shear integration (the treatments liftoff allows for it). The centre
// deflection must converge to the series at about the rate of Q2 and agree
// with Q2; the quarter model must equal the full one.

#include <deal.II/base/mpi.h>

#include "navier_plate.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace navier;


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  std::cout << std::scientific << std::setprecision(4);

  const double    delta = 0.1;
  const Reference ref   = navier_reference(shear_stiffness(delta));
  const std::vector<unsigned int> meshes = {4, 8, 16}; // cells per side

  for (const std::string treatment : {"full", "reduced"})
    {
      std::cout << treatment << " shear integration\n"
                << "  cells/side  S2 w(0,0) rel.error  Q2 rel.error"
                << "  |S2 - Q2|/w  S2 psi_x(1/2,0) rel.error" << std::endl;
      liftoff_tests::OrderTable table;
      for (unsigned int k = 0; k < meshes.size(); ++k)
        {
          const unsigned int n = meshes[k];
          const Result       s8 =
            run_navier(2, n, true, delta, treatment, "serendipity");
          const Result q2    = run_navier(2, n, true, delta, treatment);
          const double error = std::abs(s8.w_centre - ref.centre_deflection)
                               / ref.centre_deflection;
          const double q2_error = std::abs(q2.w_centre - ref.centre_deflection)
                                  / ref.centre_deflection;
          const double difference =
            std::abs(s8.w_centre - q2.w_centre) / ref.centre_deflection;
          const double psi_error = std::abs(s8.psi_edge - ref.edge_rotation)
                                   / std::abs(ref.edge_rotation);
          std::cout << "  " << std::setw(10) << n << "  " << error << "  "
                    << q2_error << "  " << difference << "  " << psi_error
                    << std::endl;

          const std::string name =
            treatment + ", " + std::to_string(n) + " cells/side";
          // Measured: errors 7e-3 (full) and 1e-3 (reduced) on 4 cells and
          // order 4 (like Q2's point values), S2 - Q2 3e-3, 1.5e-4, 9e-6.
          const double scale = std::pow(4.0 / n, 4);
          checks.less("S2 " + name + ": |w - Navier| / w", error, 2e-2 * scale);
          checks.less("S2 " + name + ": |w_S2 - w_Q2| / w",
                      difference,
                      1e-2 * scale);
          checks.less("S2 " + name + ": |psi - Navier| / psi",
                      psi_error,
                      2e-2 * scale);
          // A different element: an S2 run that is Q2 in disguise fails.
          checks.less("S2 " + name + ": S2 and Q2 differ (|w_S2 - w_Q2| / w)",
                      1e-8,
                      difference);
          table.add_value("cells", n);
          table.add_value("error", error);
        }
      // Each mesh halves h: one halving per row.
      const std::vector<double> orders = table.orders("error");
      for (unsigned int k = 1; k < meshes.size(); ++k)
        checks.within("S2 " + treatment + ", " + std::to_string(meshes[k - 1])
                        + " -> " + std::to_string(meshes[k])
                        + " cells/side: order of the centre deflection",
                      orders[k - 1],
                      3.5,
                      4.6);
    }

  // The quarter model equals the full plate on the same element size.
  const Result full = run_navier(2, 8, false, delta, "reduced", "serendipity");
  const Result quarter =
    run_navier(2, 8, true, delta, "reduced", "serendipity");
  checks.less("S2 quarter vs full model, 8 cells/side: relative difference",
              std::abs(full.w_centre - quarter.w_centre) / full.w_centre,
              1e-10);
  return checks.exit_code();
}
