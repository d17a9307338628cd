#include <liftoff/solver/mumps_cholesky_factor.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>

#include <numeric>

namespace liftoff
{
  /// MUMPS's structure with its 1-based arrays under their manual's names.
  struct MumpsCholeskyFactor::Mumps : DMUMPS_STRUC_C
  {
    MUMPS_INT &
    ICNTL(const int i)
    {
      return icntl[i - 1];
    }
    MUMPS_INT
    ICNTL(const int i) const
    {
      return icntl[i - 1];
    }
    MUMPS_INT
    INFOG(const int i) const
    {
      return infog[i - 1];
    }
  };


  namespace
  {
    /// MUMPS's job numbers (its manual, section 5).
    constexpr int initialise = -1, terminate = -2, analyse = 1, factorise = 2,
                  solve = 3;

    /// Errors of work arrays that MUMPS sized from its estimate plus
    /// ICNTL(14) percent and that a larger ICNTL(14) cures.
    bool
    workspace_too_small(const int error)
    {
      return error == -8 || error == -9 || error == -14 || error == -15
             || error == -17 || error == -20;
    }

    /// The cause of MUMPS's error `error` (INFOG(1) < 0) in words.
    std::string
    cause(const int error, const int detail, const int relaxation)
    {
      if (workspace_too_small(error))
        return "its work space was too small even " + std::to_string(relaxation)
               + " % above its estimate (ICNTL(14))";
      if (error == -13 || error == -7 || error == -5)
        return "memory ran out (an allocation of " + std::to_string(detail)
               + (detail < 0 ? " million" : "") + " entries failed)";
      if (error == -10)
        return "the matrix is numerically singular";
      if (error == -16)
        return "the matrix has " + std::to_string(detail) + " rows";
      return "see the error list in MUMPS's user guide";
    }
  } // namespace


  MumpsCholeskyFactor::MumpsCholeskyFactor(const MPI_Comm comm)
      : mumps(std::make_unique<Mumps>())
      , comm(comm)
  {
    mumps->comm_fortran = MPI_Comm_c2f(comm);
    // Rank 0, MUMPS's host, works too; SYM = 1: positive definite, pivots
    // on the diagonal without numerical pivoting.
    mumps->par = 1;
    mumps->sym = 1;
    run(initialise, "initialisation");
    // No output: errors come back as exceptions.
    for (const int stream : {1, 2, 3})
      mumps->ICNTL(stream) = -1;
    mumps->ICNTL(4) = 0;
    // The matrix in coordinates, distributed by rows as Trilinos holds it;
    // right-hand side and solution on the host.
    mumps->ICNTL(5)  = 0;
    mumps->ICNTL(18) = 3;
    mumps->ICNTL(20) = 0;
    mumps->ICNTL(21) = 0;
  }


  MumpsCholeskyFactor::~MumpsCholeskyFactor()
  {
    mumps->job = terminate;
    dmumps_c(mumps.get());
  }


  bool
  MumpsCholeskyFactor::run(const int job, const std::string &what)
  {
    mumps->job = job;
    dmumps_c(mumps.get());
    return succeeded(what);
  }


  bool
  MumpsCholeskyFactor::succeeded(const std::string &what) const
  {
    const int error = mumps->INFOG(1);
    // A pivot that is not positive: the matrix is not positive definite
    // (MUMPS stops at a zero pivot and counts negative ones in INFOG(12)).
    if (mumps->job == factorise && (error == -10 || mumps->INFOG(12) > 0))
      return false;
    AssertThrow(error >= 0,
                ExcMessage(
                  "MUMPS's Cholesky " + what
                  + " failed: INFOG(1) = " + std::to_string(error)
                  + ", INFOG(2) = " + std::to_string(mumps->INFOG(2)) + ": "
                  + cause(error, mumps->INFOG(2), mumps->ICNTL(14)) + "."));
    return true;
  }


  void
  MumpsCholeskyFactor::copy_upper_triangle(const Epetra_CrsMatrix &matrix)
  {
    const int n_rows = matrix.NumMyRows();
    owned_rows.resize(n_rows);
    row_indices.clear();
    column_indices.clear();
    values.clear();
    // Row i's entries with column j >= i, in MUMPS's 1-based numbering;
    // the matrix is symmetric, so the upper triangle is all of it (MUMPS
    // would add an entry given twice).
    for (int row = 0; row < n_rows; ++row)
      {
        int     n_in_row    = 0;
        double *row_values  = nullptr;
        int    *row_columns = nullptr;
        matrix.ExtractMyRowView(row, n_in_row, row_values, row_columns);
        const int i     = matrix.RowMap().GID(row);
        owned_rows[row] = i;
        for (int k = 0; k < n_in_row; ++k)
          if (const int j = matrix.ColMap().GID(row_columns[k]); j >= i)
            {
              row_indices.push_back(i + 1);
              column_indices.push_back(j + 1);
              values.push_back(row_values[k]);
            }
      }
  }


  void
  MumpsCholeskyFactor::plan_gathering(const Epetra_CrsMatrix &matrix)
  {
    const int n_rows = matrix.NumMyRows();
    // Where each rank's entries go in a gathered vector, on the host.
    const bool host    = Utilities::MPI::this_mpi_process(comm) == 0;
    const int  n_ranks = Utilities::MPI::n_mpi_processes(comm);
    counts.assign(host ? n_ranks : 0, 0);
    MPI_Gather(&n_rows, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
    offsets.assign(counts.size(), 0);
    if (host)
      std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
    all_rows.resize(host ? matrix.NumGlobalRows() : 0);
    MPI_Gatherv(owned_rows.data(),
                n_rows,
                MPI_INT,
                all_rows.data(),
                counts.data(),
                offsets.data(),
                MPI_INT,
                0,
                comm);
    gathered.resize(all_rows.size());
    rhs.resize(all_rows.size());
  }


  bool
  MumpsCholeskyFactor::factorize(const LA::MPI::SparseMatrix &A)
  {
    const Epetra_CrsMatrix &matrix = A.trilinos_matrix();
    copy_upper_triangle(matrix);
    plan_gathering(matrix);

    mumps->n         = matrix.NumGlobalRows();
    mumps->nnz_loc   = values.size();
    mumps->irn_loc   = row_indices.data();
    mumps->jcn_loc   = column_indices.data();
    mumps->a_loc     = values.data();
    mumps->nrhs      = 1;
    mumps->lrhs      = mumps->n;
    mumps->rhs       = rhs.data();
    mumps->ICNTL(14) = 20;
    run(analyse, "analysis");
    // MUMPS sizes its work arrays from the analysis' estimate plus a
    // margin; delayed pivots and parallel scheduling can exceed it. Each
    // retry doubles the margin (INFOG(1) is the same on every rank, so
    // every rank retries alike).
    mumps->job = factorise;
    dmumps_c(mumps.get());
    for (int retry = 0; retry < 4 && workspace_too_small(mumps->INFOG(1));
         ++retry)
      {
        mumps->ICNTL(14) *= 2;
        dmumps_c(mumps.get());
      }
    return succeeded("factorisation");
  }


  void
  MumpsCholeskyFactor::substitute(LA::MPI::Vector &x, const LA::MPI::Vector &b)
  {
    const int n_rows = owned_rows.size();
    MPI_Gatherv(b.begin(),
                n_rows,
                MPI_DOUBLE,
                gathered.data(),
                counts.data(),
                offsets.data(),
                MPI_DOUBLE,
                0,
                comm);
    for (std::size_t k = 0; k < all_rows.size(); ++k)
      rhs[all_rows[k]] = gathered[k];
    run(solve, "substitution");
    for (std::size_t k = 0; k < all_rows.size(); ++k)
      gathered[k] = rhs[all_rows[k]];
    MPI_Scatterv(gathered.data(),
                 counts.data(),
                 offsets.data(),
                 MPI_DOUBLE,
                 x.begin(),
                 n_rows,
                 MPI_DOUBLE,
                 0,
                 comm);
  }

} // namespace liftoff
