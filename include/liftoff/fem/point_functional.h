#pragma once

#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/fem/plate_fields.h>

#include <vector>

namespace liftoff
{
  using namespace dealii;

  /// Cells around a point, each with the point's unit coordinates in it.
  using PointCells =
    std::vector<std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>>;

  /**
   * The value of one solution component at a point, as the linear functional
   * u -> sum_i phi_i(p) u_i. The same object is a probe (apply it to the
   * solution) and a concentrated force (add its weights to a right hand
   * side), so both are a sparse dot product rather than a search of the mesh
   * at every step.
   *
   * Exactly one rank holds the weights: the owner of the cell of the
   * smallest CellId among those containing the point (holder_cells()). A
   * point on a cell edge therefore counts once, whatever the partition.
   */
  class PointFunctional
  {
  public:
    /// With `shared_by_slabs`, a concentrated force: shared equally by
    /// the slabs that meet at `point`, each through its first cell there (a
    /// load on a joint half to each side, as the mirror image takes half of
    /// one on a symmetry plane); else the first cell's value.
    PointFunctional(const Discretization &discretization,
                    const Point<2>       &point,
                    const unsigned int    component       = PlateFields::w,
                    const bool            shared_by_slabs = false);

    /// On the rank that holds `point`, every cell around it (a point on an
    /// edge or a vertex lies in several), this rank's own and its ghosts,
    /// each with the point's unit coordinates in it, the cell of the
    /// smallest CellId first; empty on the other ranks. The holder is the
    /// rank that owns that first cell, so which cell and rank evaluate a
    /// point follows from the mesh alone, not from deal.II's order of the
    /// cells (which differs between a mesh refined in a run and the same
    /// mesh loaded from a checkpoint) nor from the partition. A point of
    /// the plate just outside the mesh (on a circle, whose mapped cells lie
    /// inside it between their support points) is taken at the mesh's
    /// nearest point, in the one cell that has it. Collective; refuses a
    /// point off the meshed part of the plate.
    static PointCells
    holder_cells(const Discretization &discretization, const Point<2> &point);

    /// The first of holder_cells(): the cell the functional uses (an
    /// invalid iterator on the other ranks).
    static std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>
    holder_cell(const Discretization &discretization, const Point<2> &point);

    /// This rank's part of the value; sum over ranks for the value.
    double
    local_value(const LA::MPI::Vector &ghosted_solution) const;

    /// Add factor * phi_i(p) to rhs (call compress(add) afterwards).
    void
    add_to(LA::MPI::Vector                 &rhs,
           const double                     factor,
           const AffineConstraints<double> &constraints) const;

  private:
    std::vector<types::global_dof_index> dof_indices;
    Vector<double>                       weights;
  };
} // namespace liftoff
