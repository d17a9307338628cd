#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/numerics/error_estimator.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/selection.h>
#include <liftoff/fem/mesh_refinement.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace liftoff
{
  namespace
  {
    enum class Indicator
    {
      kelly,
      contact_front,
      loads
    };
    // "point loads" is the name of the indicator from before patches and
    // moving loads were refined too.
    const Selection<Indicator> indicators = {{"kelly", Indicator::kelly},
                                             {"contact front",
                                              Indicator::contact_front},
                                             {"loads", Indicator::loads},
                                             {"point loads", Indicator::loads}};

    // Whether a region meets a cell's bounding box, up to a tolerance (a
    // point load on a vertex or an edge belongs to every cell around it).
    bool
    is_under(const TriaActiveIterator<CellAccessor<2>> &cell,
             const BoundingBox<2>                      &region)
    {
      const BoundingBox<2> box       = cell->bounding_box();
      const double         tolerance = 1e-10 * cell->diameter();
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double side = box.upper_bound(d) - box.lower_bound(d);
          if (box.lower_bound(d) - tolerance * side > region.upper_bound(d)
              || box.upper_bound(d) + tolerance * side < region.lower_bound(d))
            return false;
        }
      return true;
    }

    bool
    is_under_any(const TriaActiveIterator<CellAccessor<2>> &cell,
                 const std::vector<BoundingBox<2>>         &regions)
    {
      return std::any_of(regions.begin(), regions.end(), [&](const auto &r) {
        return is_under(cell, r);
      });
    }
  } // namespace


  void
  MeshRefinement::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    declare_when_parameters(prm);
    declare_where_parameters(prm);
    prm.leave_subsection();
  }


  void
  MeshRefinement::declare_when_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Adaptive",
                      "false",
                      Patterns::Bool(),
                      "Refine the mesh where the indicators ask for it and "
                      "coarsen it where nothing happens (doc/adaptivity.md). "
                      "false: the uniform mesh of Discretization throughout.");
    prm.declare_entry("Interval",
                      "10",
                      Patterns::Integer(1),
                      "Dynamic analysis: adapt the mesh after every this many "
                      "time steps. Each new mesh costs one assembly and one "
                      "factorisation.");
    prm.declare_entry("Static cycles",
                      "3",
                      Patterns::Integer(0, 30),
                      "Static analysis: adapt the mesh and solve again this "
                      "many times after the first solve.");
    prm.declare_entry("Initial refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Refine the cells holding a point load this many times "
                      "before the first step (or the first static solve), "
                      "up to Maximum level. A dynamic run that does not "
                      "start at rest also adapts the mesh this many times to "
                      "its initial displacement, by the Indicators, before "
                      "the first step: an error in the initial state is "
                      "carried by the waves to the end of the run.");
  }


  void
  MeshRefinement::declare_where_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Indicators",
                      "kelly, contact front, point loads",
                      Patterns::MultipleSelection(indicators.names()),
                      "What decides where to refine: kelly, the jumps of the "
                      "gradients of w, psi_x and psi_y across faces "
                      "(KellyErrorEstimator), refined and coarsened by the "
                      "fractions below; contact front, the cells whose Gauss "
                      "points are partly in contact and the cells within "
                      "Front band of them; loads (or point loads, its former "
                      "name), the cells under a point, patch or Segment line "
                      "load, kept at Maximum level with the front's, and "
                      "those under the k-th coming window of Interval steps "
                      "of a moving load's path refined to Maximum level - k; "
                      "without kelly, every other cell is coarsened (down to "
                      "Minimum level), so the refinement follows the front.");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Patterns::Double(0.0, 1.0),
                      "Share of the cells with the largest Kelly "
                      "indicators that are refined at each adaptation."
                        + quantity("number"));
    prm.declare_entry("Coarsen fraction",
                      "0.1",
                      Patterns::Double(0.0, 1.0),
                      "Share of the cells with the smallest Kelly indicators "
                      "coarsened at each adaptation (Refine + Coarsen <= 1)."
                        + quantity("number"));
    prm.declare_entry("Maximum number of cells",
                      "auto",
                      Patterns::Anything(),
                      "Refine nothing once the mesh has this many cells (the "
                      "cells of the contact front and the loads then keep "
                      "their level; Kelly still coarsens its Coarsen "
                      "fraction), so a mesh exceeds it by at most one "
                      "adaptation: a number, 0 for no limit, or auto: 4 "
                      "times the cells of the uniform mesh of "
                      "Discretization. (Without a limit, refining a wave "
                      "that fills the plate ends with every cell at Maximum "
                      "level.)"
                        + quantity("number"));
    prm.declare_entry("Minimum level",
                      "0",
                      Patterns::Integer(-12, 12),
                      "Coarsest cells allowed, in levels relative to the "
                      "uniform mesh of Discretization (negative: coarser "
                      "than it, down to -Global refinements).");
    prm.declare_entry("Maximum level",
                      "3",
                      Patterns::Integer(0, 12),
                      "Finest cells allowed, in levels above the uniform "
                      "mesh of Discretization.");
    prm.declare_entry("Front band",
                      "1",
                      Patterns::Integer(0, 10),
                      "Layers of cells around the cells cut by the contact "
                      "front that are refined with them (cells sharing a "
                      "vertex count as one layer).");
  }


  void
  MeshRefinement::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    enabled                 = prm.get_bool("Adaptive");
    interval                = prm.get_integer("Interval");
    static_cycles           = prm.get_integer("Static cycles");
    refine_fraction         = prm.get_double("Refine fraction");
    coarsen_fraction        = prm.get_double("Coarsen fraction");
    const std::string cells = prm.get("Maximum number of cells");
    AssertThrow(cells == "auto" || Patterns::Integer(0).match(cells),
                ExcMessage("Mesh refinement/Maximum number of cells = <" + cells
                           + ">: expected a whole number of cells (0: no "
                             "limit) or auto."));
    cell_limit_auto     = cells == "auto";
    max_n_cells         = cell_limit_auto ? 0 : Utilities::string_to_int(cells);
    min_level           = prm.get_integer("Minimum level");
    max_level           = prm.get_integer("Maximum level");
    front_band          = prm.get_integer("Front band");
    initial_refinements = prm.get_integer("Initial refinements");
    uses_kelly = uses_front = uses_loads = false;
    for (const auto &name : Utilities::split_string_list(prm.get("Indicators")))
      switch (indicators.parse(name, "Mesh refinement/Indicators"))
        {
        case Indicator::kelly:
          uses_kelly = true;
          break;
        case Indicator::contact_front:
          uses_front = true;
          break;
        case Indicator::loads:
          uses_loads = true;
          break;
        }
    prm.leave_subsection();

    if (!enabled)
      return;
    AssertThrow(refine_fraction + coarsen_fraction <= 1.0,
                ExcMessage("Mesh refinement/Refine fraction + Coarsen "
                           "fraction = "
                           + std::to_string(refine_fraction + coarsen_fraction)
                           + " exceeds 1: a cell cannot be both."));
    AssertThrow(min_level <= static_cast<int>(max_level),
                ExcMessage(
                  "Mesh refinement/Minimum level = " + std::to_string(min_level)
                  + " exceeds Maximum level = " + std::to_string(max_level)
                  + "."));
  }


  void
  MeshRefinement::check_against(const Discretization &discretization) const
  {
    if (!enabled)
      return;
    AssertThrow(discretization.element().supports_local_refinement(),
                ExcMessage("Mesh refinement/Adaptive = true needs "
                           "Discretization/Element = lagrange: the "
                           "serendipity element has no transfer between "
                           "refined and coarse cells."));
    AssertThrow(min_level >= -static_cast<int>(discretization.initial_level()),
                ExcMessage("Mesh refinement/Minimum level = "
                           + std::to_string(min_level)
                           + " is coarser than the coarsest mesh, which is "
                             "Discretization/Global refinements = "
                           + std::to_string(discretization.initial_level())
                           + " levels below the uniform one."));
  }


  unsigned int
  MeshRefinement::cell_limit(const Discretization &discretization) const
  {
    if (cell_limit_auto)
      // The uniform mesh: the coarse mesh with Global refinements.
      return 4 * discretization.triangulation.n_global_coarse_cells()
             * (1u << (2 * discretization.initial_level()));
    return max_n_cells > 0 ? max_n_cells
                           : std::numeric_limits<unsigned int>::max();
  }


  bool
  MeshRefinement::is_enabled() const
  {
    return enabled;
  }


  bool
  MeshRefinement::is_due(const unsigned int step) const
  {
    return enabled && step > 0 && step % interval == 0;
  }


  unsigned int
  MeshRefinement::steps_between_adaptations() const
  {
    return interval;
  }


  unsigned int
  MeshRefinement::n_windows() const
  {
    return std::max(1, static_cast<int>(max_level) - min_level);
  }


  unsigned int
  MeshRefinement::n_static_cycles() const
  {
    return enabled ? static_cycles : 0;
  }


  unsigned int
  MeshRefinement::n_initial_refinements() const
  {
    return enabled ? initial_refinements : 0;
  }


  void
  MeshRefinement::refine_around_loads(Discretization &discretization,
                                      const Windows  &windows) const
  {
    if (!enabled || !uses_loads || windows.empty() || windows[0].empty())
      return;
    for (unsigned int r = 0; r < initial_refinements; ++r)
      {
        keep_loads_fine(discretization, windows, true);
        limit_levels(discretization);
        discretization.triangulation.execute_coarsening_and_refinement();
      }
    discretization.distribute_dofs();
  }


  Vector<float>
  MeshRefinement::kelly_indicators(
    const Discretization  &discretization,
    const LA::MPI::Vector &ghosted_solution) const
  {
    Vector<float> estimate(discretization.triangulation.n_active_cells());
    KellyErrorEstimator<2>::estimate(discretization.mapping(),
                                     discretization.dof_handler,
                                     QGauss<1>(discretization.element().degree()
                                               + 1),
                                     {},
                                     ghosted_solution,
                                     estimate);
    const float largest = Utilities::MPI::max(estimate.linfty_norm(),
                                              discretization.mpi_communicator);
    if (largest > 0)
      for (float &value : estimate)
        value = largest * std::round(value / largest * 1e6f) * 1e-6f;
    return estimate;
  }


  std::vector<bool>
  MeshRefinement::front_cells(const Discretization &discretization,
                              const Vector<float>  &fraction) const
  {
    const auto       &tria = discretization.triangulation;
    std::vector<bool> in_band(tria.n_active_cells(), false);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const float f = fraction[cell->active_cell_index()];
          in_band[cell->active_cell_index()] = (f > 0 && f < 1);
        }

    // Each layer: the cells sharing a node with the band so far. The
    // marks go through a ghosted vector of nodes, so a band crosses the
    // boundaries between ranks as it would on one rank.
    const unsigned int n_dofs =
      discretization.dof_handler.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n_dofs);
    LA::MPI::Vector                      marks;
    marks.reinit(discretization.locally_owned_dofs,
                 discretization.locally_relevant_dofs,
                 discretization.mpi_communicator,
                 /*vector_writable*/ true);
    LA::MPI::Vector ghosted_marks;
    discretization.reinit_ghosted_vector(ghosted_marks);
    for (unsigned int layer = 0; layer < front_band; ++layer)
      {
        marks = 0;
        for (const auto &cell :
             discretization.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && in_band[cell->active_cell_index()])
            {
              cell->get_dof_indices(dofs);
              for (const auto i : dofs)
                marks(i) = 1;
            }
        marks.compress(VectorOperation::insert);
        ghosted_marks = marks;
        for (const auto &cell :
             discretization.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              for (const auto i : dofs)
                if (ghosted_marks(i) != 0)
                  in_band[cell->active_cell_index()] = true;
            }
      }
    return in_band;
  }


  template <class Predicate>
  void
  MeshRefinement::force_refinement(Discretization  &discretization,
                                   const Predicate &is_wanted,
                                   const bool       refine) const
  {
    for (const auto &cell :
         discretization.triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && is_wanted(cell))
        {
          cell->clear_coarsen_flag();
          if (refine)
            cell->set_refine_flag();
        }
  }


  void
  MeshRefinement::keep_loads_fine(Discretization &discretization,
                                  const Windows  &windows,
                                  const bool      refine) const
  {
    const int finest = discretization.initial_level() + max_level;
    for (unsigned int k = 0; k < windows.size(); ++k)
      {
        force_refinement(
          discretization,
          [&](const auto &cell) { return is_under_any(cell, windows[k]); },
          false);
        if (refine)
          force_refinement(discretization, [&](const auto &cell) {
            return static_cast<int>(cell->level())
                     < finest - static_cast<int>(k)
                   && is_under_any(cell, windows[k]);
          });
      }
  }


  void
  MeshRefinement::limit_levels(Discretization &discretization) const
  {
    const int finest = discretization.initial_level() + max_level;
    const int coarsest =
      static_cast<int>(discretization.initial_level()) + min_level;
    for (const auto &cell :
         discretization.triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (static_cast<int>(cell->level()) >= finest)
            cell->clear_refine_flag();
          if (static_cast<int>(cell->level()) <= coarsest)
            cell->clear_coarsen_flag();
        }
  }


  bool
  MeshRefinement::mark_cells(Discretization        &discretization,
                             const Vector<float>   &contact_fraction,
                             const Windows         &windows,
                             const LA::MPI::Vector &ghosted_solution) const
  {
    auto &tria = discretization.triangulation;
    // At or above the cell limit nothing is refined, and Kelly coarsens
    // its fraction. (deal.II's own limit would coarsen as many cells as it
    // takes to get back under it; its choice then depended on the number
    // of ranks: 1 and 2 ranks took different meshes, mpi_consistency_np2.)
    const unsigned int limit = cell_limit(discretization);
    const bool         full  = tria.n_global_active_cells() >= limit;
    if (uses_kelly)
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        tria,
        kelly_indicators(discretization, ghosted_solution),
        full ? 0.0 : refine_fraction,
        coarsen_fraction,
        full ? std::numeric_limits<unsigned int>::max() : limit);
    else
      // Without Kelly nothing else coarsens: the cells the front has left
      // behind (and the loads, if they move) go back towards the uniform
      // mesh, or the front's path stays refined and the mesh ends uniform.
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_coarsen_flag();
    if (uses_front)
      {
        const auto in_band = front_cells(discretization, contact_fraction);
        force_refinement(
          discretization,
          [&](const auto &cell) { return in_band[cell->active_cell_index()]; },
          !full);
      }
    if (uses_loads)
      keep_loads_fine(discretization, windows, !full);
    limit_levels(discretization);
    tria.prepare_coarsening_and_refinement();

    unsigned int n_flagged = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned()
          && (cell->refine_flag_set() || cell->coarsen_flag_set()))
        ++n_flagged;
    return Utilities::MPI::sum(n_flagged, discretization.mpi_communicator) > 0;
  }


  void
  MeshRefinement::execute(Discretization                       &discretization,
                          const std::vector<LA::MPI::Vector *> &vectors) const
  {
    // SolutionTransfer reads the old values on every cell it touches,
    // ghost cells included.
    std::vector<LA::MPI::Vector>         ghosted(vectors.size());
    std::vector<const LA::MPI::Vector *> old_values;
    for (unsigned int i = 0; i < vectors.size(); ++i)
      {
        discretization.reinit_ghosted_vector(ghosted[i]);
        ghosted[i] = *vectors[i];
        old_values.push_back(&ghosted[i]);
      }
    parallel::distributed::SolutionTransfer<2, LA::MPI::Vector> transfer(
      discretization.dof_handler);
    discretization.triangulation.prepare_coarsening_and_refinement();
    transfer.prepare_for_coarsening_and_refinement(old_values);
    discretization.triangulation.execute_coarsening_and_refinement();
    discretization.distribute_dofs();

    std::vector<LA::MPI::Vector *> new_values = vectors;
    for (LA::MPI::Vector *vector : new_values)
      discretization.reinit_vector(*vector);
    transfer.interpolate(new_values);
    // Values on new hanging nodes follow from their parents' edges.
    for (LA::MPI::Vector *vector : vectors)
      discretization.constraints.distribute(*vector);
  }
} // namespace liftoff
