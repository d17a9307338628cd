#include <deal.II/lac/vector.h>

#include <liftoff/fem/patch_integrator.h>
#include <liftoff/fem/plate_geometry.h>

#include <algorithm>
#include <sstream>

namespace liftoff
{
  namespace
  {
    /// True for a cell that is the rectangle [x0, x1] x [y0, y1] with its
    /// vertices in deal.II's order, (x0, y0), (x1, y0), (x0, y1), (x1, y1),
    /// so that the reference coordinates are (x - x0) / (x1 - x0) and
    /// (y - y0) / (y1 - y0): every cell of the rectangle. Such cells are
    /// clipped here by hand, exactly; others by CellClipping.
    bool
    is_axis_aligned_rectangle(const DoFHandler<2>::active_cell_iterator &cell)
    {
      const BoundingBox<2> box       = cell->bounding_box();
      const Point<2>      &lo        = box.get_boundary_points().first;
      const Point<2>      &hi        = box.get_boundary_points().second;
      const double         tolerance = 1e-12 * cell->diameter();
      return (cell->vertex(0) - lo).norm() <= tolerance
             && (cell->vertex(1) - Point<2>(hi[0], lo[1])).norm() <= tolerance
             && (cell->vertex(2) - Point<2>(lo[0], hi[1])).norm() <= tolerance
             && (cell->vertex(3) - hi).norm() <= tolerance;
    }

    /// A box that holds the cell: its vertices' box, and for other cells
    /// than rectangles a quarter of its diameter around, more than a curved
    /// edge bulges beyond its vertices on any mesh of a disc or annulus.
    BoundingBox<2>
    reach_of(const DoFHandler<2>::active_cell_iterator &cell,
             const bool                                 rectangle)
    {
      BoundingBox<2> box = cell->bounding_box();
      if (!rectangle)
        box.extend(0.25 * cell->diameter());
      return box;
    }

    /// The share of a line along face `f` that the cell carries: half of one
    /// between two cells (the other half from the cell behind it), on a
    /// joint (the other half from the slab across it, or on a symmetry
    /// plane from the mirror image) or on a symmetry plane (the modelled
    /// part's share), all of one on an edge.
    double
    share_along_face(const DoFHandler<2>::active_cell_iterator &cell,
                     const unsigned int                         f,
                     const PlateGeometry                       &geometry)
    {
      // The planes' ids mean planes only on a half or quarter model (a mesh
      // file's tags may take any number; it is always a full model).
      const auto face = cell->face(f);
      const bool on_plane =
        geometry.symmetry() != Symmetry::full
        && (face->boundary_id() == PlateGeometry::x_symmetry_plane
            || face->boundary_id() == PlateGeometry::y_symmetry_plane);
      const bool on_joint =
        face->at_boundary()
        && geometry.slabs().joint_of(face->boundary_id()) != nullptr;
      return (!face->at_boundary() || on_plane || on_joint) ? 0.5 : 1.0;
    }

    /// A 1d rule on [0, 1] moved onto [a, b].
    Quadrature<1>
    on_interval(const Quadrature<1> &rule, const double a, const double b)
    {
      std::vector<Point<1>> points;
      std::vector<double>   weights;
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          points.emplace_back(a + (b - a) * rule.point(q)[0]);
          weights.push_back((b - a) * rule.weight(q));
        }
      return Quadrature<1>(points, weights);
    }
    /// The ends in x of the slices of disc ∩ cell (cell [x0, x1] x [y0,
    /// y1], [a, b] its x-range inside the disc): a, b and where the circle
    /// crosses y = y0 or y = y1 between them. Inside a slice each bound of
    /// y is either a cell edge or the circle, smoothly.
    std::vector<double>
    slice_ends(const double    a,
               const double    b,
               const double    y0,
               const double    y1,
               const Point<2> &c,
               const double    r)
    {
      std::vector<double> ends = {a, b};
      for (const double y : {y0, y1})
        if (std::abs(y - c[1]) < r)
          for (const double sign : {-1.0, 1.0})
            {
              const double x =
                c[0] + sign * std::sqrt(r * r - (y - c[1]) * (y - c[1]));
              if (x > a && x < b)
                ends.push_back(x);
            }
      std::sort(ends.begin(), ends.end());
      return ends;
    }

    /// The part [t0, t1] of the segment a + t (b - a), 0 <= t <= 1, that
    /// lies in the box (t0 >= t1: none), by clipping against each slab.
    std::pair<double, double>
    clipped(const Point<2>       &a,
            const Point<2>       &b,
            const BoundingBox<2> &box,
            const double          tolerance)
    {
      double t0 = 0, t1 = 1;
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double lo   = box.lower_bound(d) - tolerance,
                       hi   = box.upper_bound(d) + tolerance;
          const double step = b[d] - a[d];
          if (std::abs(step) <= tolerance)
            {
              if (a[d] < lo || a[d] > hi)
                return {1, 0};
              continue;
            }
          const double s0 = (lo - a[d]) / step, s1 = (hi - a[d]) / step;
          t0 = std::max(t0, std::min(s0, s1));
          t1 = std::min(t1, std::max(s0, s1));
        }
      return {t0, t1};
    }
  } // namespace


  PatchIntegrator::PatchIntegrator(const Discretization &discretization,
                                   const unsigned int    n_arc_points)
      : discretization(discretization)
      , cell_rule(discretization.dof_handler.get_fe().degree + 2)
      , line_rule(discretization.dof_handler.get_fe().degree + 2)
      , arc_rule(n_arc_points > 0 ? n_arc_points : default_arc_points)
      , column_rule(2 * arc_rule.size())
  {}


  PatchIntegrator &
  PatchIntegrator::on_layer(const unsigned int new_layer)
  {
    layer = new_layer;
    return *this;
  }


  BoundingBox<2>
  PatchIntegrator::reference_part(
    const DoFHandler<2>::active_cell_iterator &cell,
    const BoundingBox<2>                      &patch) const
  {
    const BoundingBox<2> rectangle = cell->bounding_box();
    Point<2>             lo, hi;
    for (unsigned int d = 0; d < 2; ++d)
      {
        const double x0 = rectangle.lower_bound(d);
        const double h  = rectangle.side_length(d);
        // Ends within round-off of the cell's edges are on them.
        const auto to_reference = [&](const double x) {
          const double xi = (x - x0) / h;
          return (xi < 1e-12 ? 0.0 : (xi > 1 - 1e-12 ? 1.0 : xi));
        };
        lo[d] = to_reference(patch.lower_bound(d));
        hi[d] = to_reference(patch.upper_bound(d));
      }
    return BoundingBox<2>(std::make_pair(lo, hi));
  }


  PatchIntegrator::Cover
  PatchIntegrator::cover(const DoFHandler<2>::active_cell_iterator &cell,
                         const BoundingBox<2>                      &patch) const
  {
    // Cells inside the patch or away from it are decided on boxes that
    // hold them, whatever their shape: only the cut cells need the
    // clipping.
    const bool           rectangle = is_axis_aligned_rectangle(cell);
    const BoundingBox<2> box       = reach_of(cell, rectangle);
    const double         tolerance = 1e-12 * cell->diameter();
    bool                 inside = true, away = false;
    for (unsigned int d = 0; d < 2; ++d)
      {
        inside = inside
                 && box.lower_bound(d) >= patch.lower_bound(d) - tolerance
                 && box.upper_bound(d) <= patch.upper_bound(d) + tolerance;
        away = away || box.lower_bound(d) >= patch.upper_bound(d) - tolerance
               || box.upper_bound(d) <= patch.lower_bound(d) + tolerance;
      }
    Cover result;
    if (away)
      return result;
    result.whole = inside;
    if (inside)
      return result;
    if (!rectangle)
      {
        // The box as four half-planes; its corners and centre are seeds.
        std::vector<CellClipping::Boundary> sides(4);
        std::vector<Point<2>>               seeds = {patch.center()};
        for (unsigned int d = 0; d < 2; ++d)
          {
            sides[2 * d].normal[d]     = 1;
            sides[2 * d].offset        = patch.lower_bound(d);
            sides[2 * d + 1].normal[d] = -1;
            sides[2 * d + 1].offset    = -patch.upper_bound(d);
          }
        for (unsigned int v = 0; v < 4; ++v)
          seeds.push_back(patch.vertex(v));
        return clipped_cover(cell, sides, seeds);
      }
    const BoundingBox<2> part = reference_part(cell, patch);
    result.part               = Quadrature<2>(
      on_interval(line_rule, part.lower_bound(0), part.upper_bound(0)),
      on_interval(line_rule, part.lower_bound(1), part.upper_bound(1)));
    return result;
  }


  PatchIntegrator::Cover
  PatchIntegrator::cover(const DoFHandler<2>::active_cell_iterator &cell,
                         const Disc                                &disc) const
  {
    const bool           rectangle = is_axis_aligned_rectangle(cell);
    const BoundingBox<2> box       = reach_of(cell, rectangle);
    const Point<2>      &c         = disc.centre;
    const double         r         = disc.radius;
    Cover                result;
    // Most cells are away from the disc: its bounding box tells them.
    for (unsigned int d = 0; d < 2; ++d)
      if (box.lower_bound(d) >= c[d] + r || box.upper_bound(d) <= c[d] - r)
        return result;
    bool inside = true;
    for (unsigned int v = 0; v < 4; ++v)
      inside =
        inside
        && ((rectangle ? cell->vertex(v) : box.vertex(v)) - c).norm() <= r;
    result.whole = inside;
    if (inside)
      return result;
    if (!rectangle)
      {
        CellClipping::Boundary circle;
        circle.is_circle            = true;
        circle.centre               = c;
        circle.radius               = r;
        std::vector<Point<2>> seeds = {c};
        for (unsigned int d = 0; d < 2; ++d)
          for (const double sign : {-1.0, 1.0})
            seeds.push_back(c + sign * r * Point<2>::unit_vector(d));
        return clipped_cover(cell, {circle}, seeds);
      }

    result.part = slices_of(cell, disc);
    return result;
  }


  Quadrature<2>
  PatchIntegrator::slices_of(const DoFHandler<2>::active_cell_iterator &cell,
                             const Disc &disc) const
  {
    const BoundingBox<2> box = cell->bounding_box();
    const Point<2>      &c   = disc.centre;
    const double         r   = disc.radius;
    const double         x0 = box.lower_bound(0), x1 = box.upper_bound(0),
                 y0 = box.lower_bound(1), y1 = box.upper_bound(1);
    const double a = std::max(x0, c[0] - r), b = std::min(x1, c[0] + r);
    if (b - a <= 1e-12 * cell->diameter())
      return Quadrature<2>();
    const std::vector<double> ends      = slice_ends(a, b, y0, y1, c, r);
    const auto                arc_angle = [&](const double x) {
      return std::asin(std::clamp((x - c[0]) / r, -1.0, 1.0));
    };
    std::vector<Point<2>> points;
    std::vector<double>   weights;
    const double          area = box.volume();
    for (unsigned int k = 0; k + 1 < ends.size(); ++k)
      {
        const Quadrature<1> in_t =
          on_interval(arc_rule, arc_angle(ends[k]), arc_angle(ends[k + 1]));
        for (unsigned int q = 0; q < in_t.size(); ++q)
          {
            const double t    = in_t.point(q)[0];
            const double x    = c[0] + r * std::sin(t);
            const double half = r * std::cos(t);
            const double lo   = std::max(y0, c[1] - half),
                         hi   = std::min(y1, c[1] + half);
            if (hi <= lo)
              continue;
            const Quadrature<1> in_y = on_interval(line_rule, lo, hi);
            for (unsigned int j = 0; j < in_y.size(); ++j)
              {
                // Reference coordinates of a rectangle; dx = r cos(t) dt.
                points.emplace_back((x - x0) / (x1 - x0),
                                    (in_y.point(j)[0] - y0) / (y1 - y0));
                weights.push_back(in_t.weight(q) * half * in_y.weight(j)
                                  / area);
              }
          }
      }
    return Quadrature<2>(points, weights);
  }


  PatchIntegrator::Cover
  PatchIntegrator::clipped_cover(
    const DoFHandler<2>::active_cell_iterator &cell,
    const std::vector<CellClipping::Boundary> &region,
    const std::vector<Point<2>>               &seeds) const
  {
    return CellClipping(discretization.mapping(), cell)
      .inside(region, seeds, line_rule, column_rule);
  }


  PatchIntegrator::Cover
  PatchIntegrator::cover(const DoFHandler<2>::active_cell_iterator &cell,
                         const Segment &segment) const
  {
    Cover          result;
    const Point<2> a = segment.start, b = segment.end;
    const double   tolerance = 1e-12 * cell->diameter();
    const bool     rectangle = is_axis_aligned_rectangle(cell);
    const auto [t0, t1] = clipped(a, b, reach_of(cell, rectangle), tolerance);
    const double length = (b - a).norm();
    if ((t1 - t0) * length <= tolerance)
      return result;
    if (!rectangle)
      return cover_along(cell, segment);

    // A piece along a face is met again from the cell behind it, unless
    // the face is a plate edge.
    const BoundingBox<2> box    = cell->bounding_box();
    double               weight = 1;
    for (unsigned int d = 0; d < 2; ++d)
      for (unsigned int side = 0; side < 2; ++side)
        {
          const double at = side == 0 ? box.lower_bound(d) : box.upper_bound(d);
          if (std::abs(a[d] - at) <= tolerance
              && std::abs(b[d] - at) <= tolerance)
            weight =
              share_along_face(cell, 2 * d + side, discretization.geometry());
        }
    const Quadrature<1>   in_t = on_interval(line_rule, t0, t1);
    std::vector<Point<2>> points;
    std::vector<double>   weights;
    for (unsigned int q = 0; q < in_t.size(); ++q)
      {
        const Point<2> x = a + in_t.point(q)[0] * (b - a);
        Point<2>       unit;
        for (unsigned int d = 0; d < 2; ++d)
          unit[d] = std::clamp((x[d] - box.lower_bound(d)) / box.side_length(d),
                               0.0,
                               1.0);
        points.push_back(unit);
        // FEValues multiplies by the cell's area; ds = |b - a| dt.
        weights.push_back(weight * in_t.weight(q) * length / box.volume());
      }
    result.part = Quadrature<2>(points, weights);
    return result;
  }


  PatchIntegrator::Cover
  PatchIntegrator::cover_along(const DoFHandler<2>::active_cell_iterator &cell,
                               const Segment &segment) const
  {
    const Point<2>        a = segment.start, b = segment.end;
    const double          length = (b - a).norm();
    const CellClipping    clipping(discretization.mapping(), cell);
    std::vector<Point<2>> points;
    std::vector<double>   weights;
    for (const auto &[t0, t1] : clipping.pieces(a, b))
      {
        // A piece along a (straight) face: its ends and middle on it.
        std::array<Point<2>, 3> marks;
        for (unsigned int k = 0; k < 3; ++k)
          marks[k] = clipping.to_unit(a + (t0 + k * (t1 - t0) / 2) * (b - a));
        double weight = 1;
        for (unsigned int d = 0; d < 2; ++d)
          for (unsigned int side = 0; side < 2; ++side)
            {
              bool on_face = true;
              for (const Point<2> &unit : marks)
                on_face = on_face && std::abs(unit[d] - side) <= 1e-10;
              if (on_face)
                weight = share_along_face(cell,
                                          2 * d + side,
                                          discretization.geometry());
            }
        const Quadrature<1> in_t = on_interval(line_rule, t0, t1);
        for (unsigned int q = 0; q < in_t.size(); ++q)
          {
            Point<2> unit = clipping.to_unit(a + in_t.point(q)[0] * (b - a));
            for (unsigned int d = 0; d < 2; ++d)
              unit[d] = std::clamp(unit[d], 0.0, 1.0);
            points.push_back(unit);
            // FEValues multiplies by |det J|; ds = |b - a| dt.
            weights.push_back(weight * in_t.weight(q) * length
                              / clipping.jacobian_determinant(unit));
          }
      }
    Cover result;
    result.part = Quadrature<2>(points, weights);
    return result;
  }


  void
  PatchIntegrator::for_each_covered_cell(
    const CoverOf                                  &cover_of,
    const UpdateFlags                               flags,
    const std::function<void(const DoFHandler<2>::active_cell_iterator &,
                             const FEValues<2> &)> &work) const
  {
    const Discretization &disc = discretization;
    FEValues<2>           whole_cell(disc.mapping(),
                           disc.dof_handler.get_fe(),
                           cell_rule,
                           flags);
    for (const auto &cell : disc.locally_owned_cells())
      {
        const Cover covered = cover_of(cell);
        if (covered.whole)
          {
            whole_cell.reinit(cell);
            work(cell, whole_cell);
          }
        else if (covered.part.size() > 0)
          {
            // A cut cell: the rule differs from cell to cell, and so do the
            // shape values at its points.
            FEValues<2> cut_cell(disc.mapping(),
                                 disc.dof_handler.get_fe(),
                                 covered.part,
                                 flags);
            cut_cell.reinit(cell);
            work(cell, cut_cell);
          }
      }
  }


  void
  PatchIntegrator::add_covered(const Density   &density,
                               const CoverOf   &cover_of,
                               LA::MPI::Vector &vector) const
  {
    const auto        &fe     = discretization.dof_handler.get_fe();
    const unsigned int n_dofs = fe.n_dofs_per_cell();
    Vector<double>     cell_rhs(n_dofs);
    std::vector<types::global_dof_index> dof_indices(n_dofs);
    for_each_covered_cell(
      cover_of,
      update_values | update_quadrature_points | update_JxW_values,
      [&](const DoFHandler<2>::active_cell_iterator &cell,
          const FEValues<2>                         &values) {
        cell_rhs = 0;
        for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
          {
            const std::array<double, 3> f = density(values.quadrature_point(q));
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                // The density acts on its layer's (w, psi_x, psi_y) only.
                const unsigned int c = fe.system_to_component_index(i).first;
                if (c / PlateFields::per_layer == layer)
                  cell_rhs(i) += f[c % PlateFields::per_layer]
                                 * values.shape_value(i, q) * values.JxW(q);
              }
          }
        cell->get_dof_indices(dof_indices);
        discretization.constraints.distribute_local_to_global(cell_rhs,
                                                              dof_indices,
                                                              vector);
      });
    vector.compress(VectorOperation::add);
  }


  std::vector<Point<2>>
  PatchIntegrator::covered_points(const CoverOf &cover_of) const
  {
    std::vector<Point<2>> points;
    for_each_covered_cell(cover_of,
                          update_quadrature_points,
                          [&](const DoFHandler<2>::active_cell_iterator &,
                              const FEValues<2> &values) {
                            for (const auto &p : values.get_quadrature_points())
                              points.push_back(p);
                          });
    return points;
  }


  template <class Patch>
  PatchIntegrator::CoverOf
  PatchIntegrator::covering(const Patch &patch) const
  {
    return [this, &patch](const DoFHandler<2>::active_cell_iterator &cell) {
      return cover(cell, patch);
    };
  }


  void
  PatchIntegrator::add(const Density        &density,
                       const BoundingBox<2> &patch,
                       LA::MPI::Vector      &vector) const
  {
    add_covered(density, covering(patch), vector);
  }


  void
  PatchIntegrator::add(const Density &density, LA::MPI::Vector &vector) const
  {
    add_covered(
      density,
      [](const DoFHandler<2>::active_cell_iterator &) {
        Cover whole;
        whole.whole = true;
        return whole;
      },
      vector);
  }


  void
  PatchIntegrator::add(const Density   &density,
                       const Disc      &disc,
                       LA::MPI::Vector &vector) const
  {
    add_covered(density, covering(disc), vector);
  }


  std::vector<Point<2>>
  PatchIntegrator::quadrature_points(const BoundingBox<2> &patch) const
  {
    return covered_points(covering(patch));
  }


  std::vector<Point<2>>
  PatchIntegrator::quadrature_points(const Disc &disc) const
  {
    return covered_points(covering(disc));
  }


  double
  PatchIntegrator::length_inside(const Segment        &segment,
                                 const BoundingBox<2> &box)
  {
    const auto [t0, t1] = clipped(segment.start, segment.end, box, 0);
    return std::max(0.0, t1 - t0) * segment.start.distance(segment.end);
  }


  void
  PatchIntegrator::add(const Density   &density,
                       const Segment   &segment,
                       LA::MPI::Vector &vector) const
  {
    add_covered(density, covering(segment), vector);
  }


  std::vector<Point<2>>
  PatchIntegrator::quadrature_points(const Segment &segment) const
  {
    return covered_points(covering(segment));
  }
} // namespace liftoff
