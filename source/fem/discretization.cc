#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/base/selection.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/fe_serendipity.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace liftoff
{
  const std::array<std::string, 4> Discretization::edge_names = {
    {"Left", "Right", "Bottom", "Top"}};

  namespace
  {
    const Selection<EdgeCondition> edge_conditions = {
      {"free", EdgeCondition::free},
      {"hard simply supported", EdgeCondition::hard_simply_supported},
      {"soft simply supported", EdgeCondition::soft_simply_supported},
      {"clamped", EdgeCondition::clamped}};

    const Selection<Symmetry> symmetries = {{"full", Symmetry::full},
                                            {"half", Symmetry::half},
                                            {"quarter", Symmetry::quarter}};

    using Treatment = TransverseShearStrain::Treatment;
    // true: FE_Serendipity.
    const Selection<bool>      elements   = {{"lagrange", false},
                                             {"serendipity", true}};
    const Selection<Treatment> treatments = {{"full", Treatment::full},
                                             {"reduced", Treatment::reduced},
                                             {"mitc", Treatment::mitc}};

    // What the memory estimate charges, fitted to the peak memory of runs
    // of 1e4 to 5e5 unknowns with p = 1, 2, 3 on one rank
    // (doc/reliability.md, benchmarks/memory_estimate.py --fit): per cell
    // (mesh, quadrature data of the foundation), per unknown (vectors, DoF
    // maps), per matrix entry (the shared sparsity pattern and the
    // matrices' values) and per N log2(N) of a direct factor (nested
    // dissection of a 2D mesh fills in like N log N), a symmetric one
    // (CHOLMOD, MUMPS Cholesky) or an LU factor (MUMPS, KLU). The per-unknown
    // and per-entry figures trade off (entries grow with unknowns for a
    // given degree); together they fit the one-rank runs within -8 % and
    // +12 %, the two-rank ones within -12 % and +6 %.
    constexpr double bytes_per_cell          = 510;
    constexpr double bytes_per_dof           = 1480;
    constexpr double bytes_per_matrix_entry  = 33;
    constexpr double bytes_per_cholesky_unit = 32;
    constexpr double bytes_per_lu_unit       = 113;
    // The largest of several ranks holds more than its share: 0.6 of the
    // total on two ranks, measured.
    constexpr double rank_imbalance = 1.2;

    // A number of bytes in a file of /proc or /sys, +infinity when the file
    // is absent or says "max" (no limit).
    double
    bytes_in_file(const std::string &path)
    {
      std::ifstream in(path);
      double        value = 0;
      if (in >> value)
        return value;
      return std::numeric_limits<double>::infinity();
    }

    // Memory the node can still give: MemAvailable, or less under a
    // cgroup limit (v2 or v1).
    double
    available_memory_on_node()
    {
      double        available = std::numeric_limits<double>::infinity();
      std::ifstream meminfo("/proc/meminfo");
      std::string   line;
      while (std::getline(meminfo, line))
        if (line.rfind("MemAvailable:", 0) == 0)
          available = 1024.0 * std::stod(line.substr(13)); // kB
      for (const auto &[limit, usage] :
           {std::make_pair("/sys/fs/cgroup/memory.max",
                           "/sys/fs/cgroup/memory.current"),
            std::make_pair("/sys/fs/cgroup/memory/memory.limit_in_bytes",
                           "/sys/fs/cgroup/memory/memory.usage_in_bytes")})
        {
          const double l = bytes_in_file(limit);
          if (std::isfinite(l))
            available = std::min(available, l - bytes_in_file(usage));
        }
      return available;
    }

    std::string
    gigabytes(const double bytes)
    {
      std::ostringstream text;
      text.precision(2);
      text << bytes / 1e9 << " GB";
      return text.str();
    }
  } // namespace


  Discretization::Discretization(const MPI_Comm comm)
      : mpi_communicator(comm)
      , triangulation(comm)
      , dof_handler(triangulation)
  {
    edges.fill(EdgeCondition::free);
  }


  void
  Discretization::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    prm.declare_entry("Symmetry",
                      "full",
                      symmetries.pattern(),
                      "Which part of the plate is meshed: full; half "
                      "(x >= 0, symmetry plane x = 0); quarter (x >= 0, "
                      "y >= 0). The scene always describes the full plate "
                      "and its full loads.");
    prm.declare_entry("Cells along x",
                      "10",
                      Patterns::Integer(1),
                      "Number of cells along x on the meshed part.");
    prm.declare_entry("Cells along y",
                      "10",
                      Patterns::Integer(1),
                      "Number of cells along y on the meshed part.");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Uniform refinements of the initial cells.");
    prm.declare_entry("Polynomial degree",
                      "1",
                      Patterns::Integer(1, 6),
                      "Degree p of FE_Q(p) used for w, psi_x and psi_y "
                      "(2 with Element = serendipity).");
    prm.declare_entry(
      "Element",
      "lagrange",
      elements.pattern(),
      "Finite element for w, psi_x and psi_y: lagrange, FE_Q(p) with "
      "(p+1)^2 nodes per cell (p = 2: the nine-node element); serendipity, "
      "the paper's eight-node quadrilateral (vertices and edge mid-points, "
      "no centre node), only with Polynomial degree = 2 and Shear "
      "integration = full or reduced (doc/model.md).");
    prm.declare_entry("Shear integration",
                      "mitc",
                      treatments.pattern(),
                      "Treatment of the transverse shear term: full, "
                      "(p+1)^2 Gauss points, locks as the plate gets thin; "
                      "reduced, p^2 points, gives free plates spurious "
                      "zero-energy modes; mitc, assumed natural shear "
                      "strains (MITC4 for p = 1, MITC9 for p = 2), neither "
                      "locks nor has spurious modes (doc/thin-plates.md).");
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    for (const auto &name : edge_names)
      prm.declare_entry(name,
                        "free",
                        edge_conditions.pattern(),
                        "Condition on this edge of the full plate. Left: "
                        "x = -1/2, Right: x = 1/2, Bottom: y = -mu/2, "
                        "Top: y = mu/2. Hard simple support fixes w and the "
                        "rotation along the edge, soft only w.");
    prm.leave_subsection();
  }


  void
  Discretization::parse_parameters(ParameterHandler   &prm,
                                   const MindlinPlate &plate)
  {
    aspect_ratio = plate.aspect_ratio;
    prm.enter_subsection("Discretization");
    const std::string symmetry_name = prm.get("Symmetry");
    modelled_part = symmetries.parse(symmetry_name, "Discretization/Symmetry");
    n_cells_x     = prm.get_integer("Cells along x");
    n_cells_y     = prm.get_integer("Cells along y");
    n_refinements = prm.get_integer("Global refinements");
    fe_degree     = prm.get_integer("Polynomial degree");
    shear_treatment = treatments.parse(prm.get("Shear integration"),
                                       "Discretization/Shear integration");

    is_serendipity =
      elements.parse(prm.get("Element"), "Discretization/Element");
    if (is_serendipity)
      {
        AssertThrow(fe_degree == 2,
                    ExcMessage("Discretization/Element = serendipity is the "
                               "eight-node element of degree 2: it needs "
                               "Discretization/Polynomial degree = 2, not "
                               + std::to_string(fe_degree) + "."));
        // The assumed strains of Shear integration = mitc are tied at the
        // points of the nine-node element's strain space; the eight-node
        // element would need its own scheme (MITC8), which liftoff lacks.
        AssertThrow(shear_treatment != TransverseShearStrain::Treatment::mitc,
                    ExcMessage("Discretization/Element = serendipity works "
                               "with Discretization/Shear integration = full "
                               "or reduced, not mitc (its tying points "
                               "belong to the nine-node Lagrange element)."));
      }
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    for (unsigned int e = 0; e < 4; ++e)
      edges[e] = edge_conditions.parse(prm.get(edge_names[e]),
                                       "Boundary conditions/" + edge_names[e]);
    prm.leave_subsection();

    // A symmetric model is only right for a symmetric plate.
    if (modelled_part != Symmetry::full)
      AssertThrow(edges[left_edge] == edges[right_edge],
                  ExcMessage(
                    "Discretization/Symmetry = " + symmetry_name
                    + " needs Boundary conditions/Left and Right to be "
                      "equal (the plate must be symmetric about x = 0)."));
    if (modelled_part == Symmetry::quarter)
      AssertThrow(edges[bottom_edge] == edges[top_edge],
                  ExcMessage("Discretization/Symmetry = quarter needs Boundary "
                             "conditions/Bottom and Top to be equal (the plate "
                             "must be symmetric about y = 0)."));
  }


  Discretization::SizeEstimate
  Discretization::estimate_size(const Factor       factor,
                                const unsigned int n_ranks) const
  {
    // In doubles: the counts of a refused scene overflow any integer.
    const double p        = fe_degree;
    const double nx       = n_cells_x * std::pow(2.0, n_refinements);
    const double ny       = n_cells_y * std::pow(2.0, n_refinements);
    SizeEstimate estimate = {};
    estimate.n_cells      = nx * ny;
    estimate.n_dofs       = n_components * (p * nx + 1) * (p * ny + 1);
    // A node couples with the nodes of the cells around it: (2p+1)^2 at a
    // vertex, (2p+1)(p+1) inside an edge, (p+1)^2 inside a cell; a cell
    // holds one vertex, 2 (p-1) edge and (p-1)^2 interior nodes.
    const double couplings_per_node =
      ((2 * p + 1) * (2 * p + 1) + 2 * (p - 1) * (2 * p + 1) * (p + 1)
       + (p - 1) * (p - 1) * (p + 1) * (p + 1))
      / (p * p);
    estimate.n_matrix_entries =
      estimate.n_dofs * n_components * couplings_per_node;

    const double shared = bytes_per_cell * estimate.n_cells
                          + bytes_per_dof * estimate.n_dofs
                          + bytes_per_matrix_entry * estimate.n_matrix_entries;
    const double factor_bytes =
      (factor == Factor::none       ? 0.0
       : factor == Factor::cholesky ? bytes_per_cholesky_unit
                                    : bytes_per_lu_unit)
      * estimate.n_dofs * std::log2(estimate.n_dofs);
    // KLU gathers the matrix and its factor on rank 0, which then holds
    // about what a single rank would (1228 MB on 2 ranks, 1248 MB on 1,
    // measured).
    const double share       = (n_ranks == 1 || factor == Factor::lu_on_rank_0)
                                 ? 1.0
                                 : rank_imbalance / n_ranks;
    estimate.memory_per_rank = (shared + factor_bytes) * share;
    return estimate;
  }


  void
  Discretization::check_memory(const Factor factor) const
  {
    // Ranks on one node share its memory.
    MPI_Comm node;
    MPI_Comm_split_type(
      mpi_communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    const unsigned int ranks_on_node = Utilities::MPI::n_mpi_processes(node);
    MPI_Comm_free(&node);
    double available = available_memory_on_node() / ranks_on_node;
    // ulimit -v bounds the address space, of which this process uses some.
    rlimit address_space;
    if (getrlimit(RLIMIT_AS, &address_space) == 0
        && address_space.rlim_cur != RLIM_INFINITY)
      {
        Utilities::System::MemoryStats stats;
        Utilities::System::get_memory_stats(stats);
        available =
          std::min(available,
                   double(address_space.rlim_cur) - 1024.0 * stats.VmSize);
      }
    available = Utilities::MPI::min(available, mpi_communicator);

    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const SizeEstimate estimate = estimate_size(factor, n_ranks);
    std::ostringstream counts;
    counts.precision(3);
    counts << estimate.n_cells << " cells, " << estimate.n_dofs << " unknowns, "
           << estimate.n_matrix_entries << " matrix entries";
    AssertThrow(
      estimate.memory_per_rank <= available,
      ExcMessage(
        "Discretization/Cells along x = " + std::to_string(n_cells_x)
        + ", Cells along y = " + std::to_string(n_cells_y)
        + ", Global refinements = " + std::to_string(n_refinements)
        + ", Polynomial degree = " + std::to_string(fe_degree) + " make "
        + counts.str() + ": about " + gigabytes(estimate.memory_per_rank)
        + " per rank"
        + (factor == Factor::none ? "" : " with the direct factor") + " on "
        + std::to_string(n_ranks) + " rank(s), but only "
        + gigabytes(std::max(available, 0.0))
        + " per rank are available. Use fewer cells, refinements or a "
          "lower degree, more ranks or nodes, or Linear solver/Type = cg."));
  }


  void
  Discretization::setup()
  {
    create_coarse_mesh();
    triangulation.refine_global(n_refinements);

    if (is_serendipity)
      fe = std::make_unique<FESystem<2>>(FE_Serendipity(), n_components);
    else
      fe = std::make_unique<FESystem<2>>(FE_Q<2>(fe_degree), n_components);
    distribute_dofs();
  }


  void
  Discretization::create_coarse_mesh()
  {
    triangulation.clear();
    const BoundingBox<2> box = modelled_box();
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {n_cells_x, n_cells_y},
                                              box.get_boundary_points().first,
                                              box.get_boundary_points().second,
                                              /*colorize*/ true);
    // Faces on x = 0 or y = 0 of a symmetric model are symmetry planes, not
    // plate edges. Refined faces inherit the ids of the coarse ones.
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            if (modelled_part != Symmetry::full
                && face->boundary_id() == left_edge && std::abs(c[0]) < 1e-12)
              face->set_boundary_id(x_symmetry_plane);
            if (modelled_part == Symmetry::quarter
                && face->boundary_id() == bottom_edge && std::abs(c[1]) < 1e-12)
              face->set_boundary_id(y_symmetry_plane);
          }
  }


  void
  Discretization::load_mesh(const std::string &filename)
  {
    create_coarse_mesh();
    triangulation.load(filename);
    distribute_dofs();
  }


  std::vector<std::string>
  Discretization::save_mesh(const std::string &folder,
                            const std::string &name) const
  {
    triangulation.save(folder + "/" + name);
    // deal.II writes "mesh", "mesh.info" and, with cell data, more.
    std::vector<std::string> names;
    for (const auto &entry : std::filesystem::directory_iterator(folder))
      if (entry.path().filename().string().rfind(name, 0) == 0)
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }


  unsigned int
  Discretization::initial_level() const
  {
    return n_refinements;
  }


  bool
  Discretization::supports_local_refinement() const
  {
    return !is_serendipity;
  }


  bool
  Discretization::has_hanging_nodes() const
  {
    return has_hanging;
  }


  void
  Discretization::distribute_dofs()
  {
    dof_handler.distribute_dofs(*fe);
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

    const Functions::ZeroFunction<2> zero(n_components);
    const auto constrain = [&](const types::boundary_id   id,
                               const std::array<bool, 3> &components) {
      const ComponentMask mask(
        std::vector<bool>(components.begin(), components.end()));
      VectorTools::interpolate_boundary_values(
        mapping, dof_handler, id, zero, constraints, mask);
    };

    for (unsigned int e = 0; e < 4; ++e)
      {
        // Rotation along an edge: psi_y on the edges x = const, psi_x on
        // the edges y = const.
        const bool          along_y = (e == left_edge || e == right_edge);
        std::array<bool, 3> mask    = {{false, false, false}};
        switch (edges[e])
          {
          case EdgeCondition::free:
            continue;
          case EdgeCondition::soft_simply_supported:
            mask[0] = true;
            break;
          case EdgeCondition::hard_simply_supported:
            mask[0]               = true;
            mask[along_y ? 2 : 1] = true;
            break;
          case EdgeCondition::clamped:
            mask = {{true, true, true}};
            break;
          }
        constrain(e, mask);
      }

    // On a symmetry plane the rotation normal to it vanishes.
    constrain(x_symmetry_plane, {{false, true, false}});
    constrain(y_symmetry_plane, {{false, false, true}});
    constraints.close();
    // Collective: what depends on it (PlateMatrices::quadratic_form's
    // set_zero) communicates, and a rank without hanging nodes of its own
    // must take part when another has them.
    bool here = false;
    for (const auto &line : constraints.get_lines())
      here = here || !line.entries.empty();
    has_hanging = Utilities::MPI::logical_or(here, mpi_communicator);
  }


  unsigned int
  Discretization::degree() const
  {
    return fe_degree;
  }


  std::string
  Discretization::element_name() const
  {
    return is_serendipity ? "S2" : "Q" + std::to_string(fe_degree);
  }


  const GridTools::Cache<2> &
  Discretization::grid_cache() const
  {
    if (!cache)
      cache = std::make_unique<GridTools::Cache<2>>(triangulation, mapping);
    return *cache;
  }


  void
  Discretization::release_grid_cache() const
  {
    cache.reset();
  }


  TransverseShearStrain::Treatment
  Discretization::shear_integration() const
  {
    return shear_treatment;
  }


  Symmetry
  Discretization::symmetry() const
  {
    return modelled_part;
  }


  unsigned int
  Discretization::n_symmetry_copies() const
  {
    return 1u << symmetry_axes().size();
  }


  std::vector<unsigned int>
  Discretization::symmetry_axes() const
  {
    switch (modelled_part)
      {
      case Symmetry::full:
        return {};
      case Symmetry::half:
        return {0};
      default:
        return {0, 1};
      }
  }


  bool
  Discretization::has_kinematic_support() const
  {
    for (const auto e : edges)
      if (e != EdgeCondition::free)
        return true;
    return false;
  }


  std::string
  Discretization::only_supported_edge() const
  {
    unsigned int n_supported = 0, supported = 0;
    for (unsigned int e = 0; e < edges.size(); ++e)
      if (edges[e] != EdgeCondition::free)
        {
          ++n_supported;
          supported = e;
        }
    return (n_supported == 1 && edges[supported] != EdgeCondition::clamped)
             ? edge_names[supported]
             : std::string();
  }


  double
  Discretization::largest_cell_aspect_ratio() const
  {
    // Refinement splits cells in both directions: the coarse cells' ratio.
    const double width  = 1.0 / n_cells_x;
    const double height = aspect_ratio / n_cells_y;
    return std::max(width / height, height / width);
  }


  BoundingBox<2>
  Discretization::plate_box() const
  {
    return BoundingBox<2>(std::make_pair(Point<2>(-0.5, -0.5 * aspect_ratio),
                                         Point<2>(0.5, 0.5 * aspect_ratio)));
  }


  bool
  Discretization::is_on_plate(const Point<2> &p) const
  {
    // Relative to the plate's size, so that a point written on an edge is
    // on the plate whatever the round-off of its decimal digits.
    return plate_box().point_inside(p, 1e-12 * std::max(1.0, aspect_ratio));
  }


  std::string
  Discretization::plate_description() const
  {
    std::ostringstream text;
    text.precision(6);
    text << "the plate [-0.5, 0.5] x [" << -0.5 * aspect_ratio << ", "
         << 0.5 * aspect_ratio << "]";
    return text.str();
  }


  BoundingBox<2>
  Discretization::modelled_box() const
  {
    auto corners = plate_box().get_boundary_points();
    for (const unsigned int axis : symmetry_axes())
      corners.first[axis] = 0.0;
    return BoundingBox<2>(corners);
  }


  Point<2>
  Discretization::to_modelled_part(const Point<2> &p) const
  {
    Point<2> q = p;
    for (const unsigned int axis : symmetry_axes())
      q[axis] = std::abs(q[axis]);
    return q;
  }


  double
  Discretization::share_of_point_load(const Point<2> &p) const
  {
    double share = 1.0;
    for (const unsigned int axis : symmetry_axes())
      if (std::abs(p[axis]) < 1e-12)
        share *= 0.5;
    return share;
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
