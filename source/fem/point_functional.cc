#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <liftoff/fem/point_functional.h>

#include <algorithm>

namespace liftoff
{
  namespace
  {
    // How far outside a cell, in its unit coordinates, a point still counts
    // as inside: round-off of points on cell edges and the plate's edges.
    constexpr double tolerance = 1e-10;

    // The search trees find a cell around the point; a point on an edge or
    // a vertex lies in its neighbours too, some of them perhaps of other
    // ranks. This rank's cells that hold it (its own and its ghosts), the
    // smallest CellId first: a rule of the mesh alone, where deal.II's own
    // order of the cells depends on how the mesh was reached (refined in
    // the run, or loaded from a checkpoint). A rank that owns one of them
    // has all of them, owned or ghost, since they share the point.
    std::vector<Triangulation<2>::active_cell_iterator>
    cells_around(const Discretization &discretization, const Point<2> &point)
    {
      const auto first = GridTools::find_active_cell_around_point(
        discretization.grid_cache(),
        point,
        typename Triangulation<2>::active_cell_iterator(),
        {},
        tolerance);
      std::vector<Triangulation<2>::active_cell_iterator> cells;
      if (first.first.state() == IteratorState::valid)
        for (const auto &[cell, unit] :
             GridTools::find_all_active_cells_around_point(
               discretization.mapping(),
               discretization.triangulation,
               point,
               tolerance,
               first))
          if (!cell->is_artificial())
            cells.push_back(cell);
      std::sort(cells.begin(), cells.end(), [](const auto &a, const auto &b) {
        return a->id() < b->id();
      });
      return cells;
    }
  } // namespace


  PointCells
  PointFunctional::holder_cells(const Discretization &discretization,
                                const Point<2>       &point)
  {
    const MPI_Comm comm  = discretization.mpi_communicator;
    const auto     cells = cells_around(discretization, point);
    // The owner of the first cell, whatever the partition.
    const bool holds = !cells.empty() && cells.front()->is_locally_owned();

    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int holder =
      Utilities::MPI::min(holds ? my_rank : n_ranks, comm);
    AssertThrow(holder < n_ranks,
                ExcMessage("The point (" + std::to_string(point[0]) + ", "
                           + std::to_string(point[1])
                           + ") lies outside the meshed part of the plate."));
    PointCells found;
    if (holder != my_rank)
      return found;
    for (const auto &cell : cells)
      found.emplace_back(
        DoFHandler<2>::active_cell_iterator(&discretization.triangulation,
                                            cell->level(),
                                            cell->index(),
                                            &discretization.dof_handler),
        GeometryInfo<2>::project_to_unit_cell(
          discretization.mapping().transform_real_to_unit_cell(cell, point)));
    return found;
  }


  std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>
  PointFunctional::holder_cell(const Discretization &discretization,
                               const Point<2>       &point)
  {
    const auto cells = holder_cells(discretization, point);
    if (cells.empty())
      return {};
    return cells.front();
  }


  PointFunctional::PointFunctional(const Discretization &discretization,
                                   const Point<2>       &point,
                                   const unsigned int    component)
  {
    const auto &fe                = discretization.dof_handler.get_fe();
    const auto [cell, unit_point] = holder_cell(discretization, point);
    if (cell.state() != IteratorState::valid)
      return;

    FEValues<2> fe_values(discretization.mapping(),
                          fe,
                          Quadrature<2>(unit_point),
                          update_values);
    fe_values.reinit(cell);
    dof_indices.resize(fe.n_dofs_per_cell());
    cell->get_dof_indices(dof_indices);
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
