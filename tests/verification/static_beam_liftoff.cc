// Static plate strip on a TENSIONLESS Winkler foundation under a central
// line load: the strip lifts off near its ends. Compared with the closed
// form of a Timoshenko beam that is supported on [-a, a] and straight and
// unloaded beyond.
//
// As in static_beam_winkler.cc (see the reasoning in timoshenko_beam.h),
// nu = 0, free long edges, one cell across the strip and consistent nodal
// loads of a uniform line load make the FE strip exactly the 1D Timoshenko
// beam element.
//
// Closed form on the half x >= 0: on the contact zone [0, a] the beam obeys
// the equations of the elastic foundation with psi(0) = 0, Q(0) = -F, and at
// the contact edge M(a) = Q(a) = 0 (the lifted part (a, 1/2] carries no
// load and has a free end, so M = Q = 0 all along it, and by continuity at
// a), plus w(a) = 0 (the edge of the contact zone). For each trial a the
// first four conditions fix the four constants; a is the root of w(a) = 0.
// Beyond a, M = psi' = 0 and Q = 0 give psi = psi(a) and w' = psi(a): a
// straight line w = psi(a) (x - a) < 0.
//
// The FE contact set is resolved at Gauss points, so the contact edge is
// located only to within a cell; the FE zero of w_h still converges to a
// under h-refinement, and that is what is checked.
//
// How it was checked that this test can fail: running
//   liftoff_tests static_beam_liftoff bilateral
// repeats the scenes with Foundation/Model = bilateral (springs that pull).
// The bilateral strip first crosses w = 0 at x = 0.327 instead of a = 0.221
// and its w(0) is 6 % smaller, so the checks on a, w(0), the profile, the
// contact fraction and the active-set iterations FAIL (the program exits
// with 1).

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include "test_tools.h"
#include "timoshenko_beam.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace liftoff_tests::beam_strip;

  constexpr double Gamma = 1e4; // the contact zone ends near x = 0.22


} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  // Only to show that the checks can fail: "bilateral" as the argument runs
  // the same scenes with springs that pull (see the comment at the top).
  const std::string model = (argc > 1 ? argv[1] : "tensionless");

  // The contact half-length: the first a at which w(a), with the other
  // four conditions imposed at a, turns from positive to negative.
  liftoff_tests::TimoshenkoBeamOnFoundation beam(S, Gamma);
  const double a = liftoff_tests::contact_half_length(beam, F);
  checks.within("closed form: contact half-length a", a, 0.01, 0.49);
  if (a < 0)
    return checks.exit_code(); // no lift-off: nothing to compare with
  liftoff_tests::verify_closed_form(beam, S, Gamma, a, F, checks);
  checks.less("closed form: |w(a)| / w(0)",
              std::abs(beam.w(a)) / beam.w(0),
              1e-10);

  // The solution must be admissible: pressed in on [0, a), lifted beyond.
  double w_min = beam.w(0);
  for (unsigned int i = 0; i < 1000; ++i)
    w_min = std::min(w_min, beam.w(a * i / 1000.0));
  checks.within("closed form: min w on [0, a) / w(0)",
                w_min / beam.w(0),
                1e-6,
                1);
  const double slope = beam.psi(a); // of the straight lifted part
  checks.less("closed form: slope of the lifted part / (w(0) / a), < 0",
              slope / (beam.w(0) / a),
              0);

  // The reference deflection on the whole half strip.
  const auto w_reference = [&](const double x) {
    return x <= a ? beam.w(x) : slope * (x - a);
  };
  const double w0 = beam.w(0);

  const liftoff_tests::DeflectionSamples samples(w_reference);

  const std::vector<unsigned int> meshes = {8, 16, 32, 64};
  for (const unsigned int p : {1u, 2u})
    {
      std::vector<double>       w0_errors, a_errors, l2_errors;
      liftoff_tests::OrderTable table;
      for (const unsigned int n : meshes)
        {
          const auto simulator = liftoff_tests::run_scene(
            liftoff_tests::beam_strip_scene(model, Gamma, p, n));
          const auto w_h = [&](const double x) {
            return simulator->deflection_at(Point<2>(x, 0.0));
          };

          const double a_h = liftoff_tests::first_zero(w_h);

          w0_errors.push_back(std::abs(w_h(0) - w0) / w0);
          a_errors.push_back(std::abs(a_h - a) / a);
          l2_errors.push_back(samples.relative_l2_error(w_h));
          table.add_value("cells", n);
          table.add_value("w(0)", w0_errors.back());
          table.add_value("a", a_errors.back());
          table.add_value("L2", l2_errors.back());

          const std::string name =
            "Q" + std::to_string(p) + ", " + std::to_string(n) + " cells";
          // Loose bounds on every mesh, to show all errors in the output.
          checks.less(name + ": relative error of w(0)", w0_errors.back(), 0.1);
          checks.less(name + ": relative error of a", a_errors.back(), 0.1);
          checks.less(name + ": relative discrete L2 error of w",
                      l2_errors.back(),
                      0.1);
          // The first iterate is the bilateral problem, whose solution pulls
          // beyond x = 0.33, so the active set must have changed at least
          // once; and it must settle well before the limit.
          checks.within(name + ": active-set iterations",
                        simulator->history().back()["active_set_iterations"],
                        2,
                        20);
          // The library's contact bookkeeping: the Gauss points in contact
          // cover [0, a] up to the one cell that holds the contact edge.
          const double contact_length =
            simulator->history().back()["contact_fraction"] * half_length;
          checks.less(name + ": |contact fraction * 1/2 - a| / cell size",
                      std::abs(contact_length - a) / (half_length / n),
                      1.0);
        }
      // Pairwise orders, for information: with Q2 they jump around (see
      // below), so only their mean over 8 -> 64 cells is checked.
      const std::string q      = "Q" + std::to_string(p);
      const auto        orders = [&](const std::string &key) {
        table.set_scientific(key, true);
        return table.orders(key, "cells");
      };
      const std::vector<double> w0_orders = orders("w(0)"),
                                a_orders  = orders("a"),
                                l2_orders = orders("L2");
      std::cout << q << ": relative errors and orders" << std::endl;
      table.write_text(std::cout);

      // The Gauss-point contact status integrates the kinked max(w, 0) in
      // the cell that holds the contact edge only to O(h^2), whatever p, so
      // a and the profile converge like h^2 at best, irregularly with the
      // position of a among the Gauss points (Q2: a stalls from 16 to 32
      // cells). Require that rate on average over three halvings.
      const auto mean_order = [](const std::vector<double> &pairwise) {
        return std::accumulate(pairwise.begin(), pairwise.end(), 0.0)
               / pairwise.size();
      };
      checks.within(q + ": mean order of w(0), 8 -> 64 cells",
                    mean_order(w0_orders),
                    1.5,
                    10);
      checks.within(q + ": mean order of a, 8 -> 64 cells",
                    mean_order(a_orders),
                    1.5,
                    10);
      checks.within(q + ": mean order of the L2 error, 8 -> 64 cells",
                    mean_order(l2_orders),
                    1.5,
                    10);
      if (p == 1)
        {
          // Q1 is in its asymptotic range: the last pair is close to 2.
          checks.within("Q1: order of w(0), 32 -> 64 cells",
                        w0_orders[2],
                        1.7,
                        2.5);
          checks.within("Q1: order of a, 32 -> 64 cells",
                        a_orders[2],
                        1.5,
                        2.5);
        }

      // Finest mesh (observed: Q1 4.9e-4, 4.3e-4, 8.8e-4; Q2 9.3e-8,
      // 1.6e-5, 3.8e-5 for w(0), a and L2).
      checks.less(q + ", 64 cells: relative error of w(0) (finest)",
                  w0_errors.back(),
                  p == 1 ? 1e-3 : 1e-6);
      checks.less(q + ", 64 cells: relative error of a (finest)",
                  a_errors.back(),
                  p == 1 ? 1e-3 : 1e-4);
      checks.less(q + ", 64 cells: relative L2 error of w (finest)",
                  l2_errors.back(),
                  p == 1 ? 2e-3 : 1e-4);
    }

  return checks.exit_code();
}
