#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/fe/mapping_q.h>

#include <liftoff/fem/cell_clipping.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace liftoff
{
  namespace
  {
    using Polynomial = std::vector<double>;

    double
    evaluate(const Polynomial &p, const double t)
    {
      double sum = 0;
      for (auto c = p.rbegin(); c != p.rend(); ++c)
        sum = sum * t + *c;
      return sum;
    }

    Polynomial
    derivative(const Polynomial &p)
    {
      Polynomial d(p.size() > 1 ? p.size() - 1 : 1, 0.0);
      for (unsigned int n = 1; n < p.size(); ++n)
        d[n - 1] = n * p[n];
      return d;
    }

    /// p + s q.
    Polynomial
    plus(const Polynomial &p, const double s, const Polynomial &q)
    {
      Polynomial sum(std::max(p.size(), q.size()), 0.0);
      for (unsigned int n = 0; n < p.size(); ++n)
        sum[n] += p[n];
      for (unsigned int n = 0; n < q.size(); ++n)
        sum[n] += s * q[n];
      return sum;
    }

    Polynomial
    times(const Polynomial &p, const Polynomial &q)
    {
      Polynomial product(p.size() + q.size() - 1, 0.0);
      for (unsigned int m = 0; m < p.size(); ++m)
        for (unsigned int n = 0; n < q.size(); ++n)
          product[m + n] += p[m] * q[n];
      return product;
    }

    /// The simple roots of p in the open interval (0, 1), sorted: p is
    /// monotone between the roots of p', so each sign change between them
    /// holds one root, found by bisection. Double roots (p touching zero)
    /// do not split an interval and are left out.
    std::vector<double>
    roots(const Polynomial &p)
    {
      std::size_t n = p.size();
      while (n > 1 && p[n - 1] == 0)
        --n;
      if (n <= 1)
        return {};
      const Polynomial    trimmed(p.begin(), p.begin() + n);
      std::vector<double> knots = {0.0};
      for (const double c : roots(derivative(trimmed)))
        knots.push_back(c);
      knots.push_back(1.0);
      std::vector<double> found;
      for (unsigned int k = 0; k + 1 < knots.size(); ++k)
        {
          double       u = knots[k], v = knots[k + 1];
          const double pu = evaluate(trimmed, u), pv = evaluate(trimmed, v);
          if (!((pu < 0 && pv > 0) || (pu > 0 && pv < 0)))
            continue;
          const bool rising = pu < 0;
          while (v - u > 4 * std::numeric_limits<double>::epsilon())
            {
              const double m = 0.5 * (u + v);
              if (m <= u || m >= v)
                break;
              ((evaluate(trimmed, m) < 0) == rising ? u : v) = m;
            }
          found.push_back(0.5 * (u + v));
        }
      return found;
    }

    /// The Lagrange polynomials of the nodes 0, 1/k, ..., 1.
    std::vector<Polynomial>
    lagrange_basis(const unsigned int k)
    {
      std::vector<Polynomial> basis;
      for (unsigned int m = 0; m <= k; ++m)
        {
          Polynomial l = {1.0};
          for (unsigned int n = 0; n <= k; ++n)
            if (n != m)
              {
                // (t - t_n) / (t_m - t_n)
                const double gap = (double(m) - double(n)) / k;
                l = times(l, Polynomial{-double(n) / k / gap, 1.0 / gap});
              }
          basis.push_back(l);
        }
      return basis;
    }

    /// g of `boundary` along the curve (x(t), y(t)).
    Polynomial
    along_boundary(const CellClipping::Boundary    &boundary,
                   const std::array<Polynomial, 2> &curve)
    {
      if (!boundary.is_circle)
        return plus(plus(Polynomial{-boundary.offset},
                         boundary.normal[0],
                         curve[0]),
                    boundary.normal[1],
                    curve[1]);
      // (r^2 - |x - c|^2) / (2 r): the distance to the circle near it.
      const Polynomial dx = plus(curve[0], -boundary.centre[0], {1.0});
      const Polynomial dy = plus(curve[1], -boundary.centre[1], {1.0});
      const double     r  = boundary.radius;
      return plus(plus(Polynomial{r / 2}, -0.5 / r, times(dx, dx)),
                  -0.5 / r,
                  times(dy, dy));
    }

    unsigned int
    degree_of(const Mapping<2> &mapping)
    {
      const auto *polynomial = dynamic_cast<const MappingQ<2> *>(&mapping);
      AssertThrow(polynomial != nullptr,
                  ExcMessage("CellClipping needs a MappingQ (or MappingQ1), "
                             "whose cells are tensor polynomials."));
      return polynomial->get_degree();
    }
  } // namespace


  CellClipping::CellClipping(const Mapping<2>                          &mapping,
                             const DoFHandler<2>::active_cell_iterator &cell)
      : degree(degree_of(mapping))
      , basis(lagrange_basis(degree))
      , cell_size(cell->diameter())
  {
    for (unsigned int j = 0; j <= degree; ++j)
      for (unsigned int i = 0; i <= degree; ++i)
        node_values.push_back(mapping.transform_unit_to_real_cell(
          cell, Point<2>(double(i) / degree, double(j) / degree)));
  }


  std::array<CellClipping::Polynomial, 2>
  CellClipping::along(const unsigned int direction, const double at) const
  {
    const unsigned int        n = degree + 1;
    std::array<Polynomial, 2> curve;
    for (unsigned int m = 0; m < n; ++m)
      {
        // The map's value at node m of the free coordinate.
        Point<2> g;
        for (unsigned int l = 0; l < n; ++l)
          g += evaluate(basis[l], at)
               * (direction == 0 ? node_values[l + n * m]
                                 : node_values[m + n * l]);
        for (unsigned int d = 0; d < 2; ++d)
          curve[d] = plus(curve[d], g[d], basis[m]);
      }
    return curve;
  }


  Point<2>
  CellClipping::value(const Point<2> &xi) const
  {
    const auto curve = along(0, xi[0]);
    return Point<2>(evaluate(curve[0], xi[1]), evaluate(curve[1], xi[1]));
  }


  Tensor<2, 2>
  CellClipping::jacobian(const Point<2> &xi) const
  {
    const auto   column = along(0, xi[0]);
    const auto   row    = along(1, xi[1]);
    Tensor<2, 2> j;
    for (unsigned int d = 0; d < 2; ++d)
      {
        j[d][0] = evaluate(derivative(row[d]), xi[0]);
        j[d][1] = evaluate(derivative(column[d]), xi[1]);
      }
    return j;
  }


  double
  CellClipping::jacobian_determinant(const Point<2> &xi) const
  {
    return std::abs(determinant(jacobian(xi)));
  }


  Point<2>
  CellClipping::to_unit(const Point<2> &x) const
  {
    Point<2> xi(0.5, 0.5);
    for (unsigned int it = 0; it < 50; ++it)
      {
        const Tensor<1, 2> residual = value(xi) - x;
        if (residual.norm() <= 1e-14 * cell_size)
          return xi;
        const Tensor<2, 2> j = jacobian(xi);
        if (!(std::abs(determinant(j)) > 0))
          break;
        xi -= invert(j) * residual;
        if (xi.norm() > 1e3)
          break;
      }
    const Tensor<1, 2> residual = value(xi) - x;
    if (residual.norm() <= 1e-10 * cell_size)
      return xi;
    return Point<2>(std::numeric_limits<double>::quiet_NaN(),
                    std::numeric_limits<double>::quiet_NaN());
  }


  CellClipping::Column
  CellClipping::column(const double                 xi,
                       const std::vector<Boundary> &region) const
  {
    const auto              curve = along(0, xi);
    std::vector<Polynomial> g;
    Column                  result;
    for (unsigned int b = 0; b < region.size(); ++b)
      {
        g.push_back(along_boundary(region[b], curve));
        for (const double eta : roots(g.back()))
          result.roots.emplace_back(eta, b);
      }
    std::sort(result.roots.begin(), result.roots.end());
    std::vector<double> ends = {0.0};
    for (const auto &root : result.roots)
      ends.push_back(root.first);
    ends.push_back(1.0);
    for (unsigned int k = 0; k + 1 < ends.size(); ++k)
      {
        const double middle = 0.5 * (ends[k] + ends[k + 1]);
        bool         in     = true;
        for (const Polynomial &p : g)
          in = in && evaluate(p, middle) >= 0;
        // The order of the boundaries crossed and where the column is
        // inside: what changes at an event.
        if (k > 0)
          result.signature.push_back(result.roots[k - 1].second);
        result.signature.push_back(in ? region.size() + 1 : region.size());
        if (!in || ends[k + 1] <= ends[k])
          continue;
        if (!result.intervals.empty()
            && result.intervals.back().second == ends[k])
          result.intervals.back().second = ends[k + 1];
        else
          result.intervals.emplace_back(ends[k], ends[k + 1]);
      }
    return result;
  }


  void
  CellClipping::add_events(const double                 a,
                           const std::vector<unsigned> &signature_a,
                           const double                 b,
                           const std::vector<unsigned> &signature_b,
                           const std::vector<Boundary> &region,
                           std::vector<double>         &events) const
  {
    if (signature_a == signature_b)
      return;
    const double middle = 0.5 * (a + b);
    if (b - a <= 1e-14 || middle <= a || middle >= b)
      {
        events.push_back(middle);
        return;
      }
    const std::vector<unsigned> signature = column(middle, region).signature;
    add_events(a, signature_a, middle, signature, region, events);
    add_events(middle, signature, b, signature_b, region, events);
  }


  std::vector<double>
  CellClipping::events(const std::vector<Boundary> &region,
                       const std::vector<Point<2>> &seeds,
                       bool                        &wholly_inside) const
  {
    // Breaks in xi that are known: the cell's ends, the seeds' columns and
    // where the boundaries cross the edges eta = 0 and eta = 1.
    std::vector<double> breaks = {0.0, 1.0};
    for (const Point<2> &p : seeds)
      {
        const double xi = to_unit(p)[0];
        if (xi > 0 && xi < 1)
          breaks.push_back(xi);
      }
    for (const double eta : {0.0, 1.0})
      {
        const auto edge = along(1, eta);
        for (const Boundary &boundary : region)
          for (const double xi : roots(along_boundary(boundary, edge)))
            breaks.push_back(xi);
      }
    std::vector<double> scan = breaks;
    for (unsigned int k = 1; k < 8; ++k)
      scan.push_back(k / 8.0);
    std::sort(scan.begin(), scan.end());
    scan.erase(std::unique(scan.begin(), scan.end()), scan.end());

    std::vector<std::vector<unsigned>> signatures;
    for (const double xi : scan)
      signatures.push_back(column(xi, region).signature);
    bool uniform = true;
    for (unsigned int k = 0; k + 1 < scan.size(); ++k)
      {
        uniform = uniform && signatures[k] == signatures[k + 1];
        add_events(scan[k],
                   signatures[k],
                   scan[k + 1],
                   signatures[k + 1],
                   region,
                   breaks);
      }
    // No boundary in the cell: wholly inside or outside.
    wholly_inside = (signatures[0].back() == region.size() + 1);
    if (uniform && signatures[0].size() == 1)
      return {};
    std::sort(breaks.begin(), breaks.end());
    return breaks;
  }


  CellClipping::Result
  CellClipping::inside(const std::vector<Boundary> &region,
                       const std::vector<Point<2>> &seeds,
                       const Quadrature<1>         &line_rule,
                       const Quadrature<1>         &arc_rule) const
  {
    Result                    result;
    const std::vector<double> breaks = events(region, seeds, result.whole);
    if (breaks.empty())
      return result;
    result.whole = false;
    std::vector<Point<2>> points;
    std::vector<double>   weights;
    for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
      {
        const double a = breaks[k], b = breaks[k + 1];
        if (b - a <= 1e-14)
          continue;
        for (unsigned int q = 0; q < arc_rule.size(); ++q)
          {
            const double u  = arc_rule.point(q)[0];
            const double xi = a + (b - a) * (1 - std::cos(numbers::PI * u)) / 2;
            const double dxi = arc_rule.weight(q) * (b - a) * numbers::PI
                               * std::sin(numbers::PI * u) / 2;
            for (const auto &[lo, hi] : column(xi, region).intervals)
              for (unsigned int j = 0; j < line_rule.size(); ++j)
                {
                  points.emplace_back(xi,
                                      lo + (hi - lo) * line_rule.point(j)[0]);
                  weights.push_back(dxi * (hi - lo) * line_rule.weight(j));
                }
          }
      }
    result.part = Quadrature<2>(points, weights);
    return result;
  }


  std::vector<std::pair<double, double>>
  CellClipping::pieces(const Point<2> &a, const Point<2> &b) const
  {
    const Tensor<1, 2> d = b - a;
    const Tensor<1, 2> normal({-d[1], d[0]});
    Boundary           line;
    line.normal = normal;
    line.offset = normal * a;
    // Where the line meets the cell's edges, and the feet of the vertices
    // on it: a piece along an edge ends at vertices within round-off of
    // the line, where no sign change need be. Splits too many are harmless.
    std::vector<double> ts           = {0.0, 1.0};
    const auto          add_crossing = [&](const Point<2> &x) {
      const double t = (x - a) * d / d.norm_square();
      if (t > 0 && t < 1)
        ts.push_back(t);
    };
    for (const unsigned int direction : {0u, 1u})
      for (const double at : {0.0, 1.0})
        {
          const auto edge = along(direction, at);
          for (const double s : roots(along_boundary(line, edge)))
            add_crossing(Point<2>(evaluate(edge[0], s), evaluate(edge[1], s)));
          for (const double s : {0.0, 1.0})
            add_crossing(Point<2>(evaluate(edge[0], s), evaluate(edge[1], s)));
        }
    std::sort(ts.begin(), ts.end());
    std::vector<std::pair<double, double>> found;
    for (unsigned int k = 0; k + 1 < ts.size(); ++k)
      {
        if ((ts[k + 1] - ts[k]) * d.norm() <= 1e-12 * cell_size)
          continue;
        const Point<2> xi = to_unit(a + 0.5 * (ts[k] + ts[k + 1]) * d);
        bool           in = true;
        for (unsigned int c = 0; c < 2; ++c)
          in = in && xi[c] >= -1e-10 && xi[c] <= 1 + 1e-10;
        if (!in)
          continue;
        if (!found.empty() && found.back().second == ts[k])
          found.back().second = ts[k + 1];
        else
          found.emplace_back(ts[k], ts[k + 1]);
      }
    return found;
  }
} // namespace liftoff
