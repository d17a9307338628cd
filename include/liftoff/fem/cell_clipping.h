#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <utility>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * Quadrature rules, in one cell's reference coordinates, on the part of
   * the cell inside a region bounded by straight lines and circles (a
   * pressure's box, a tyre's disc), and the pieces of a straight segment
   * (a line load) inside the cell. For cells of any shape: the skewed
   * quadrilaterals of a mesh file and the curved ones of a disc or an
   * annulus, which PatchIntegrator's exact clipping of axis-aligned
   * rectangles does not cover.
   *
   * Under MappingQ(k) (MappingQ1: k = 1) the cell's map F from the unit
   * square is a tensor polynomial of degree k; it is sampled once at
   * (k + 1)^2 points and evaluated exactly from them. Along a column xi =
   * const each boundary g(F(xi, eta)) = 0 of the region is a polynomial in
   * eta (degree k for a line, 2k for a circle), so the roots in (0, 1)
   * bound the column's inside intervals exactly, and a Gauss rule on each
   * is exact for polynomial integrands in eta. Across columns the
   * intervals' ends move smoothly except at events: a boundary meeting a
   * cell edge, two boundaries meeting (a box's corner), a boundary tangent
   * to the columns (a circle's ends). Events are the xi where the order of
   * the roots and the inside flags of a column change; they are bisected
   * between columns of a scan that includes the xi of the region's corners
   * and centre and of its boundaries' crossings with the cell edges, so
   * that a region smaller than the scan's spacing is not missed. Between
   * events the ends are analytic in xi except at a tangency, where they go
   * like a square root; xi = a + (b - a) (1 - cos(pi u)) / 2 makes them
   * analytic in u, and the Gauss rule in u converges exponentially.
   */
  class CellClipping
  {
  public:
    /// One boundary of the region, inside where g(x) >= 0: the half-plane
    /// normal . x >= offset, or the disc |x - centre| <= radius.
    struct Boundary
    {
      bool         is_circle = false;
      Tensor<1, 2> normal;
      double       offset = 0;
      Point<2>     centre;
      double       radius = 0;
    };

    /// What inside() found: the cell wholly inside the region (its own
    /// rule is exact), not at all, or in part (`part`).
    struct Result
    {
      bool          whole = false;
      Quadrature<2> part;
    };

    CellClipping(const Mapping<2>                          &mapping,
                 const DoFHandler<2>::active_cell_iterator &cell);

    /// The cell's part inside every boundary of `region`: reference points,
    /// weights for FEValues (which multiplies by |det J|). `seeds`: points
    /// of the region (corners, centre) whose columns the scan includes.
    /// `line_rule` is used in eta, `arc_rule` in u.
    Result
    inside(const std::vector<Boundary> &region,
           const std::vector<Point<2>> &seeds,
           const Quadrature<1>         &line_rule,
           const Quadrature<1>         &arc_rule) const;

    /// The pieces [t0, t1] of the segment a + t (b - a), 0 <= t <= 1,
    /// inside the cell (its edges included), in increasing t.
    std::vector<std::pair<double, double>>
    pieces(const Point<2> &a, const Point<2> &b) const;

    /// The reference point of x (Newton on F; x in or near the cell).
    Point<2>
    to_unit(const Point<2> &x) const;
    /// |det J| of F at the reference point xi.
    double
    jacobian_determinant(const Point<2> &xi) const;

  private:
    /// Monomial coefficients of a polynomial in one variable.
    using Polynomial = std::vector<double>;

    /// Degree of the map, its values at the (k + 1)^2 equispaced nodes
    /// (xi fastest) and the Lagrange basis of those nodes in one variable.
    unsigned int            degree;
    std::vector<Point<2>>   node_values;
    std::vector<Polynomial> basis;
    double                  cell_size;

    /// F along the line xi = `at` (direction 0) or eta = `at` (1), as
    /// polynomials of x and y in the other coordinate.
    std::array<Polynomial, 2>
    along(const unsigned int direction, const double at) const;
    Point<2>
    value(const Point<2> &xi) const;
    Tensor<2, 2>
    jacobian(const Point<2> &xi) const;

    /// The roots in (0, 1) of each boundary's g along a column, sorted,
    /// with the index of its boundary, and the inside intervals.
    struct Column
    {
      std::vector<std::pair<double, unsigned int>> roots;
      std::vector<std::pair<double, double>>       intervals;
      std::vector<unsigned int>                    signature;
    };
    Column
    column(const double xi, const std::vector<Boundary> &region) const;
    /// The xi where the columns change (0 and 1 among them, sorted), found
    /// by a scan and bisection; none if no boundary enters the cell, which
    /// then lies `wholly_inside` the region or wholly outside.
    std::vector<double>
    events(const std::vector<Boundary> &region,
           const std::vector<Point<2>> &seeds,
           bool                        &wholly_inside) const;
    /// The xi in (a, b) where the column's signature changes.
    void
    add_events(const double                 a,
               const std::vector<unsigned> &signature_a,
               const double                 b,
               const std::vector<unsigned> &signature_b,
               const std::vector<Boundary> &region,
               std::vector<double>         &events) const;
  };
} // namespace liftoff
