#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/fem/discretization.h>


#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <set>

namespace liftoff
{
  Discretization::Discretization(const MPI_Comm comm)
      : mpi_communicator(comm)
      , triangulation(comm)
      , dof_handler(triangulation)
      , cell_mapping(std::make_unique<MappingQ1<2>>())
  {}


  void
  Discretization::declare_parameters(ParameterHandler &prm)
  {
    PlateGeometry::declare_parameters(prm);
    PlateElement::declare_parameters(prm);
    prm.enter_subsection("Discretization");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Uniform refinements of the initial cells.");
    prm.leave_subsection();
  }


  void
  Discretization::parse_parameters(ParameterHandler    &prm,
                                   const MindlinPlate  &plate,
                                   const PhysicalUnits &units)
  {
    plate_geometry.parse_parameters(prm, plate, units);
    plate_element.parse_parameters(prm, plate.base.n_layers());
    // Isoparametric: a mapping of higher degree than the element's (Q2
    // under Q1 cells) makes w = x no function of the element, and a free
    // plate resisted a rigid tilt (a load's resultant 3 % off its point).
    cell_mapping = plate_geometry.has_curved_boundary()
                     ? std::make_unique<MappingQ<2>>(plate_element.degree())
                     : std::make_unique<MappingQ1<2>>();
    prm.enter_subsection("Discretization");
    n_refinements = prm.get_integer("Global refinements");
    prm.leave_subsection();
  }


  const PlateGeometry &
  Discretization::geometry() const
  {
    return plate_geometry;
  }


  const Mapping<2> &
  Discretization::mapping() const
  {
    return *cell_mapping;
  }


  const PlateElement &
  Discretization::element() const
  {
    return plate_element;
  }


  void
  Discretization::create_coarse_mesh()
  {
    triangulation.clear();
    const SlabLayout &slabs = plate_geometry.slabs();
    if (!slabs.is_jointed())
      {
        plate_geometry.create_coarse_mesh(triangulation);
        return;
      }
    Triangulation<2> whole;
    plate_geometry.create_coarse_mesh(whole);
    slabs.cut(whole, triangulation);
  }


  void
  Discretization::setup()
  {
    create_coarse_mesh();
    triangulation.refine_global(n_refinements);
    distribute_dofs();
    mesh_area_error = measure_area_error();
  }


  double
  Discretization::measure_area_error() const
  {
    // Straight outlines are meshed exactly.
    if (!plate_geometry.has_curved_boundary())
      return 0;
    // The Jacobian of a map of degree p is of degree 2p - 1 in each
    // coordinate: p + 1 Gauss points integrate it exactly.
    const QGauss<2>     quadrature(plate_element.degree() + 1);
    const FE_Nothing<2> nothing;
    FEValues<2> fe_values(mapping(), nothing, quadrature, update_JxW_values);
    double      area = 0;
    for (const auto &cell : owned_cells)
      {
        fe_values.reinit(Triangulation<2>::cell_iterator(cell));
        for (const unsigned int q : fe_values.quadrature_point_indices())
          area += fe_values.JxW(q);
      }
    area = Utilities::MPI::sum(area, mpi_communicator);
    return std::abs(area / plate_geometry.modelled_area() - 1);
  }


  double
  Discretization::area_error() const
  {
    return mesh_area_error;
  }


  void
  Discretization::load_mesh(const std::string &filename)
  {
    create_coarse_mesh();
    triangulation.load(filename);
    distribute_dofs();
    mesh_area_error = measure_area_error();
  }


  unsigned int
  Discretization::initial_level() const
  {
    return n_refinements;
  }


  bool
  Discretization::has_hanging_nodes() const
  {
    return has_hanging;
  }


  void
  Discretization::distribute_dofs()
  {
    dof_handler.distribute_dofs(plate_element.fe());
    // Where a refined mesh keeps its cells depends on its history: a mesh
    // refined and coarsened in a run and the same mesh loaded from a
    // checkpoint list their cells in different orders. The checkpoint
    // holds vectors, Gauss point data and matrix values in this rank's
    // order, so the order of dofs and cells must follow from the mesh
    // alone: the hierarchical order of the cells (coarse cell, then
    // children) for both.
    DoFRenumbering::hierarchical(dof_handler);
    owned_cells.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        owned_cells.push_back(cell);
    std::sort(owned_cells.begin(),
              owned_cells.end(),
              [](const auto &a, const auto &b) { return a->id() < b->id(); });
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    make_constraints();

    const unsigned int n_components = dof_handler.get_fe().n_components();
    Table<2, DoFTools::Coupling> every_component(n_components, n_components);
    every_component.fill(DoFTools::always);
    // The dynamic pattern (a vector per row) lives only until the
    // compressed one is built from it.
    DynamicSparsityPattern pattern;
    make_sparsity_pattern(every_component, pattern);
    sparsity_pattern.reinit(locally_owned_dofs,
                            locally_owned_dofs,
                            pattern,
                            mpi_communicator);
  }


  const std::vector<DoFHandler<2>::active_cell_iterator> &
  Discretization::locally_owned_cells() const
  {
    return owned_cells;
  }


  void
  Discretization::make_sparsity_pattern(
    const Table<2, DoFTools::Coupling> &coupling,
    DynamicSparsityPattern             &pattern) const
  {
    pattern.reinit(locally_relevant_dofs.size(),
                   locally_relevant_dofs.size(),
                   locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    coupling,
                                    pattern,
                                    constraints,
                                    /*keep_constrained_dofs*/ false);
    plate_geometry.slabs().add_couplings(dof_handler, constraints, pattern);
    SparsityTools::distribute_sparsity_pattern(pattern,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
  }


  void
  Discretization::make_constraints()
  {
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    plate_geometry.slabs().tie(dof_handler, constraints);

    const Functions::ZeroFunction<2> zero(dof_handler.get_fe().n_components());
    for (const auto &[id, mask] : plate_geometry.held_components(
           PlateFields::n_layers(dof_handler.get_fe())))
      VectorTools::interpolate_boundary_values(
        mapping(), dof_handler, id, zero, constraints, mask);
    hold_projected_rotations();
    constraints.close();
    // Collective: what depends on it (PlateMatrices::quadratic_form's
    // set_zero) communicates, and a rank without hanging nodes of its own
    // must take part when another has them.
    bool here = false;
    for (const auto &line : constraints.get_lines())
      here = here || !line.entries.empty();
    has_hanging = Utilities::MPI::logical_or(here, mpi_communicator);
  }


  void
  Discretization::hold_projected_rotations()
  {
    const HeldRotations held = plate_geometry.held_rotations();
    if (held.projected.empty())
      return;
    // After the hanging nodes and the components held directly (clamped
    // neighbours, symmetry planes along an axis): deal.II's functions leave
    // a constrained dof as it is. Where a circle meets a symmetry plane at a
    // right angle both hold the same component, so nothing is lost.
    if (!plate_geometry.has_curved_boundary())
      hold_rotation_at_corners(held);
    std::set<types::boundary_id> along, across;
    for (const types::boundary_id id : held.projected)
      (held.along.count(id) > 0 ? along : across).insert(id);
    // The normals are the manifolds' at the support points (a circle's
    // exact radius, a straight face's normal), the same on every rank that
    // sees the face. deal.II's name for psi x n = 0 (psi . t = 0) is
    // compute_normal_flux_constraints, for psi . n = 0 it is
    // compute_no_normal_flux_constraints.
    // Every layer's rotation alike.
    for (unsigned int layer = 0;
         layer < PlateFields::n_layers(dof_handler.get_fe());
         ++layer)
      {
        const unsigned int psi_x = PlateFields::rotation(0, layer);
        if (!along.empty())
          VectorTools::compute_normal_flux_constraints(
            dof_handler, psi_x, along, constraints, mapping());
        if (!across.empty())
          VectorTools::compute_no_normal_flux_constraints(
            dof_handler, psi_x, across, constraints, mapping());
      }
  }


  void
  Discretization::hold_rotation_at_corners(const HeldRotations &held)
  {
    // At a vertex where two held straight faces meet at an angle, w = 0
    // along both sides (or two symmetry planes) holds two independent
    // projections of psi: the whole rotation, as at a rectangle's corner.
    // deal.II's flux constraints would average the normals of faces of two
    // cells there (a re-entrant corner) and hold one projection only.
    std::map<std::array<types::global_dof_index, 2>, std::vector<Tensor<1, 2>>>
      held_directions;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto &face : cell->face_iterators())
          {
            if (!face->at_boundary())
              continue;
            const bool along = held.along.count(face->boundary_id()) > 0;
            if (!along && held.across.count(face->boundary_id()) == 0)
              continue;
            Tensor<1, 2> direction = face->vertex(1) - face->vertex(0);
            direction /= direction.norm();
            if (!along)
              direction = cross_product_2d(direction);
            for (const unsigned int v : face->vertex_indices())
              for (unsigned int layer = 0;
                   layer < PlateFields::n_layers(dof_handler.get_fe());
                   ++layer)
                held_directions
                  [{face->vertex_dof_index(v, PlateFields::rotation(0, layer)),
                    face->vertex_dof_index(v, PlateFields::rotation(1, layer))}]
                    .push_back(direction);
          }
    for (const auto &[psi, directions] : held_directions)
      for (const Tensor<1, 2> &direction : directions)
        if (std::abs(cross_product_2d(direction) * directions[0]) > 1e-10)
          for (const types::global_dof_index dof : psi)
            if (constraints.can_store_line(dof))
              constraints.add_line(dof);
  }


  const GridTools::Cache<2> &
  Discretization::grid_cache() const
  {
    if (!cache)
      cache = std::make_unique<GridTools::Cache<2>>(triangulation, mapping());
    return *cache;
  }


  void
  Discretization::release_grid_cache() const
  {
    cache.reset();
  }


  void
  Discretization::reinit_matrix(LA::MPI::SparseMatrix &matrix) const
  {
    matrix.reinit(sparsity_pattern);
  }


  void
  Discretization::reinit_matrix(
    LA::MPI::SparseMatrix              &matrix,
    const Table<2, DoFTools::Coupling> &coupling) const
  {
    DynamicSparsityPattern pattern;
    make_sparsity_pattern(coupling, pattern);
    matrix.reinit(locally_owned_dofs,
                  locally_owned_dofs,
                  pattern,
                  mpi_communicator);
  }


  void
  Discretization::reinit_vector(LA::MPI::Vector &vector) const
  {
    vector.reinit(locally_owned_dofs, mpi_communicator);
  }


  void
  Discretization::reinit_ghosted_vector(LA::MPI::Vector &vector) const
  {
    vector.reinit(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
  }
} // namespace liftoff
