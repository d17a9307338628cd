#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/table.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_element.h>
#include <liftoff/fem/plate_geometry.h>

#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The mesh of the plate's geometry, the DoFHandler of its element and the
   * kinematic constraints of the edges and symmetry planes, on a distributed
   * triangulation so that the same code runs serially and under MPI
   * (step-40). The shape is PlateGeometry's, the element PlateElement's.
   */
  class Discretization
  {
  public:
    explicit Discretization(const MPI_Comm comm);

    /// The entries of the geometry and the element, and `Global
    /// refinements`.
    static void
    declare_parameters(ParameterHandler &prm);
    /// `units` are the scene's as written: a mesh file is in its length
    /// unit (PlateGeometry::parse_parameters()).
    void
    parse_parameters(ParameterHandler    &prm,
                     const MindlinPlate  &plate,
                     const PhysicalUnits &units = PhysicalUnits());

    /// The plate's shape, supports and symmetry.
    const PlateGeometry &
    geometry() const;
    /// The element of (w, psi_x, psi_y).
    const PlateElement &
    element() const;

    /// Build mesh, dofs, constraints for the plate of parse_parameters().
    void
    setup();

    /// Dofs, constraints (hanging nodes included) and sparsity pattern of
    /// the mesh as it is now: after setup(), and again after the mesh has
    /// been refined or coarsened.
    void
    distribute_dofs();

    /// Replace the mesh by one saved with triangulation.save() (a
    /// checkpoint of an adaptive run, Checkpoint::mesh_writer()) and
    /// distribute the dofs on it.
    void
    load_mesh(const std::string &filename);

    /// This rank's active cells in an order that depends on the mesh only,
    /// not on how it was reached (refined in the run or loaded from a
    /// checkpoint). Loops whose results are kept per cell or per Gauss
    /// point, or summed, walk the cells in this order, so that a resumed
    /// run repeats the uninterrupted one bit for bit.
    const std::vector<DoFHandler<2>::active_cell_iterator> &
    locally_owned_cells() const;

    /// The level of the cells of the uniform mesh the parameters describe
    /// (`Global refinements`): adaptive levels count from it.
    unsigned int
    initial_level() const;
    /// Whether the constraints of any rank tie hanging nodes to other
    /// nodes (not only fix values to zero); the same on every rank.
    bool
    has_hanging_nodes() const;

    /// Sparse matrix and vectors laid out on this discretization. A matrix
    /// has the plate's pattern (every component couples with every other
    /// in a cell), or with `coupling` (3 x 3) one in
    /// which only the components it names couple: the mass matrix couples
    /// each component with itself only, and a product with it in the
    /// smaller pattern skips two thirds of the entries. The matrices of
    /// the plate's pattern share one Epetra graph (the pattern's), so each
    /// costs its values only.
    void
    reinit_matrix(LA::MPI::SparseMatrix &matrix) const;
    void
    reinit_matrix(LA::MPI::SparseMatrix              &matrix,
                  const Table<2, DoFTools::Coupling> &coupling) const;
    void
    reinit_vector(LA::MPI::Vector &vector) const;
    void
    reinit_ghosted_vector(LA::MPI::Vector &vector) const;

    /// The search trees of the mesh, for finding the cells around points
    /// (GridTools::find_active_cell_around_point); built when first asked
    /// for, kept until release_grid_cache().
    const GridTools::Cache<2> &
    grid_cache() const;
    /// MappingQ1 on the rectangle; on a curved outline a MappingQ of the
    /// element's degree (2 for the serendipity element), which puts its
    /// support points on the manifolds, so the cells follow the circle.
    /// The same degree as the element (isoparametric): the element then
    /// holds the rigid motions w = x, y exactly, which a free plate's
    /// equilibrium needs; Q1 cells are straight, the disc a polygon.
    const Mapping<2> &
    mapping() const;
    /// |area of the mesh (with its mapping) / the outline's - 1| of the
    /// mesh setup() or load_mesh() made: the circles' cells lose area to
    /// their mapping (a polygon with degree 1, arcs of parabolas with 2).
    double
    area_error() const;
    /// Free the search trees once the scene's points are found: the time
    /// loop does not use them (L, p = 1: 248 MB of the peak).
    void
    release_grid_cache() const;

    MPI_Comm                                mpi_communicator;
    parallel::distributed::Triangulation<2> triangulation;
    DoFHandler<2>                           dof_handler;
    IndexSet                                locally_owned_dofs;
    IndexSet                                locally_relevant_dofs;
    AffineConstraints<double>               constraints;

  private:
    std::unique_ptr<Mapping<2>>                      cell_mapping;
    PlateGeometry                                    plate_geometry;
    PlateElement                                     plate_element;
    unsigned int                                     n_refinements = 0;
    TrilinosWrappers::SparsityPattern                sparsity_pattern;
    mutable std::unique_ptr<GridTools::Cache<2>>     cache;
    std::vector<DoFHandler<2>::active_cell_iterator> owned_cells;
    bool                                             has_hanging     = false;
    double                                           mesh_area_error = 0;

    /// The geometry's coarse mesh, cut along the joints.
    void
    create_coarse_mesh();
    void
    make_constraints();
    /// area_error() of the mesh as it is now (collective).
    double
    measure_area_error() const;
    /// psi . t = 0 and psi . n = 0 on the boundaries where these are no
    /// components of psi (PlateGeometry::held_rotations()).
    void
    hold_projected_rotations();
    void
    hold_rotation_at_corners(const HeldRotations &held);
    /// The pattern of the couplings `coupling` allows, with the
    /// constraints condensed, of the rows this rank owns and those it
    /// writes to.
    void
    make_sparsity_pattern(const Table<2, DoFTools::Coupling> &coupling,
                          DynamicSparsityPattern             &pattern) const;
  };
} // namespace liftoff
