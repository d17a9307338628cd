// What a factor kept current by low-rank updates would cost (issue 36):
// CHOLMOD's rank-k update/downdate of a simplicial LDL^T factor
// (cholmod_updown) against a supernodal factorisation and one substitution,
// on a system matrix written by liftoff (factor_update.sh).
//
//   factor_update_cost MATRIX.mtx RANK...
//
// A spring that enters or leaves contact at a Gauss point changes the
// matrix by +-Gamma JxW N N^T, N the point's w shape functions: a rank-1
// term whose pattern is a clique of the matrix's graph. Its cost in
// cholmod_updown is that of the path in the elimination tree from its
// first row to the root, which a column with two entries of one row of the
// matrix (a row and one of its neighbours; no fill) has as well. The
// columns are drawn at random rows of the permuted matrix; each rank is
// timed as an update and the downdate that undoes it, three times.
#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace
{
  double
  seconds()
  {
    return std::chrono::duration<double>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
  }

  // Median of `runs` timings of f.
  template <typename F>
  double
  median_time(const int runs, F f)
  {
    std::vector<double> t;
    for (int r = 0; r < runs; ++r)
      {
        const double start = seconds();
        f();
        t.push_back(seconds() - start);
      }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  }
} // namespace


int
main(int argc, char **argv)
{
  if (argc < 3)
    {
      std::fprintf(stderr, "usage: %s MATRIX.mtx RANK...\n", argv[0]);
      return 2;
    }
  cholmod_common c;
  cholmod_start(&c);
  FILE *file = std::fopen(argv[1], "r");
  if (file == nullptr)
    {
      std::fprintf(stderr, "cannot read %s\n", argv[1]);
      return 1;
    }
  cholmod_sparse *A = cholmod_read_sparse(file, &c);
  std::fclose(file);
  const int n = A->nrow;

  c.supernodal            = CHOLMOD_SUPERNODAL;
  cholmod_factor *L_super = cholmod_analyze(A, &c);
  const double    t_super =
    median_time(3, [&] { cholmod_factorize(A, L_super, &c); });
  cholmod_dense *b = cholmod_ones(n, 1, CHOLMOD_REAL, &c);
  cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
  const double   s_super = median_time(21, [&] {
    cholmod_solve2(CHOLMOD_A, L_super, b, nullptr, &x, nullptr, &y, &e, &c);
  });

  c.supernodal          = CHOLMOD_SIMPLICIAL;
  c.final_ll            = 0;
  cholmod_factor *L     = cholmod_analyze(A, &c);
  const double t_simple = median_time(3, [&] { cholmod_factorize(A, L, &c); });
  const double s_simple = median_time(21, [&] {
    cholmod_solve2(CHOLMOD_A, L, b, nullptr, &x, nullptr, &y, &e, &c);
  });
  std::printf("unknowns %d, entries of the factor %.0f\n", n, c.lnz);
  std::printf("supernodal LL^T: factorisation %.4f s, substitution %.3f ms\n",
              t_super,
              s_super * 1e3);
  std::printf("simplicial LDL^T: factorisation %.4f s, substitution %.3f ms\n",
              t_simple,
              s_simple * 1e3);

  // The permuted matrix's full pattern, to draw columns from.
  cholmod_sparse *full = cholmod_copy(A, 0, 1, &c);
  cholmod_sparse *PA   = cholmod_submatrix(full,
                                         static_cast<int *>(L->Perm),
                                         n,
                                         static_cast<int *>(L->Perm),
                                         n,
                                         1,
                                         1,
                                         &c);
  const int   *Ap = static_cast<int *>(PA->p), *Ai = static_cast<int *>(PA->i);
  std::mt19937 random(1);
  for (int i = 2; i < argc; ++i)
    {
      const int           k = std::atoi(argv[i]);
      std::vector<double> t;
      for (int repetition = 0; repetition < 3; ++repetition)
        {
          cholmod_triplet *T =
            cholmod_allocate_triplet(n, k, 2 * k, 0, CHOLMOD_REAL, &c);
          auto add = [&](const int row, const int column, const double value) {
            static_cast<int *>(T->i)[T->nnz]    = row;
            static_cast<int *>(T->j)[T->nnz]    = column;
            static_cast<double *>(T->x)[T->nnz] = value;
            ++T->nnz;
          };
          for (int j = 0; j < k; ++j)
            {
              const int row =
                std::uniform_int_distribution<int>(0, n - 1)(random);
              const int neighbour = Ai[Ap[row]
                                       + std::uniform_int_distribution<int>(
                                         0, Ap[row + 1] - Ap[row] - 1)(random)];
              add(row, j, 1e-3);
              if (neighbour != row)
                add(neighbour, j, 5e-4);
            }
          cholmod_sparse *C = cholmod_triplet_to_sparse(T, 0, &c);
          cholmod_sort(C, &c);
          for (const int update : {1, 0})
            {
              const double start = seconds();
              cholmod_updown(update, C, L, &c);
              t.push_back(seconds() - start);
            }
          cholmod_free_sparse(&C, &c);
          cholmod_free_triplet(&T, &c);
        }
      std::sort(t.begin(), t.end());
      std::printf("rank-%d update: %.3f ms (median of 6), %.1f substitutions, "
                  "%.2f supernodal factorisations\n",
                  k,
                  t[t.size() / 2] * 1e3,
                  t[t.size() / 2] / s_super,
                  t[t.size() / 2] / t_super);
    }
  cholmod_finish(&c);
  return 0;
}
