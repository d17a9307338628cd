#pragma once

#include <mpi.h>

namespace liftoff
{
  class Discretization;

  /**
   * Cells, unknowns, matrix entries and memory of a discretization, from its
   * parameters alone, before anything is built (doc/reliability.md has the
   * formula and how well it matches measured peak memory), and the refusal
   * of a scene that would not fit.
   */
  struct MemoryEstimate
  {
    /// The factor of a direct solver: none (CG and AMG), a Cholesky factor
    /// (CHOLMOD on one rank, MUMPS spread over the ranks), an LU factor
    /// spread over the ranks (MUMPS) or an LU factor on rank 0 (KLU).
    enum class Factor
    {
      none,
      cholesky,
      lu,
      lu_on_rank_0
    };

    MemoryEstimate(const Discretization &discretization,
                   const Factor          factor,
                   const unsigned int    n_ranks);

    double n_cells          = 0;
    double n_dofs           = 0;
    double n_matrix_entries = 0;
    /// Bytes the largest rank will add to what it holds at start-up.
    double memory_per_rank = 0;

    /// Refuse, on every rank of `comm`, a discretization whose estimate
    /// does not fit in the memory each rank can have (the node's
    /// MemAvailable or a cgroup limit shared by the ranks on the node, and
    /// `ulimit -v`). It allocates nothing: call it before the mesh is built.
    static void
    check(const Discretization &discretization,
          const Factor          factor,
          const MPI_Comm        comm);
  };
} // namespace liftoff
