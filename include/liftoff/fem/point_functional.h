#pragma once

#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <liftoff/fem/discretization.h>

#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The value of one solution component at a point, as the linear functional
   * u -> sum_i phi_i(p) u_i. The same object is a probe (apply it to the
   * solution) and a concentrated force (add its weights to a right hand
   * side), so both are a sparse dot product rather than a search of the mesh
   * at every step.
   *
   * Exactly one rank holds the weights: the lowest rank that owns a cell
   * containing the point. A point on a cell edge therefore counts once,
   * whatever the partition.
   */
  class PointFunctional
  {
  public:
    PointFunctional(const Discretization &discretization,
                    const Point<2>       &point,
                    const unsigned int    component = 0);

    /// This rank's part of the value; sum over ranks for the value.
    /// On the rank that holds `point` (the lowest rank that owns a cell
    /// around it), that cell and the point's unit coordinates in it; an
    /// invalid iterator on the other ranks. Collective; refuses a point
    /// off the meshed part of the plate. A point of the plate just outside
    /// the mesh (on a circle, whose mapped cells lie inside it between
    /// their support points) is taken at the mesh's nearest point.
    static std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>
    holder_cell(const Discretization &discretization, const Point<2> &point);

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
