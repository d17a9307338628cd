#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <liftoff/point_functional.h>

namespace liftoff
{
  PointFunctional::PointFunctional(const Discretization &discretization,
                                   const Point<2>       &point,
                                   const unsigned int    component)
  {
    const auto    &dof_handler = discretization.dof_handler;
    const auto    &fe          = *discretization.fe;
    const MPI_Comm comm        = discretization.mpi_communicator;

    typename DoFHandler<2>::active_cell_iterator found;
    Point<2>                                     unit_point;
    bool                                         is_found = false;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (!cell->bounding_box().point_inside(point, 1e-10))
            continue;
          const Point<2> candidate =
            discretization.mapping.transform_real_to_unit_cell(cell, point);
          if (GeometryInfo<2>::is_inside_unit_cell(candidate, 1e-10))
            {
              found      = cell;
              unit_point = GeometryInfo<2>::project_to_unit_cell(candidate);
              is_found   = true;
              break;
            }
        }

    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int holder =
      Utilities::MPI::min(is_found ? my_rank : n_ranks, comm);
    AssertThrow(holder < n_ranks,
                ExcMessage("The point (" + std::to_string(point[0]) + ", "
                           + std::to_string(point[1])
                           + ") lies outside the meshed part of the plate."));
    if (holder != my_rank)
      return;

    FEValues<2> fe_values(discretization.mapping,
                          fe,
                          Quadrature<2>(unit_point),
                          update_values);
    fe_values.reinit(found);
    dof_indices.resize(fe.n_dofs_per_cell());
    found->get_dof_indices(dof_indices);
    weights.reinit(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == component)
        weights[i] = fe_values.shape_value(i, 0);
  }


  double
  PointFunctional::local_value(const LA::MPI::Vector &ghosted_solution) const
  {
    double value = 0;
    for (unsigned int i = 0; i < dof_indices.size(); ++i)
      value += weights[i] * ghosted_solution(dof_indices[i]);
    return value;
  }


  void
  PointFunctional::add_to(LA::MPI::Vector                 &rhs,
                          const double                     factor,
                          const AffineConstraints<double> &constraints) const
  {
    if (dof_indices.empty())
      return;
    Vector<double> scaled(weights);
    scaled *= factor;
    constraints.distribute_local_to_global(scaled, dof_indices, rhs);
  }
} // namespace liftoff
