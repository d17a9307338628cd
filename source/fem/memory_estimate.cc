#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/fem/memory_estimate.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace liftoff
{
  using namespace dealii;

  namespace
  {
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


  MemoryEstimate::MemoryEstimate(const Discretization &discretization,
                                 const Factor          factor,
                                 const unsigned int    n_ranks)
  {
    // In doubles: the counts of a refused scene overflow any integer.
    const PlateGeometry &geometry = discretization.geometry();
    const double         p        = discretization.element().degree();
    const double refinement   = std::pow(2.0, discretization.initial_level());
    const double nx           = geometry.coarse_cells_along(0) * refinement;
    const double ny           = geometry.coarse_cells_along(1) * refinement;
    const double n_components = discretization.element().fe().n_components();
    n_cells                   = nx * ny;
    n_dofs                    = n_components * (p * nx + 1) * (p * ny + 1);
    // A node couples with the nodes of the cells around it: (2p+1)^2 at a
    // vertex, (2p+1)(p+1) inside an edge, (p+1)^2 inside a cell; a cell
    // holds one vertex, 2 (p-1) edge and (p-1)^2 interior nodes.
    const double couplings_per_node =
      ((2 * p + 1) * (2 * p + 1) + 2 * (p - 1) * (2 * p + 1) * (p + 1)
       + (p - 1) * (p - 1) * (p + 1) * (p + 1))
      / (p * p);
    n_matrix_entries = n_dofs * n_components * couplings_per_node;

    const double shared = bytes_per_cell * n_cells + bytes_per_dof * n_dofs
                          + bytes_per_matrix_entry * n_matrix_entries;
    const double factor_bytes =
      (factor == Factor::none       ? 0.0
       : factor == Factor::cholesky ? bytes_per_cholesky_unit
                                    : bytes_per_lu_unit)
      * n_dofs * std::log2(n_dofs);
    // KLU gathers the matrix and its factor on rank 0, which then holds
    // about what a single rank would (1228 MB on 2 ranks, 1248 MB on 1,
    // measured).
    const double share = (n_ranks == 1 || factor == Factor::lu_on_rank_0)
                           ? 1.0
                           : rank_imbalance / n_ranks;
    memory_per_rank    = (shared + factor_bytes) * share;
  }


  void
  MemoryEstimate::check(const Discretization &discretization,
                        const Factor          factor,
                        const MPI_Comm        comm)
  {
    // Ranks on one node share its memory.
    MPI_Comm node;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
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
    available = Utilities::MPI::min(available, comm);

    const unsigned int   n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const MemoryEstimate estimate(discretization, factor, n_ranks);
    if (estimate.memory_per_rank <= available)
      return;
    const PlateGeometry &geometry = discretization.geometry();
    std::ostringstream   counts;
    counts.precision(3);
    counts << estimate.n_cells << " cells, " << estimate.n_dofs << " unknowns, "
           << estimate.n_matrix_entries << " matrix entries";
    // The coarse mesh of a disc or an annulus is fixed: only the
    // rectangle's cells are named.
    const std::string coarse_mesh =
      geometry.shape() != PlateShape::rectangle
        ? geometry.shape_setting()
        : "Discretization/Cells along x = "
            + std::to_string(geometry.coarse_cells_along(0))
            + ", Cells along y = "
            + std::to_string(geometry.coarse_cells_along(1));
    AssertThrow(
      false,
      ExcMessage(
        coarse_mesh + ", Global refinements = "
        + std::to_string(discretization.initial_level())
        + ", Polynomial degree = "
        + std::to_string(discretization.element().degree()) + " make "
        + counts.str() + ": about " + gigabytes(estimate.memory_per_rank)
        + " per rank"
        + (factor == Factor::none ? "" : " with the direct factor") + " on "
        + std::to_string(n_ranks) + " rank(s), but only "
        + gigabytes(std::max(available, 0.0))
        + " per rank are available. Use fewer cells, refinements or a "
          "lower degree, more ranks or nodes, or Linear solver/Type = cg."));
  }
} // namespace liftoff
