// The static lift-off strip of static_beam_liftoff.cc (a free Timoshenko
// strip on a tensionless bed under a central line load) on adaptive meshes:
// the contact half-length a of the closed form (timoshenko_beam.h) must be
// met with fewer dofs by refining around the contact front than by refining
// every cell, both to the same tolerance.
//
// Both start from the same mesh of square cells (10 along the half strip,
// one across) and refine isotropically, as p4est does: "uniform" is
// `Global refinements` = 0, 1, 2, 3; "adaptive" is the coarse mesh with
// `Static cycles` refinements of the cells cut by the contact front and one
// band around them, up to `Maximum level` 3. The cell at x = 0 that carries
// the line load (as consistent nodal loads of a cell one cell wide, see
// timoshenko_beam.h) is not refined by the front indicator, so the load
// stays the consistent one of the closed form.
//
// With Q2 the smooth part of the deflection is resolved on the coarse mesh
// already (static_beam_liftoff.cc: w(0) to 1e-7 on 64 cells): what limits a
// is the cell that holds the contact edge, whose Gauss-point status
// integrates the kinked max(w, 0) only to O(h^2). Refining that cell alone
// is what the front indicator does.
//
// Measured (Q2, tolerance 1e-4 on a): uniform levels 0, 1, 2 give 2.1e-4,
// 1.4e-4, 2.7e-5 with 189, 615, 2187 dofs; the front-refined mesh 5.2e-5
// with 855 dofs (0.39 of the cheapest uniform mesh that meets 1e-4).
// Refining by the Kelly indicator (`liftoff_tests adaptive_static_liftoff
// kelly`) also passes, with 1878 dofs: it refines the loaded end as well.
//
// It can fail: `liftoff_tests adaptive_static_liftoff "point loads"` refines
// only the cells holding the loads, not the front, and a keeps the coarse
// mesh's error (2.2e-4): the check on a fails.

#include <deal.II/base/point.h>

#include "test_tools.h"
#include "timoshenko_beam.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
  using namespace dealii;
  using namespace liftoff_tests::beam_strip;
  using liftoff_tests::set;

  constexpr double       Gamma       = 1e4; // the contact edge near x = 0.22
  constexpr unsigned int degree      = 2;
  constexpr unsigned int coarse      = 10; // square cells: 1/2 / 10 = mu
  constexpr unsigned int finest      = 3;  // levels above the coarse mesh
  constexpr double       a_tolerance = 1e-4;

  struct Result
  {
    double        a_error;
    unsigned long n_dofs;
  };

  Result
  run(const std::string &options, const double a)
  {
    const auto simulator = liftoff_tests::run_scene(
      liftoff_tests::beam_strip_scene("tensionless", Gamma, degree, coarse)
      + options);
    const double a_h = liftoff_tests::first_zero([&](const double x) {
      return simulator->deflection_at(Point<2>(x, 0.0));
    });
    return {std::abs(a_h - a) / a,
            static_cast<unsigned long>(simulator->history().back()["dofs"])};
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  const std::string     indicator = (argc > 1 ? argv[1] : "contact front");

  liftoff_tests::TimoshenkoBeamOnFoundation beam(S, Gamma);
  const double a = liftoff_tests::contact_half_length(beam, F);
  checks.within("closed form: contact half-length a", a, 0.2, 0.25);

  // The cheapest uniform mesh that meets the tolerance; the coarse mesh
  // must miss it (else the tolerance says nothing about refinement).
  unsigned long uniform_dofs = 0;
  for (unsigned int level = 0; level <= finest && uniform_dofs == 0; ++level)
    {
      const Result r = run(set("Discretization/Global refinements", level), a);
      std::cout << "uniform, level " << level << ": " << r.n_dofs
                << " dofs, |a_h - a| / a = " << r.a_error << std::endl;
      if (level == 0)
        checks.within("uniform, coarse mesh: relative error of a, above the "
                      "tolerance",
                      r.a_error,
                      a_tolerance,
                      1);
      if (r.a_error < a_tolerance)
        uniform_dofs = r.n_dofs;
    }
  checks.less("uniform: a mesh up to level " + std::to_string(finest)
                + " meets the tolerance (0: none)",
              -double(uniform_dofs),
              0);

  const Result adaptive =
    run(set("Mesh refinement/Adaptive", "true")
          + set("Mesh refinement/Indicators", indicator)
          + set("Mesh refinement/Static cycles", finest + 1)
          + set("Mesh refinement/Maximum level", finest)
          + set("Mesh refinement/Front band", 1),
        a);
  std::cout << "adaptive (" << indicator << "), up to level " << finest << ": "
            << adaptive.n_dofs << " dofs, |a_h - a| / a = " << adaptive.a_error
            << std::endl;
  checks.less("adaptive: relative error of a", adaptive.a_error, a_tolerance);
  checks.less("adaptive dofs / uniform dofs at the same tolerance",
              double(adaptive.n_dofs) / uniform_dofs,
              1);
  return checks.exit_code();
}
