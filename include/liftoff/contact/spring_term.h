#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/archive_types.h>
#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/foundation_points.h>

#include <functional>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The foundation's term over the Gauss points S in contact,
   * sum_q status_q k JxW_q phi_i phi_j + status_q G_p JxW_q grad phi_i .
   * grad phi_j (the second term with a shear layer only): the one place it
   * is coded (cell_weights()), for each of its uses:
   *  - assemble() and update_matrix(): K_f(S) in a system matrix, all of it
   *    once and then only the points whose status changed since, so that
   *    an active-set iteration costs a pass over the flipped points, not a
   *    reassembly; the class keeps the status the matrix holds;
   *  - add_change_product(): the product with the change of that matrix
   *    since it held another status, applied through w at the points;
   *  - add_product(): K_f(S) u, the springs' and layer's reaction;
   *  - add_integral(): k int_S f phi_i, the springs' term alone applied to
   *    a field at the points (the gap load, the dashpots' force).
   * k is an argument: the matrix's Gamma + c kappa, the reaction's Gamma.
   */
  class SpringTerm
  {
  public:
    /// The term over `points`, with the layer's modulus G_p (0: none); a
    /// matrix is taken to hold `status`.
    void
    setup(const FoundationPoints           &points,
          const double                      layer_modulus,
          const std::vector<unsigned char> &status);

    /// Point i's status has changed: update_matrix() looks at it.
    void
    status_changed(const unsigned int i);

    /// matrix += K_f(status) with the stiffness k; `matrix` now holds
    /// `status` (status_in_matrix()). Collective.
    void
    assemble(const std::vector<unsigned char> &status,
             const double                      k,
             LA::MPI::SparseMatrix            &matrix);
    /// matrix += K_f(status), recording nothing: to build again a matrix
    /// that was built from `status`. Collective.
    void
    add_to_matrix(const std::vector<unsigned char> &status,
                  const double                      k,
                  LA::MPI::SparseMatrix            &matrix) const;
    /// The status whose K_f the matrix of assemble() and update_matrix()
    /// holds.
    const std::vector<unsigned char> &
    status_in_matrix() const;
    /// Bring that matrix, built with the stiffness k, up to `status`: only
    /// the points that changed are touched. Returns the number of points
    /// updated over all ranks (0: `matrix` is unchanged).
    unsigned long
    update_matrix(const std::vector<unsigned char> &status,
                  const double                      k,
                  LA::MPI::SparseMatrix            &matrix);

    /// dst += (K_f(status_in_matrix()) - K_f(reference)) src with the
    /// stiffness k, from the cells whose status differs. `ghosted_src`
    /// must satisfy the constraints; `dst` has no ghosts. Collective.
    void
    add_change_product(const std::vector<unsigned char> &reference,
                       const double                      k,
                       const LA::MPI::Vector            &ghosted_src,
                       LA::MPI::Vector                  &dst) const;
    /// vector += K_f(status) u with the springs' stiffness k. Collective.
    void
    add_product(const std::vector<unsigned char> &status,
                const double                      k,
                const LA::MPI::Vector            &ghosted_u,
                LA::MPI::Vector                  &vector) const;
    /// vector += k int_S f phi_i, f at the points of owned cell c given by
    /// f(c, values). Collective.
    void
    add_integral(
      const std::vector<unsigned char> &status,
      const double                      k,
      const std::function<void(const unsigned int, std::vector<double> &)> &f,
      LA::MPI::Vector &vector) const;

    /// The status the matrix holds and the points that may differ from it.
    void
    save(OutputArchive &archive) const;
    void
    load(InputArchive &archive);

  private:
    const FoundationPoints *points        = nullptr;
    double                  layer_modulus = 0;
    /// The status that the matrix given to assemble() holds, and the
    /// points whose status may differ from it.
    std::vector<unsigned char> in_matrix;
    std::vector<unsigned int>  points_to_update;

    /// factor(i) k JxW_i and factor(i) G_p JxW_i at the points i of owned
    /// cell c, factor(i) the status of point i or its change (-1, 0, 1):
    /// the term's coefficient, formed here only. Returns whether some
    /// factor is not 0.
    template <class Factor>
    bool
    cell_weights(const unsigned int   c,
                 const Factor        &factor,
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
