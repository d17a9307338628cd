#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/table.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/transverse_shear_strain.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /// How an edge of the plate is held.
  enum class EdgeCondition
  {
    free,
    hard_simply_supported, // w = 0 and the tangential rotation is zero
    soft_simply_supported, // w = 0 only
    clamped                // w = psi_x = psi_y = 0
  };

  /// Which part of the plate is meshed. The scene always describes the full
  /// plate; symmetry planes are x = 0 (half and quarter) and y = 0 (quarter).
  enum class Symmetry
  {
    full,
    half,
    quarter
  };

  /**
   * The mesh, the finite element (w, psi_x, psi_y) in
   * FESystem(FE_Q(p), 3) or FESystem(FE_Serendipity, 3), the DoFHandler and the
   * kinematic constraints of the edges and symmetry planes, on a distributed
   * triangulation so that the same code runs serially and under MPI (step-40).
   */
  class Discretization
  {
  public:
    /// The factor of a direct solver, for the memory estimate: none (CG and
    /// AMG), a Cholesky factor (CHOLMOD on one rank, MUMPS spread over the
    /// ranks), an LU factor spread over the ranks (MUMPS) or an LU factor
    /// on rank 0 (KLU).
    enum class Factor
    {
      none,
      cholesky,
      lu,
      lu_on_rank_0
    };

    /// The size of the discretization the parameters ask for, known
    /// before anything is built.
    struct SizeEstimate
    {
      double n_cells          = 0;
      double n_dofs           = 0;
      double n_matrix_entries = 0;
      /// Bytes the largest rank will add to what it holds at start-up.
      double memory_per_rank = 0;
    };

    /// Boundary ids: the four plate edges, then the symmetry planes.
    enum BoundaryId : types::boundary_id
    {
      left_edge        = 0,
      right_edge       = 1,
      bottom_edge      = 2,
      top_edge         = 3,
      x_symmetry_plane = 4, // x = 0
      y_symmetry_plane = 5  // y = 0
    };

    static constexpr unsigned int           n_components = 3;
    static const std::array<std::string, 4> edge_names;

    explicit Discretization(const MPI_Comm comm);

    static void
    declare_parameters(ParameterHandler &prm);
    /// The plate's aspect ratio is taken here, so that every check of a
    /// point against the plate made while parsing sees the real plate.
    void
    parse_parameters(ParameterHandler &prm, const MindlinPlate &plate);

    /// Cells, unknowns, matrix entries and memory of this discretization on
    /// `n_ranks` ranks, from the parameters alone (doc/reliability.md has
    /// the formula and how well it matches measured peak memory).
    SizeEstimate
    estimate_size(const Factor factor, const unsigned int n_ranks) const;

    /// Refuse, on every rank, a discretization whose estimate does not fit
    /// in the memory each rank can have (the node's MemAvailable or a
    /// cgroup limit shared by the ranks on the node, and `ulimit -v`).
    /// Call it before setup(): it allocates nothing.
    void
    check_memory(const Factor factor) const;

    /// Build mesh, dofs, constraints for the plate of parse_parameters().
    void
    setup();

    /// Dofs, constraints (hanging nodes included) and sparsity pattern of
    /// the mesh as it is now: after setup(), and again after the mesh has
    /// been refined or coarsened.
    void
    distribute_dofs();

    /// Replace the mesh by one saved with triangulation.save() (a
    /// checkpoint of an adaptive run) and distribute the dofs on it.
    void
    load_mesh(const std::string &filename);
    /// Save the mesh as `name` in `folder` for load_mesh(); returns the
    /// names of the files deal.II wrote for it there, sorted.
    std::vector<std::string>
    save_mesh(const std::string &folder, const std::string &name) const;

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
    /// Whether the element has the transfer matrices between a cell and its
    /// children that hanging nodes and SolutionTransfer need (FE_Q has,
    /// FE_Serendipity has not).
    bool
    supports_local_refinement() const;
    /// Whether the constraints of any rank tie hanging nodes to other
    /// nodes (not only fix values to zero); the same on every rank.
    bool
    has_hanging_nodes() const;

    unsigned int
    degree() const;
    /// "Q<p>" (Lagrange) or "S2" (serendipity), for logs and summaries.
    std::string
    element_name() const;
    /// How the element integrates the transverse shear energy (`Shear
    /// integration`).
    TransverseShearStrain::Treatment
    shear_integration() const;
    Symmetry
    symmetry() const;
    /// How many copies of the modelled part make the plate (1, 2 or 4).
    unsigned int
    n_symmetry_copies() const;
    /// Axes normal to the symmetry planes (0: plane x = 0, 1: plane y = 0).
    std::vector<unsigned int>
    symmetry_axes() const;
    /// True when some edge restrains w, so the stiffness alone is regular
    /// enough for a static solve without foundation contact.
    bool
    has_kinematic_support() const;

    /// The name of the edge ("Left", ...) if it is the only one that holds
    /// the plate and it is not clamped: the plate can turn about it, so
    /// only a foundation makes a static problem regular. Else "".
    std::string
    only_supported_edge() const;
    /// The larger of width / height and height / width of the cells.
    double
    largest_cell_aspect_ratio() const;

    /// The full plate and the part of it that is meshed.
    BoundingBox<2>
    plate_box() const;
    /// True for a point of the plate, its edges included.
    bool
    is_on_plate(const Point<2> &p) const;
    /// "the plate [-0.5, 0.5] x [-1, 1]": messages about points off it name
    /// the plate in numbers, since mu is a parameter of another class.
    std::string
    plate_description() const;
    BoundingBox<2>
    modelled_box() const;
    /// Mirror a point of the full plate into the modelled part.
    Point<2>
    to_modelled_part(const Point<2> &p) const;
    /// Share of a concentrated load at p (in the modelled part) that the
    /// modelled part carries: 1/2 for each symmetry plane p lies on.
    double
    share_of_point_load(const Point<2> &p) const;

    /// Sparse matrix and vectors laid out on this discretization. A matrix
    /// has the plate's pattern (every component couples with every other
    /// in a cell), or with `coupling` (n_components x n_components) one in
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
    /// Free the search trees once the scene's points are found: the time
    /// loop does not use them (L, p = 1: 248 MB of the peak).
    void
    release_grid_cache() const;

    MPI_Comm                                mpi_communicator;
    parallel::distributed::Triangulation<2> triangulation;
    MappingQ1<2>                            mapping;
    std::unique_ptr<FESystem<2>>            fe;
    DoFHandler<2>                           dof_handler;
    IndexSet                                locally_owned_dofs;
    IndexSet                                locally_relevant_dofs;
    AffineConstraints<double>               constraints;

  private:
    double                           aspect_ratio = 1.0;
    unsigned int                     fe_degree    = 1;
    TransverseShearStrain::Treatment shear_treatment =
      TransverseShearStrain::Treatment::mitc;
    Symmetry                                     modelled_part = Symmetry::full;
    unsigned int                                 n_cells_x     = 10;
    unsigned int                                 n_cells_y     = 10;
    unsigned int                                 n_refinements = 0;
    std::array<EdgeCondition, 4>                 edges;
    TrilinosWrappers::SparsityPattern            sparsity_pattern;
    mutable std::unique_ptr<GridTools::Cache<2>> cache;
    std::vector<DoFHandler<2>::active_cell_iterator> owned_cells;

    /// FE_Serendipity (degree 2) instead of FE_Q(fe_degree).
    bool is_serendipity = false;
    bool has_hanging    = false;

    void
    make_constraints();
    /// The pattern of the couplings `coupling` allows, with the
    /// constraints condensed, of the rows this rank owns and those it
    /// writes to.
    void
    make_sparsity_pattern(const Table<2, DoFTools::Coupling> &coupling,
                          DynamicSparsityPattern             &pattern) const;
    /// The `Cells along x` x `Cells along y` cells with the boundary ids of
    /// edges and symmetry planes, replacing any mesh there was.
    void
    create_coarse_mesh();
  };
} // namespace liftoff
