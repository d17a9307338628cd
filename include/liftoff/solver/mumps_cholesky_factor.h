#pragma once

#include <liftoff/base/linear_algebra.h>

#include <memory>
#include <string>
#include <vector>

class Epetra_CrsMatrix;

namespace liftoff
{
  using namespace dealii;

  /**
   * MUMPS's Cholesky factor (SYM = 1) of a symmetric positive definite
   * matrix distributed over the ranks of its communicator, called through
   * MUMPS's own C interface: Trilinos Amesos, which LinearSolver uses for
   * MUMPS's LU, always asks MUMPS for a general LU (SYM = 0), twice the
   * factor and twice the memory traffic per substitution.
   *
   * Each rank hands MUMPS the upper triangle of the rows it owns (MUMPS's
   * distributed assembled input, ICNTL(18) = 3); MUMPS analyses and
   * factorises it in parallel. A substitution gathers the right-hand side on
   * rank 0 (MUMPS's host), substitutes in parallel and scatters the
   * solution back to the ranks that own it. MUMPS prints nothing; a failure
   * is an exception naming MUMPS's error code and its cause, thrown on
   * every rank alike (MUMPS's global status is the same on all).
   *
   * The MUMPS structure is kept out of this header.
   */
  class MumpsCholeskyFactor
  {
  public:
    explicit MumpsCholeskyFactor(const MPI_Comm comm);
    ~MumpsCholeskyFactor();

    MumpsCholeskyFactor(const MumpsCholeskyFactor &) = delete;
    MumpsCholeskyFactor &
    operator=(const MumpsCholeskyFactor &) = delete;

    /// Analyse and factorise A (collective). Returns false if A is not
    /// positive definite; throws for MUMPS's other errors.
    bool
    factorize(const LA::MPI::SparseMatrix &A);

    /// x = A^{-1} b (collective), x and b of A's row layout.
    void
    substitute(LA::MPI::Vector &x, const LA::MPI::Vector &b);

  private:
    /// DMUMPS_STRUC_C, which MUMPS's header declares as an unnamed struct.
    struct Mumps;
    std::unique_ptr<Mumps> mumps;
    MPI_Comm               comm;
    /// The rows of A this rank owns (global indices), and on rank 0 all
    /// ranks' in rank order with their counts and offsets: the order in
    /// which a substitution gathers and scatters vector entries.
    std::vector<int> owned_rows;
    std::vector<int> all_rows, counts, offsets;
    /// The gathered entries and the right-hand side / solution of length
    /// n on rank 0 (empty elsewhere), kept between substitutions.
    std::vector<double> gathered, rhs;
    /// The upper triangle of this rank's rows in MUMPS's coordinate form
    /// (1-based); MUMPS reads them during the factorisation.
    std::vector<int>    row_indices, column_indices;
    std::vector<double> values;

    /// row_indices, column_indices and values from this rank's rows.
    void
    copy_upper_triangle(const Epetra_CrsMatrix &matrix);
    /// Where each rank's rows go in the vectors gathered on rank 0.
    void
    plan_gathering(const Epetra_CrsMatrix &matrix);
    /// Run MUMPS's `job`; then succeeded().
    bool
    run(const int job, const std::string &what);
    /// Whether MUMPS's last job succeeded: false for a factorisation that
    /// found the matrix not positive definite; throws, naming `what` and
    /// MUMPS's error, for any other failure.
    bool
    succeeded(const std::string &what) const;
  };
} // namespace liftoff
