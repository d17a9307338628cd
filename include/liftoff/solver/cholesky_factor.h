#pragma once

#include <cholmod.h>

#include <vector>

class Epetra_CrsMatrix;

namespace liftoff
{
  /**
   * CHOLMOD's sparse Cholesky factor P A P^T = L L^T of a symmetric
   * positive definite matrix held on one rank, with CHOLMOD's fill-reducing
   * ordering (AMD or METIS, its choice).
   *
   * A supernodal factor is substituted by this class, not by CHOLMOD: each
   * supernode's dense block [L_ss; L_rs] (its columns' triangle and the rows
   * below) is replaced once, after the factorisation, by
   * G = [L_ss^{-1}; L_rs L_ss^{-1}] in the same storage. Then each pass of a
   * substitution costs one matrix-vector product with G per supernode,
   * where CHOLMOD's own solve needs a triangular solve (level-1 BLAS on
   * small blocks) and a product. Forward: t = G y_s gives y_s = t_s and the
   * update y_r -= t_r; backward: x_s = G^T [x_s; -x_r]. Substitutions are
   * memory-bound, and this reads each entry once per pass, in storage
   * order: on the benchmark L, p = 1 (1.5e8 entries) a substitution took
   * 0.121 s against CHOLMOD's 0.263 s, on M 21.9 against 48.7 ms
   * (doc/performance.md, "The substitution"). A simplicial factor
   * (small matrices), or one with a block whose triangle is ill-conditioned
   * (the partitioned inverse's error grows with that condition), is
   * substituted by CHOLMOD.
   *
   * A substitution reuses the workspace of the previous one, so it
   * allocates nothing.
   */
  class CholeskyFactor
  {
  public:
    CholeskyFactor();
    ~CholeskyFactor();

    CholeskyFactor(const CholeskyFactor &) = delete;
    CholeskyFactor &
    operator=(const CholeskyFactor &) = delete;

    /// Factorise A (all rows on this rank, in Epetra's packed storage,
    /// numbered in order). Returns false if A is not positive definite (or
    /// CHOLMOD fails otherwise).
    bool
    factorize(const Epetra_CrsMatrix &A);

    /// x = A^{-1} b, both of length n.
    void
    substitute(double *x, const double *b);

    /// Whether substitute() uses inverted blocks: the factor is supernodal
    /// and the reciprocal condition number of each block's triangle
    /// (LAPACK's estimate) is at least 1e-6.
    bool
    has_inverted_blocks() const;

    /// The smallest reciprocal condition number of the triangles of a
    /// supernodal factor's blocks (1 for a simplicial factor).
    double
    smallest_block_rcond() const;

    /// The cost of a factorisation (with the inversion of the blocks) and
    /// of one substitution in floating-point operations.
    double
    factorization_cost() const;
    double
    substitution_flops() const;

  private:
    cholmod_common  common;
    int             n                   = 0;
    double          n_entries_of_matrix = 0;
    double          inversion_flops     = 0;
    bool            is_inverted         = false;
    double          smallest_rcond      = 1;
    cholmod_factor *factor              = nullptr;
    // CHOLMOD's solution and workspace (simplicial factors), kept between
    // substitutions.
    cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
    // The permuted vector and one supernode's rows (supernodal factors).
    std::vector<double> permuted, block_vector;

    bool
    blocks_are_well_conditioned();
    bool
    invert_diagonal_blocks();
    void
    substitute_supernodal(double *x_out, const double *b_in);
  };
} // namespace liftoff
