#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <liftoff/solver/cholesky_factor.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <cstring>

extern "C" {
// LAPACK and BLAS, which deal.II links; lapack_templates.h has no
// wrappers for the triangular inverse and the triangular solve with a
// matrix right-hand side.
void
dtrtri_(const char *uplo,
        const char *diag,
        const int  *n,
        double     *a,
        const int  *lda,
        int        *info);
void
dtrsm_(const char   *side,
       const char   *uplo,
       const char   *trans,
       const char   *diag,
       const int    *m,
       const int    *n,
       const double *alpha,
       const double *a,
       const int    *lda,
       double       *b,
       const int    *ldb);
}

namespace liftoff
{
  using namespace dealii;

  namespace
  {
    // A view of A's own arrays in CHOLMOD's form. On one rank the rows
    // and columns are numbered 0, ..., n-1 in order, and A is symmetric,
    // so its rows are its columns: row i's entries with column j >= i (the
    // upper triangle by rows) are column i of the lower triangle, which is
    // all CHOLMOD reads with stype -1. Nothing is copied (L: 170 MB).
    cholmod_sparse
    lower_triangle_view(const Epetra_CrsMatrix &A)
    {
      const Epetra_Map &columns = A.ColMap();
      AssertThrow(A.StorageOptimized() && A.RowMap().LinearMap()
                    && A.RowMap().MinMyGID() == 0 && columns.LinearMap()
                    && columns.MinMyGID() == 0
                    && columns.NumMyElements() == A.NumMyRows(),
                  ExcMessage("CHOLMOD needs the whole matrix on one rank in "
                             "Epetra's packed storage, numbered in order."));
      int    *offsets = nullptr;
      int    *indices = nullptr;
      double *values  = nullptr;
      A.ExtractCrsDataPointers(offsets, indices, values);
      cholmod_sparse view{};
      view.nrow  = A.NumMyRows();
      view.ncol  = A.NumMyRows();
      view.nzmax = A.NumMyNonzeros();
      view.p     = offsets;
      view.i     = indices;
      view.x     = values;
      view.stype = -1;
      view.itype = CHOLMOD_INT;
      view.xtype = CHOLMOD_REAL;
      view.dtype = CHOLMOD_DOUBLE;
      // (Epetra sorts each row, but does not say so publicly; CHOLMOD's
      // permuted transpose sorts anyway.)
      view.sorted = false;
      view.packed = true;
      return view;
    }

    // A substitution reads the whole factor twice and is bound by memory
    // bandwidth, so the products below are written for the order of the
    // reads, not for the arithmetic: each pass reads G column by column in
    // storage order (ascending in the forward pass, descending in the
    // backward pass, which visits the supernodes last to first), one
    // stream the hardware prefetcher can follow across blocks. BLAS's
    // dgemv and loops over several columns at once read several short
    // streams per block and reached half the bandwidth (M: 42 ms against
    // 20 ms, doc/performance.md, "The substitution"). GCC's vector type
    // gives SIMD products without -ffast-math, in a summation order that
    // is the same on every machine (only the AVX2 clone's fused
    // multiply-adds round differently).
    constexpr int width = 4;
    using Packet        = double __attribute__((vector_size(8 * width)));

    inline __attribute__((always_inline)) Packet
    load(const double *p)
    {
      Packet r;
      std::memcpy(&r, p, sizeof(Packet));
      return r;
    }

    inline __attribute__((always_inline)) void
    store(double *p, const Packet r)
    {
      std::memcpy(p, &r, sizeof(Packet));
    }

    inline __attribute__((always_inline)) double
    sum_of(const Packet a)
    {
      double s = 0;
      for (int k = 0; k < width; ++k)
        s += a[k];
      return s;
    }

// AVX2 and FMA where the processor has them, chosen when the program
// loads: Debian builds for plain x86-64.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define LIFTOFF_CLONES \
  __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define LIFTOFF_CLONES
#endif

    /// t = G y, G with m rows and n columns, column-major.
    LIFTOFF_CLONES void
    multiply(const double *G,
             const int     m,
             const int     n,
             const double *y,
             double       *t)
    {
      std::fill(t, t + m, 0.0);
      for (int j = 0; j < n; ++j)
        {
          const double *column = G + std::size_t(j) * m;
          const double  yj     = y[j];
          int           i      = 0;
          for (; i + width <= m; i += width)
            store(t + i, load(t + i) + load(column + i) * yj);
          for (; i < m; ++i)
            t[i] += column[i] * yj;
        }
    }

    /// y = G^T t, reading G from its last entry to its first.
    LIFTOFF_CLONES void
    multiply_transposed(const double *G,
                        const int     m,
                        const int     n,
                        const double *t,
                        double       *y)
    {
      constexpr int chunk = 4 * width;
      const int     head  = m % chunk;
      for (int j = n - 1; j >= 0; --j)
        {
          const double *column = G + std::size_t(j) * m;
          Packet        s0 = {}, s1 = {}, s2 = {}, s3 = {};
          for (int i = m - chunk; i >= head; i -= chunk)
            {
              s3 += load(column + i + 3 * width) * load(t + i + 3 * width);
              s2 += load(column + i + 2 * width) * load(t + i + 2 * width);
              s1 += load(column + i + width) * load(t + i + width);
              s0 += load(column + i) * load(t + i);
            }
          double sum = sum_of((s0 + s1) + (s2 + s3));
          for (int i = head - 1; i >= 0; --i)
            sum += column[i] * t[i];
          y[j] = sum;
        }
    }
  } // namespace


  CholeskyFactor::CholeskyFactor()
  {
    cholmod_start(&common);
    // Errors are reported through `common.status`, not printed.
    common.print         = 0;
    common.error_handler = nullptr;
  }


  CholeskyFactor::~CholeskyFactor()
  {
    for (cholmod_dense **d : {&x, &y, &e})
      cholmod_free_dense(d, &common);
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }


  bool
  CholeskyFactor::factorize(const Epetra_CrsMatrix &A)
  {
    n                    = A.NumMyRows();
    n_entries_of_matrix  = A.NumMyNonzeros();
    inversion_flops      = 0;
    smallest_rcond       = 1;
    cholmod_sparse lower = lower_triangle_view(A);
    cholmod_free_factor(&factor, &common);
    factor                   = cholmod_analyze(&lower, &common);
    const bool is_factorized = factor != nullptr
                               && cholmod_factorize(&lower, factor, &common)
                               && common.status == CHOLMOD_OK;
    // The factor stays supernodal (dense blocks): its substitution is the
    // faster one (M: 48 against 63 ms for CHOLMOD's simplicial form), and
    // converting needs both forms in memory at once (M: 8 % more peak
    // memory). doc/performance.md, "OpenBLAS and a supernodal factor".
    is_inverted = is_factorized && factor->is_super
                  && blocks_are_well_conditioned() && invert_diagonal_blocks();
    return is_factorized;
  }


  bool
  CholeskyFactor::has_inverted_blocks() const
  {
    return is_inverted;
  }


  double
  CholeskyFactor::smallest_block_rcond() const
  {
    return smallest_rcond;
  }


  bool
  CholeskyFactor::blocks_are_well_conditioned()
  {
    // The partitioned inverse's error grows with the condition of the
    // inverted blocks (Higham and Pothen, SIAM J. Sci. Comput. 15, 1994);
    // a triangular solve is backward stable whatever that condition. A
    // factor with an ill-conditioned block is left to CHOLMOD's solves.
    const int          *super = static_cast<const int *>(factor->super);
    const int          *pi    = static_cast<const int *>(factor->pi);
    const int          *px    = static_cast<const int *>(factor->px);
    const double       *lx    = static_cast<const double *>(factor->x);
    std::vector<double> work;
    std::vector<types::blas_int> integer_work;
    smallest_rcond = 1;
    for (std::size_t s = 0; s < factor->nsuper; ++s)
      {
        const types::blas_int n_columns = super[s + 1] - super[s];
        const types::blas_int n_rows    = pi[s + 1] - pi[s];
        work.resize(3 * n_columns);
        integer_work.resize(n_columns);
        double          rcond = 0;
        types::blas_int info  = 0;
        trcon("1",
              "L",
              "N",
              &n_columns,
              lx + px[s],
              &n_rows,
              &rcond,
              work.data(),
              integer_work.data(),
              &info);
        smallest_rcond = std::min(smallest_rcond, info == 0 ? rcond : 0.0);
      }
    return smallest_rcond >= 1e-6;
  }


  bool
  CholeskyFactor::invert_diagonal_blocks()
  {
    const int *super = static_cast<const int *>(factor->super);
    const int *pi    = static_cast<const int *>(factor->pi);
    const int *px    = static_cast<const int *>(factor->px);
    double    *lx    = static_cast<double *>(factor->x);
    int        rows  = 0;
    for (std::size_t s = 0; s < factor->nsuper; ++s)
      {
        const int n_columns = super[s + 1] - super[s];
        const int n_rows    = pi[s + 1] - pi[s];
        const int n_below   = n_rows - n_columns;
        rows                = std::max(rows, n_rows);
        // Column-major, n_rows x n_columns. CHOLMOD leaves the strict upper
        // part of the triangle's block unspecified; G's product reads it.
        double *block = lx + px[s];
        for (int j = 1; j < n_columns; ++j)
          std::fill(block + j * n_rows, block + j * n_rows + j, 0.0);
        // L_rs L_ss^{-1} needs L_ss itself, so it comes first.
        const double one = 1;
        if (n_below > 0)
          dtrsm_("R",
                 "L",
                 "N",
                 "N",
                 &n_below,
                 &n_columns,
                 &one,
                 block,
                 &n_rows,
                 block + n_columns,
                 &n_rows);
        int info = 0;
        dtrtri_("L", "N", &n_columns, block, &n_rows, &info);
        // L's diagonal is positive once cholmod_factorize succeeded.
        AssertThrow(info == 0,
                    ExcMessage("Inverting a block of CHOLMOD's factor failed "
                               "(LAPACK's dtrtri: info = "
                               + std::to_string(info) + ")."));
        inversion_flops += double(n_columns) * n_columns * n_columns / 3.0
                           + double(n_below) * n_columns * n_columns;
      }
    permuted.resize(n);
    block_vector.resize(rows);
    return true;
  }


  void
  CholeskyFactor::substitute(double *x_out, const double *b_in)
  {
    if (is_inverted)
      {
        substitute_supernodal(x_out, b_in);
        return;
      }
    cholmod_dense b;
    b.nrow  = n;
    b.ncol  = 1;
    b.nzmax = n;
    b.d     = n;
    b.x     = const_cast<double *>(b_in);
    b.z     = nullptr;
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    AssertThrow(cholmod_solve2(
                  CHOLMOD_A, factor, &b, nullptr, &x, nullptr, &y, &e, &common),
                ExcMessage("CHOLMOD's substitution failed."));
    const double *solution = static_cast<const double *>(x->x);
    std::copy(solution, solution + n, x_out);
  }


  void
  CholeskyFactor::substitute_supernodal(double *x_out, const double *b_in)
  {
    const int    *super   = static_cast<const int *>(factor->super);
    const int    *pi      = static_cast<const int *>(factor->pi);
    const int    *px      = static_cast<const int *>(factor->px);
    const int    *row     = static_cast<const int *>(factor->s);
    const int    *perm    = static_cast<const int *>(factor->Perm);
    const double *lx      = static_cast<const double *>(factor->x);
    const int     n_super = factor->nsuper;
    double       *v       = permuted.data();
    double       *t       = block_vector.data();

    for (int k = 0; k < n; ++k)
      v[k] = b_in[perm[k]];

    // L y = P b. A supernode's first rows are its own columns, k1, k1 + 1,
    // ...; the rows below are listed in `row`.
    for (int s = 0; s < n_super; ++s)
      {
        const int k1        = super[s];
        const int n_columns = super[s + 1] - k1;
        const int n_rows    = pi[s + 1] - pi[s];
        multiply(lx + px[s], n_rows, n_columns, v + k1, t);
        std::copy(t, t + n_columns, v + k1);
        const int *below = row + pi[s];
        for (int i = n_columns; i < n_rows; ++i)
          v[below[i]] -= t[i];
      }

    // L^T z = y, then x = P^T z.
    for (int s = n_super - 1; s >= 0; --s)
      {
        const int  k1        = super[s];
        const int  n_columns = super[s + 1] - k1;
        const int  n_rows    = pi[s + 1] - pi[s];
        const int *below     = row + pi[s];
        std::copy(v + k1, v + k1 + n_columns, t);
        for (int i = n_columns; i < n_rows; ++i)
          t[i] = -v[below[i]];
        multiply_transposed(lx + px[s], n_rows, n_columns, t, v + k1);
      }
    for (int k = 0; k < n; ++k)
      x_out[perm[k]] = v[k];
  }


  double
  CholeskyFactor::factorization_cost() const
  {
    // CHOLMOD counts the operations of the numerical factorisation; the
    // rest (extracting the matrix, the ordering, the elimination tree)
    // grows with the entries of A. Measured on one core (doc/performance.md,
    // "When to factorise again"), a factorisation took 90 substitutions on the
    // Example 2 beam (246 unknowns; 2.4 by the count alone) and 58 on the
    // benchmark S (12 675; 35 by the count): 150 operations per entry of A
    // for the rest fits both within 20 %.
    return common.fl + inversion_flops + 150.0 * n_entries_of_matrix;
  }


  double
  CholeskyFactor::substitution_flops() const
  {
    return 4 * common.lnz;
  }
} // namespace liftoff
