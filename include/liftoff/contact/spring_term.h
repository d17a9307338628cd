#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/foundation_points.h>

#include <functional>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The foundation's springs over Gauss points S of given factors,
   * sum_q f_q k JxW_q phi_i phi_j + f_q G_p JxW_q grad phi_i . grad phi_j
   * (the second term with a shear layer only), f_q a point's status or its
   * change (-1, 0, 1): the one place it is coded (cell_weights()), for each
   * of its uses:
   *  - add_to_matrix(): the term in a system matrix, over every cell or
   *    only those of listed points (the points whose status changed);
   *  - add_product(): the same term times a vector, through w at the
   *    points (the product with a change of the matrix);
   *  - add_reaction(): K_f(S) u, the springs' and layer's reaction;
   *  - add_integral(): k int_S f phi_i, the springs' term alone applied to
   *    a field at the points (the gap load, the dashpots' force).
   * k is an argument: the matrix's Gamma + c kappa, the reaction's Gamma.
   * The statuses themselves are the StatusTerm's.
   */
  class SpringTerm
  {
  public:
    /// A point's factor, by its number.
    using Factor = std::function<double(unsigned int)>;

    /// The term over `points`, with the layer's modulus G_p (0: none).
    void
    setup(const FoundationPoints &points, const double layer_modulus);

    /// matrix += the term with `factor` and the stiffness k, over every
    /// owned cell or (`listed`, ascending) the cells of the listed points.
    /// No compress.
    void
    add_to_matrix(const Factor                    &factor,
                  const std::vector<unsigned int> *listed,
                  const double                     k,
                  LA::MPI::SparseMatrix           &matrix) const;

    /// dst += the term with `factor` and k times src, from the cells with
    /// a factor that is not 0. `ghosted_src` must satisfy the constraints;
    /// `dst` has no ghosts. Collective.
    void
    add_product(const Factor          &factor,
                const double           k,
                const LA::MPI::Vector &ghosted_src,
                LA::MPI::Vector       &dst) const;

    /// vector += K_f(status) u with the springs' stiffness k. Collective.
    void
    add_reaction(const std::vector<unsigned char> &status,
                 const double                      k,
                 const LA::MPI::Vector            &ghosted_u,
                 LA::MPI::Vector                  &vector) const;

    /// vector += k int_S factor f phi_i, f at the points of owned cell c
    /// given by f(c, values). Collective.
    void
    add_integral(
      const Factor &factor,
      const double  k,
      const std::function<void(const unsigned int, std::vector<double> &)> &f,
      LA::MPI::Vector &vector) const;

  private:
    const FoundationPoints *points        = nullptr;
    double                  layer_modulus = 0;

    /// factor(i) k JxW_i and factor(i) G_p JxW_i at the points i of owned
    /// cell c: the term's coefficient, formed here only. Returns whether
    /// some factor is not 0.
    template <class FactorOf>
    bool
    cell_weights(const unsigned int   c,
                 const FactorOf      &factor,
                 const double         k,
                 std::vector<double> &weight,
                 std::vector<double> &layer_weight) const;

    /// cell_vector(k) = sum_q weight[q] values[q] phi_k(x_q): the springs'
    /// term applied to a field at the points of a cell.
    void
    apply_weights(const std::vector<double> &weight,
                  const std::vector<double> &values,
                  Vector<double>            &cell_vector) const;

    /// The cell matrix sum_q weight[q] phi phi^T + layer_weight[q] grad phi
    /// grad phi^T of owned cell c, added to `matrix`.
    void
    add_cell_term(const unsigned int         c,
                  const std::vector<double> &weight,
                  const std::vector<double> &layer_weight,
                  LA::MPI::SparseMatrix     &matrix) const;

    /// The same cell term times u, through w (and grad w) at the points:
    /// 2 n_q n_w operations instead of n_q n_w^2. A term whose weights are
    /// all 0 is skipped.
    void
    cell_product(const unsigned int         c,
                 const std::vector<double> &weight,
                 const std::vector<double> &layer_weight,
                 const LA::MPI::Vector     &ghosted_u,
                 Vector<double>            &cell_vector) const;
  };
} // namespace liftoff
