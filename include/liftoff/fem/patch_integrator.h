#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/cell_clipping.h>
#include <liftoff/fem/discretization.h>

#include <array>
#include <functional>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * Integrals of a density against the shape functions over the part of a
   * rectangle (a pressure patch) that lies in the meshed part:
   * int_{patch ∩ cell} f_c phi_i^c over every cell of this rank.
   *
   * The density is commonly discontinuous at the patch's edges, which need
   * not follow cell edges; a Gauss rule on the whole cell would sample that
   * jump (a patch smaller than a cell got 21.7 times its force, or none).
   * So each cell is clipped: a cell inside the patch keeps the ordinary
   * rule, a cell that the patch cuts gets the same Gauss rule mapped onto
   * patch ∩ cell, and a cell outside is skipped (also one that touches the
   * patch along a line only). With n = p + 2 points per
   * direction (p the element's degree) the integral is exact for
   * intensities of degree up to p + 3 in each of x and y, and converges
   * for smooth ones, whatever the patch's position and size.
   *
   * Cells inside and outside are told by boxes that hold them. The cut
   * cells of the rectangle (axis-aligned rectangles) are clipped here by
   * hand, exactly; the skewed and curved cells of mesh files, discs and
   * annuli by CellClipping, which follows the cell's polynomial map.
   *
   * A disc (a tyre's contact area) is cut from each cell it covers in
   * part by slices in x: on each slice the chord's ends y = y_c +- sqrt(r^2
   * - (x - x_c)^2) or the cell's edges bound y, and the slices end where
   * the circle crosses the cell's edges, so that inside each slice the
   * bounds are smooth. x = x_c + r sin(t) removes the square root's
   * infinite slope at the disc's left and right ends; in t the integrand
   * is then analytic and a Gauss rule of n_arc points converges
   * exponentially, and in y the same n = p + 2 point rule is exact.
   *
   * A segment (a line load) is a patch of no width: the same Gauss rule
   * in its parameter t on the piece that each cell clips from it, weighted
   * by the piece's length instead of an area, so that the integral is exact
   * for intensities of degree up to 3 along any straight line. A piece on
   * a face between two cells is counted half from each side; on a plate
   * edge wholly, and on a symmetry plane half, the modelled part's share.
   *
   * Used for pressures, moving patches (another rectangle or disc at every
   * step), line loads and the body force (the patch is then the whole
   * plate).
   */
  class PatchIntegrator
  {
  public:
    /// The density (f_w, f_psi_x, f_psi_y) at a point of the plate.
    using Density = std::function<std::array<double, 3>(const Point<2> &)>;

    /// A disc of centre and radius.
    struct Disc
    {
      Point<2> centre;
      double   radius;
    };

    /// A straight line from `start` to `end`.
    struct Segment
    {
      Point<2> start;
      Point<2> end;
    };

    /// `n_arc_points`: the Gauss rule in t = asin((x - x_c) / r) on the
    /// slices of a disc (0: default_arc_points).
    explicit PatchIntegrator(const Discretization &discretization,
                             const unsigned int    n_arc_points = 0);

    /// Enough for a relative error below 1e-12 of a disc's load vector on
    /// Q1 and Q2 (doc/model.md, "Moving loads"; test moving_loads).
    static constexpr unsigned int default_arc_points = 16;

    /// vector += int_{patch ∩ mesh} f_c phi_i^c (owned entries, the
    /// constraints applied). Collective (compresses `vector`).
    void
    add(const Density        &density,
        const BoundingBox<2> &patch,
        LA::MPI::Vector      &vector) const;
    /// The same over the whole meshed part (every cell wholly).
    void
    add(const Density &density, LA::MPI::Vector &vector) const;
    /// The same over disc ∩ mesh.
    void
    add(const Density   &density,
        const Disc      &disc,
        LA::MPI::Vector &vector) const;

    /// The same along segment ∩ mesh, per unit length.
    void
    add(const Density   &density,
        const Segment   &segment,
        LA::MPI::Vector &vector) const;

    /// The length of the part of `segment` inside `box`.
    static double
    length_inside(const Segment &segment, const BoundingBox<2> &box);

    /// The points at which add() evaluates the density on this rank's
    /// cells, for checks of where a load is used.
    std::vector<Point<2>>
    quadrature_points(const BoundingBox<2> &patch) const;
    std::vector<Point<2>>
    quadrature_points(const Disc &disc) const;
    std::vector<Point<2>>
    quadrature_points(const Segment &segment) const;

    /// The integrals of the densities go to the fields of `layer`
    /// (PlateFields: 0 the slab, the default; 1 a base).
    PatchIntegrator &
    on_layer(const unsigned int layer);
    /// The mesh it integrates on.
    const Discretization &
    mesh() const
    {
      return discretization;
    }

  private:
    const Discretization &discretization;
    unsigned int          layer = 0;
    /// The ordinary rule of a cell and the 1d rule its clipped rules are
    /// made of (the same number of points).
    const QGauss<2> cell_rule;
    const QGauss<1> line_rule;
    /// The rule in t on the slices of a disc.
    const QGauss<1> arc_rule;
    /// The rule across the columns of a cut cell that is not an axis-aligned
    /// rectangle (CellClipping): twice arc_rule's points, which a disc
    /// needs there for a relative error below 1e-12 (test clipped_cells:
    /// 5.6e-11 with 16, 3e-15 with 32).
    const QGauss<1> column_rule;

    /// How a patch covers a cell: wholly (the cell's own rule), in part
    /// (`part`, a rule in reference coordinates), or not at all (neither).
    using Cover = CellClipping::Result;
    using CoverOf =
      std::function<Cover(const DoFHandler<2>::active_cell_iterator &)>;

    Cover
    cover(const DoFHandler<2>::active_cell_iterator &cell,
          const BoundingBox<2>                      &patch) const;
    Cover
    cover(const DoFHandler<2>::active_cell_iterator &cell,
          const Disc                                &disc) const;
    Cover
    cover(const DoFHandler<2>::active_cell_iterator &cell,
          const Segment                             &segment) const;
    /// The rule of disc ∩ cell on an axis-aligned rectangle that the disc
    /// cuts: slices in x.
    Quadrature<2>
    slices_of(const DoFHandler<2>::active_cell_iterator &cell,
              const Disc                                &disc) const;
    /// The cover of a cell other than an axis-aligned rectangle.
    Cover
    clipped_cover(const DoFHandler<2>::active_cell_iterator &cell,
                  const std::vector<CellClipping::Boundary> &region,
                  const std::vector<Point<2>>               &seeds) const;
    Cover
    cover_along(const DoFHandler<2>::active_cell_iterator &cell,
                const Segment                             &segment) const;
    /// cover() of `patch` (a rectangle or a disc) for every cell.
    template <class Patch>
    CoverOf
    covering(const Patch &patch) const;

    /// patch ∩ cell in the reference coordinates of a cell that the patch
    /// cuts: a sub-rectangle of the unit square.
    BoundingBox<2>
    reference_part(const DoFHandler<2>::active_cell_iterator &cell,
                   const BoundingBox<2>                      &patch) const;

    /// Calls `work` with FEValues (`flags`) on the rule of patch ∩ cell for
    /// every cell of this rank that the patch covers.
    void
    for_each_covered_cell(
      const CoverOf                                  &cover_of,
      const UpdateFlags                               flags,
      const std::function<void(const DoFHandler<2>::active_cell_iterator &,
                               const FEValues<2> &)> &work) const;
    void
    add_covered(const Density   &density,
                const CoverOf   &cover_of,
                LA::MPI::Vector &vector) const;
    std::vector<Point<2>>
    covered_points(const CoverOf &cover_of) const;
  };
} // namespace liftoff
