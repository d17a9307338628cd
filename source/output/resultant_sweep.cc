#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_values.h>

#include <liftoff/contact/contact_law.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/stress_resultants.h>

#include <cmath>

namespace liftoff
{
  ResultantSweep::ResultantSweep(const MindlinPlate     &plate,
                                 const Discretization   &discretization,
                                 const ContactLaw       &law,
                                 const LA::MPI::Vector  &ghosted_solution,
                                 const FreeBendingField &free_bending)
      : plate(plate)
      , discretization(discretization)
      , law(law)
      , solution(ghosted_solution)
      , thermal_bending(free_bending)
  {}


  const FreeBendingField &
  ResultantSweep::free_bending() const
  {
    return thermal_bending;
  }


  const std::vector<Point<2>> &
  ResultantSweep::points() const
  {
    compute();
    return point_list;
  }


  const std::vector<ResultantSweep::Values> &
  ResultantSweep::values() const
  {
    compute();
    return value_list;
  }


  void
  ResultantSweep::compute() const
  {
    if (is_computed)
      return;
    is_computed                 = true;
    const Discretization  &disc = discretization;
    const StressResultants resultants(plate,
                                      disc.mapping(),
                                      disc.element().shear_integration(),
                                      solution,
                                      thermal_bending);
    const FE_DGQ<2>        output_points(disc.element().degree());
    FEValues<2>            fe_values(
      disc.mapping(),
      disc.dof_handler.get_fe(),
      Quadrature<2>(output_points.get_unit_support_points()),
      update_values | update_gradients | update_quadrature_points);
    const unsigned int n = fe_values.n_quadrature_points;
    // Kept from cell to cell; the cell's dofs are read from the vector once.
    Vector<double>                    dof_values(fe_values.dofs_per_cell);
    std::vector<double>               w(n);
    StressResultants::PrincipalValues principal;
    point_list.clear();
    value_list.clear();
    point_list.reserve(n * disc.triangulation.n_active_cells());
    value_list.reserve(point_list.capacity());
    // In the order of the cells' CellId: of two equal extremes (a vertex
    // of several cells) the first is taken, which must not depend on how
    // the mesh was reached (refined in the run or loaded at a resume).
    for (const auto &cell : disc.locally_owned_cells())
      {
        fe_values.reinit(cell);
        cell->get_dof_values(solution, dof_values);
        const ArrayView<double> dofs = make_array_view(dof_values);
        resultants.principal(cell, fe_values, dofs, principal);
        fe_values[FEValuesExtractors::Scalar(0)]
          .get_function_values_from_local_dof_values(dofs, w);
        const auto &x = fe_values.get_quadrature_points();
        for (unsigned int k = 0; k < n; ++k)
          {
            const double g = (law.has_gap() ? law.gap_at(x[k]) : 0.0);
            Values       v;
            v.w        = w[k];
            v.pressure = law.spring_pressure(w[k] - g);
            v.m_1      = principal.m_1[k];
            v.m_2      = principal.m_2[k];
            v.shear    = std::hypot(principal.q[k][0], principal.q[k][1]);
            point_list.push_back(x[k]);
            value_list.push_back(v);
          }
      }
  }
} // namespace liftoff
