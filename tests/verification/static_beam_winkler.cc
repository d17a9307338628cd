// Static plate strip on a bilateral Winkler foundation under a central line
// load, compared with the closed-form Timoshenko beam on an elastic
// foundation.
//
// The FE strip (nu = 0, free long edges, one cell across, consistent nodal
// loads of a uniform line load; see timoshenko_beam.h for why) is exactly the
// 1D Timoshenko beam element, so w_h must converge to the closed form at the
// optimal rate p + 1, and must not depend on y.

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include "test_tools.h"
#include "timoshenko_beam.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace liftoff_tests::beam_strip;

  constexpr double Gamma = 2000.0; // decay length ~ (4/Gamma)^(1/4)
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  liftoff_tests::TimoshenkoBeamOnFoundation beam(S, Gamma);
  beam.solve(half_length, F);
  liftoff_tests::verify_closed_form(beam, S, Gamma, half_length, F, checks);

  const liftoff_tests::DeflectionSamples samples(
    [&](const double x) { return beam.w(x); });

  const std::vector<unsigned int> meshes = {8, 16, 32, 64};
  for (const unsigned int p : {1u, 2u})
    {
      std::vector<double>       errors;
      liftoff_tests::OrderTable table;
      for (const unsigned int n : meshes)
        {
          const auto simulator = liftoff_tests::run_scene(
            liftoff_tests::beam_strip_scene("bilateral", Gamma, p, n));
          const auto w_h = [&](const double x, const double y = 0.0) {
            return simulator->deflection_at(Point<2>(x, y));
          };
          // Discrete L2 norm of w_h - w along the axis (y = 0), and the
          // difference on the edge y = mu/2 (none if the FE strip is
          // y-independent).
          errors.push_back(samples.relative_l2_error(w_h));
          table.add_value("cells", n);
          table.add_value("L2 error w", errors.back());
          double edge_difference = 0;
          for (const double x : samples.x)
            edge_difference =
              std::max(edge_difference, std::abs(w_h(x, mu / 2) - w_h(x)));

          const std::string name =
            "Q" + std::to_string(p) + ", " + std::to_string(n) + " cells";
          checks.less(name + ": |w_h(y=mu/2) - w_h(y=0)| / rms w",
                      edge_difference / samples.rms,
                      1e-8);
          // A loose bound on every mesh, to see all errors in the output.
          checks.less(name + ": relative discrete L2 error of w",
                      errors.back(),
                      0.1);
        }
      const std::vector<double> orders = table.orders("L2 error w", "cells");
      table.set_scientific("L2 error w", true);
      std::cout << "Q" << p << ":" << std::endl;
      table.write_text(std::cout);
      for (unsigned int i = 1; i < errors.size(); ++i)
        {
          const double      order = orders[i - 1];
          const std::string name  = "Q" + std::to_string(p) + ": order "
                                   + std::to_string(meshes[i - 1]) + " -> "
                                   + std::to_string(meshes[i]) + " cells";
          // The asymptotic rate is p + 1; the last pair must be close to it.
          if (i + 1 == errors.size())
            checks.within(name, order, p + 0.7, p + 1.5);
          else
            checks.within(name, order, 0.0, p + 2.0);
        }
      // Observed on 64 cells: Q1 4.7e-4, Q2 7.1e-7.
      checks.less("Q" + std::to_string(p) + ": finest relative error",
                  errors.back(),
                  p == 1 ? 1e-3 : 2e-6);
    }

  return checks.exit_code();
}
