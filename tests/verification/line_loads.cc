// Line loads along any straight segment (issue 33), standing and moving.
// The load vector b is checked as pressure_patches checks patches:
// b . I(g) = int f g ds for g = 1, x, y, x y in the w component (g is in the
// element's space and satisfies the hanging-node constraints, so the
// identity is exact for the condensed vector). The exact values are the
// line integrals of polynomials, by a 12-point Gauss rule over the part of
// the segment on the meshed part (exact for the degrees used here).
// Segments across many cells, inside one cell, through the hanging nodes of
// a locally refined mesh, along the faces between cells (where each side
// must count half), along a plate edge, on a symmetry plane (the modelled
// part's share is half), partly off the plate, and moving along a path.
// A static run on a bilateral bed: the bed's resultant and its centre equal
// the line's (free plate: statics).
// Seen failing: with each side of a face counting the whole piece, the
// force was off by 2.4e-3 of the load's scale on the full plate (the line
// along y = 0.2 counted twice) and by 1.9e-2 on the half model (the line
// on the plane counted whole).

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/loads/load_set.h>

#include "pressure_patches.h"
#include "test_tools.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using liftoff_tests::set;
  using pressure_patches::InWComponent;
  using pressure_patches::mesh;
  using pressure_patches::Monomial;

  Point<2>
  P(const double x, const double y)
  {
    return Point<2>(x, y);
  }

  /// A line load: its ends on the full plate at tau = 0 (offsets from the
  /// path's point if it has a Path), its intensity and magnitude.
  struct Line
  {
    Point<2>              a, b;
    std::vector<Monomial> intensity = {{1, 0, 0}};
    double                magnitude = 1;
    /// A path "x(tau); y(tau)" or "" (the line stands).
    std::string path = "";
    /// Where the path is at the tau of the check.
    Tensor<1, 2> shift;
    /// The modelled part's share of it (1/2 on a symmetry plane).
    double share = 1;

    std::string
    scene(const unsigned int k) const
    {
      std::ostringstream text;
      text << std::setprecision(17) << a[0] << ", " << a[1] << ", " << b[0]
           << ", " << b[1];
      std::ostringstream f;
      f << std::setprecision(17) << "0";
      for (const auto &m : intensity)
        f << " + (" << m.c << ")*x^" << m.a << "*y^" << m.b;
      const std::string section = "Loads/Line load " + std::to_string(k) + "/";
      return set(section + "Magnitude", magnitude)
             + set(section + "Segment", text.str())
             + set(section + "Intensity", f.str())
             + (path.empty() ? "" : set(section + "Path", path));
    }

    /// magnitude * share * int f x^i y^j ds over the line's part in `box`.
    double
    moment(const BoundingBox<2> &box,
           const unsigned int    i,
           const unsigned int    j) const
    {
      const Point<2> p = a + shift, q = b + shift;
      // The part in the box: clipped slab by slab (written anew here).
      double t0 = 0, t1 = 1;
      for (unsigned int d = 0; d < 2; ++d)
        if (std::abs(q[d] - p[d]) > 0)
          {
            const double s0 = (box.lower_bound(d) - p[d]) / (q[d] - p[d]);
            const double s1 = (box.upper_bound(d) - p[d]) / (q[d] - p[d]);
            t0              = std::max(t0, std::min(s0, s1));
            t1              = std::min(t1, std::max(s0, s1));
          }
      if (t1 <= t0)
        return 0;
      const QGauss<1> rule(12);
      double          sum = 0;
      for (unsigned int k = 0; k < rule.size(); ++k)
        {
          const Point<2> x = p + (t0 + (t1 - t0) * rule.point(k)[0]) * (q - p);
          double         f = 0;
          for (const auto &m : intensity)
            f += m.c * std::pow(x[0], m.a) * std::pow(x[1], m.b);
          sum += rule.weight(k) * f * std::pow(x[0], i) * std::pow(x[1], j);
        }
      return magnitude * share * sum * (t1 - t0) * p.distance(q);
    }

    double
    scale() const
    {
      double sum = 0;
      for (const auto &m : intensity)
        sum += std::abs(m.c);
      return std::abs(magnitude) * sum * a.distance(b);
    }
  };

  /// A standing or moving line (aggregate initialisation would leave the
  /// later members to their defaults silently).
  Line
  line(const Point<2>              &a,
       const Point<2>              &b,
       const std::vector<Monomial> &intensity = {{1, 0, 0}},
       const double                 magnitude = 1,
       const std::string           &path      = "")
  {
    Line l;
    l.a         = a;
    l.b         = b;
    l.intensity = intensity;
    l.magnitude = magnitude;
    l.path      = path;
    return l;
  }

  struct Case
  {
    std::string       label;
    std::string       discretization;
    std::vector<Line> lines;
    double            refine_below = -1e300;
    double            tau          = 0;

    std::string
    scene() const
    {
      std::string text = discretization;
      for (unsigned int k = 0; k < lines.size(); ++k)
        text += lines[k].scene(k + 1);
      return text;
    }
  };

  void
  check_case(const Case &c, liftoff_tests::Checks &checks, const MPI_Comm comm)
  {
    const pressure_patches::AssembledLoad load =
      pressure_patches::assemble_load(c.scene(), c.refine_below, c.tau, comm);
    double scale = 0;
    for (const auto &line : c.lines)
      scale += line.scale();
    const std::array<std::array<unsigned int, 2>, 4> powers = {
      {{{0, 0}}, {{1, 0}}, {{0, 1}}, {{1, 1}}}};
    const std::array<std::string, 4> names = {{"1", "x", "y", "x y"}};
    for (unsigned int k = 0; k < powers.size(); ++k)
      {
        double exact = 0;
        for (const auto &line : c.lines)
          exact += line.moment(load.disc->geometry().modelled_box(),
                               powers[k][0],
                               powers[k][1]);
        checks.less(c.label + ": |int f " + names[k] + " - exact| / scale",
                    std::abs(load.moment(powers[k][0], powers[k][1]) - exact)
                      / scale,
                    1e-12);
      }
  }

  std::vector<Case>
  cases()
  {
    // Cells of 5 x 4 on a plate 0.8 wide: x = -0.5, -0.3, ..., 0.5 and
    // y = -0.4, -0.2, ..., 0.4; those with x + y < 0 refined once.
    const std::vector<Monomial> cubic = {
      {1, 0, 0}, {2, 1, 0}, {-3, 0, 1}, {4, 1, 1}, {-2, 2, 0}};
    const std::vector<Line> anywhere = {
      line(P(-0.37, -0.29), P(0.41, 0.33), cubic, 1.5), // across many cells
      line(P(0.013, 0.021), P(0.037, 0.029), cubic, 2), // inside one cell
      line(P(-0.45, 0.2), P(0.35, 0.2), cubic, -0.7),   // along faces, hanging
      line(P(-0.3, -0.2), P(0.3, 0.2), cubic, 0.4),     // through vertices
      line(P(0.5, -0.1), P(0.5, 0.3), cubic, 1.1),      // on the Right edge
      line(P(-0.5, -0.4), P(0.5, -0.4), {{1, 0, 0}}, 0.9) // the Bottom edge
    };
    std::vector<Case> list;
    for (const std::string element : {"Q1", "Q2", "S2"})
      list.push_back({"full plate, 5 x 4 " + element + ", hanging nodes",
                      mesh("full", 5, 4, element, 0.8),
                      anywhere,
                      0.0});

    // A half model: a line on the plane x = 0 (its own image, intensity
    // even in x), one across the plane and a mirrored pair.
    const std::vector<Monomial> even = {{1, 0, 0}, {3, 2, 0}, {-2, 0, 1}};
    Line on_plane                    = line(P(0, -0.33), P(0, 0.27), even, 1.3);
    on_plane.share                   = 0.5;
    const std::vector<Line> half     = {
          on_plane,
          line(P(-0.21, 0.1), P(0.21, 0.1), even, 0.6),
          line(P(0.07, -0.3), P(0.41, 0.25), cubic, 1),
          line(P(-0.07, -0.3),
           P(-0.41, 0.25),
           {{1, 0, 0}, {-2, 1, 0}, {-3, 0, 1}, {-4, 1, 1}, {-2, 2, 0}},
           1)};
    for (const std::string element : {"Q1", "Q2"})
      list.push_back({"half model, 3 x 5 " + element + ", hanging nodes",
                      mesh("half", 3, 5, element, 0.8),
                      half,
                      0.15});

    // Moving: at tau = 0.3 the first line has crossed the Right edge in
    // part, the second the Top edge.
    Line leaving =
      line(P(-0.1, -0.05), P(0.1, 0.15), cubic, 1.2, "0.35 + 0.5*tau; 0");
    leaving.shift = Tensor<1, 2>({0.5, 0});
    Line rising =
      line(P(0.0, -0.1), P(0.02, 0.1), {{1, 0, 0}}, 0.8, "-0.2; 0.1 + tau");
    rising.shift = Tensor<1, 2>({-0.2, 0.4});
    for (const std::string element : {"Q1", "Q2"})
      list.push_back({"moving lines at tau = 0.3, 5 x 4 " + element,
                      mesh("full", 5, 4, element, 0.8),
                      {leaving, rising},
                      -1e300,
                      0.3});
    return list;
  }

  /// A static run on a bilateral bed: the bed carries the line.
  void
  check_static_resultant(liftoff_tests::Checks &checks, const MPI_Comm comm)
  {
    const Line load = line(P(-0.31, -0.17), P(0.23, 0.29));
    const auto run  = liftoff_tests::run_scene(
      mesh("full", 6, 6, "Q2") + load.scene(1) + set("Analysis/Type", "static")
        + set("Foundation/Model", "bilateral")
        + set("Output/Write foundation resultant", "true"),
      nullptr,
      comm);
    const auto  &row    = run->history().back();
    const double length = load.a.distance(load.b);
    checks.less("static run: |bed resultant / load - 1|",
                std::abs(row["resultant"] / length - 1),
                1e-8);
    const Point<2> centre = load.a + 0.5 * (load.b - load.a);
    checks.less("static run: |centre of resultant - middle of the line|",
                std::hypot(row["resultant_x"] - centre[0],
                           row["resultant_y"] - centre[1]),
                1e-9);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  for (const auto &c : cases())
    check_case(c, checks, MPI_COMM_WORLD);
  check_static_resultant(checks, MPI_COMM_WORLD);
  return checks.exit_code();
}
