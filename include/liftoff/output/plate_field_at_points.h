#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <array>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * w, grad w, psi and grad psi at fixed points of the reference cell, cell
   * after cell, from the cell's dof values. The element is FESystem(base,
   * 3); this evaluates the base element alone (FEValues of the system
   * copies the base's shape values and gradients into a table three times
   * as large at every cell) and sums each component in the order of the
   * system's shape functions, as FEValues does, so the values are
   * FEValues' to the bit.
   */
  class PlateFieldAtPoints
  {
  public:
    PlateFieldAtPoints(const Mapping<2>       &mapping,
                       const FiniteElement<2> &system,
                       const Quadrature<2>    &points);

    /// The fields on `cell` with the dof values `dof_values` (in the order
    /// of the cell's dofs).
    void
    reinit(const DoFHandler<2>::active_cell_iterator &cell,
           const ArrayView<const double>             &dof_values);

    unsigned int
    n_points() const;
    const std::vector<Point<2>> &
    unit_points() const;
    /// The points in real coordinates.
    const std::vector<Point<2>> &
    points() const;

    std::vector<double>       w;
    std::vector<Tensor<1, 2>> grad_w;
    /// psi and its gradient: grad_psi[q][d] is grad psi_d.
    std::vector<Tensor<1, 2>> psi;
    std::vector<Tensor<2, 2>> grad_psi;
    /// The same of a base of its own (BaseLayer, tensionless); empty
    /// without one.
    std::vector<Tensor<2, 2>> grad_psi_base;

  private:
    FEValues<2> base_values;
    /// Per component, the system's shape functions in their order: (index
    /// in the system, index in the base element).
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>>
      shape_functions;
    /// The base's shape values and gradients on the cell, point after point
    /// for each function (phi[b * n + q]), and the sums, point after point
    /// for each of w, dw/dx, dw/dy, psi_x, ...: loops over the points that
    /// the compiler vectorises, each sum still formed in FEValues' order.
    std::vector<double> phi, dphi_x, dphi_y;
    /// sums[3 c + k]: the value (k = 0), d/dx (1) and d/dy (2) of
    /// component c.
    std::vector<std::vector<double>> sums;
  };
} // namespace liftoff
