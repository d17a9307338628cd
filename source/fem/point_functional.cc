#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/fem/point_functional.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

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


    // The cell of `discretization`'s DoFHandler that is `cell`.
    DoFHandler<2>::active_cell_iterator
    dof_cell(const Discretization                         &discretization,
             const Triangulation<2>::active_cell_iterator &cell)
    {
      return {&discretization.triangulation,
              cell->level(),
              cell->index(),
              &discretization.dof_handler};
    }


    // Of this rank's cells at the boundary, the one whose point nearest to
    // `point` (its unit coordinates projected into the cell) is nearest,
    // that point's unit coordinates and its distance (infinite if there is
    // none).
    std::tuple<DoFHandler<2>::active_cell_iterator, Point<2>, double>
    nearest_owned_point(const Discretization &discretization,
                        const Point<2>       &point)
    {
      const Mapping<2> &mapping = discretization.mapping();
      std::tuple<DoFHandler<2>::active_cell_iterator, Point<2>, double> nearest{
        {}, {}, std::numeric_limits<double>::infinity()};
      for (const auto &cell : discretization.locally_owned_cells())
        if (cell->at_boundary())
          try
            {
              const Point<2> unit = GeometryInfo<2>::project_to_unit_cell(
                mapping.transform_real_to_unit_cell(cell, point));
              const double distance =
                point.distance(mapping.transform_unit_to_real_cell(cell, unit));
              if (distance < std::get<2>(nearest))
                nearest = {cell, unit, distance};
            }
          catch (const Mapping<2>::ExcTransformationFailed &)
            {
              // Too far from this cell for its inverse map.
            }
      return nearest;
    }


    // A point of the plate outside every cell: between the support points
    // of the mapping, the mapped rim lies inside a circle (by up to 7.2e-4
    // of the radius on the coarse disc's arcs of degree 2, 7.6 % on its Q1
    // chords), so a point the scene puts on the circle lies just outside
    // the mesh. It is taken at the nearest point of the mesh, which lies
    // within that error of it. Collective.
    std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>
    nearest_holder(const Discretization &discretization, const Point<2> &point)
    {
      const MPI_Comm    comm = discretization.mpi_communicator;
      const std::string outside =
        "The point "
        + tagged("(" + format_point(point[0], point[1]) + ")",
                 Quantity::position)
        + " lies outside the meshed part of the plate.";
      AssertThrow(discretization.geometry().is_on_modelled_part(point),
                  ExcMessage(outside));
      const auto [cell, unit, distance] =
        nearest_owned_point(discretization, point);
      const double nearest = Utilities::MPI::min(distance, comm);
      AssertThrow(std::isfinite(nearest), ExcMessage(outside));
      const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
      const unsigned int holder  = Utilities::MPI::min(
        distance == nearest ? my_rank : numbers::invalid_unsigned_int, comm);
      if (holder != my_rank)
        return {};
      return {cell, unit};
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
    PointCells found;
    if (holder == n_ranks)
      {
        const auto nearest = nearest_holder(discretization, point);
        if (nearest.first.state() == IteratorState::valid)
          found.push_back(nearest);
        return found;
      }
    if (holder != my_rank)
      return found;
    for (const auto &cell : cells)
      found.emplace_back(
        dof_cell(discretization, cell),
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
                                   const unsigned int    component,
                                   const bool            shared_by_slabs)
  {
    // The first cell, and with `shared_by_slabs` one of every other slab
    // (material id) at the point: the mesh is cut along the joints, so the
    // slabs beyond one are reached across its faces, not by the vertices.
    PointCells chosen = holder_cells(discretization, point);
    chosen.resize(std::min<std::size_t>(chosen.size(), 1));
    const SlabLayout &slabs = discretization.geometry().slabs();
    for (unsigned int k = 0; shared_by_slabs && k < chosen.size(); ++k)
      for (const unsigned int f : GeometryInfo<2>::face_indices())
        {
          const auto cell = chosen[k].first;
          const auto unit = chosen[k].second;
          if (!cell->face(f)->at_boundary()
              || slabs.joint_of(cell->face(f)->boundary_id()) == nullptr
              || std::abs(unit[f / 2] - f % 2) > tolerance)
            continue;
          // The neighbour may be refined: its child at the point, the one
          // whose centre is nearest (the point lies on their edges).
          auto across = slabs.across(cell, f);
          while (across->has_children())
            {
              unsigned int nearest = 0;
              for (unsigned int c = 1; c < across->n_children(); ++c)
                if (across->child(c)->center().distance(point)
                    < across->child(nearest)->center().distance(point))
                  nearest = c;
              across = across->child(nearest);
            }
          if (std::none_of(chosen.begin(), chosen.end(), [&](const auto &c) {
                return c.first->material_id() == across->material_id();
              }))
            chosen.emplace_back(
              dof_cell(discretization, across),
              GeometryInfo<2>::project_to_unit_cell(
                discretization.mapping().transform_real_to_unit_cell(across,
                                                                     point)));
        }
    const auto        &fe = discretization.dof_handler.get_fe();
    const unsigned int n  = fe.n_dofs_per_cell();
    weights.reinit(n * chosen.size());
    for (unsigned int k = 0; k < chosen.size(); ++k)
      {
        const auto &[cell, unit_point] = chosen[k];
        FEValues<2> fe_values(discretization.mapping(),
                              fe,
                              Quadrature<2>(unit_point),
                              update_values);
        fe_values.reinit(cell);
        std::vector<types::global_dof_index> dofs(n);
        cell->get_dof_indices(dofs);
        dof_indices.insert(dof_indices.end(), dofs.begin(), dofs.end());
        for (unsigned int i = 0; i < n; ++i)
          if (fe.system_to_component_index(i).first == component)
            weights[k * n + i] = fe_values.shape_value(i, 0) / chosen.size();
      }
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
