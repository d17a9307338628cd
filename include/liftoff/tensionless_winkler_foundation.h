#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <liftoff/discretization.h>
#include <liftoff/linear_algebra.h>

#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * Winkler springs that push but never pull: the reaction is
   * r = -Gamma max(w, 0). Following eqs. (3.7c)-(3.8), the foundation
   * stiffness is integrated with the (p+1)^2 Gauss rule and a Gauss point
   * contributes only while w_h > 0 there. This class owns that contact
   * status, one flag per Gauss point of the locally owned cells.
   *
   * The `bilateral` model keeps every point active (linear springs), and
   * `none` removes the foundation.
   */
  class TensionlessWinklerFoundation
  {
  public:
    enum class Model
    {
      tensionless,
      bilateral,
      none
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    void
    setup(const Discretization &discretization);

    /// Every Gauss point in contact: the first iterate of eq. (3.9).
    void
    activate_all();

    /// Status from w_h at the Gauss points. Returns the number of points
    /// (over all ranks) whose status changed.
    unsigned long
    update_contact_status(const LA::MPI::Vector &ghosted_solution);

    /// The foundation stiffness for the current status (matrix is zeroed).
    void
    assemble_matrix(LA::MPI::SparseMatrix &matrix) const;

    /// Energy stored in the springs, 1/2 Gamma int max(w,0)^2 (or w^2 when
    /// bilateral), on the meshed part.
    double
    energy(const LA::MPI::Vector &ghosted_solution) const;

    /// Area in contact over the area of the meshed part.
    double
    contact_area_fraction() const;

    /// Fraction of each locally owned cell's Gauss points in contact,
    /// indexed by active cell index, for output.
    Vector<float>
    contact_fraction_per_cell() const;

    Model  model     = Model::tensionless;
    double stiffness = 1.0;

  private:
    const Discretization *discretization = nullptr;
    unsigned int          n_q_points     = 0;
    /// Local indices (within a cell) of the w shape functions.
    std::vector<unsigned int> w_dofs;
    /// phi_i(x_q) for the w shape functions: the same on every cell.
    FullMatrix<double> shape_values;
    /// Flat per (owned cell, q) or per (owned cell, w dof) data.
    std::vector<types::global_dof_index> cell_w_dof_indices;
    std::vector<unsigned int>            cell_index;
    std::vector<double>                  jxw;
    std::vector<unsigned char>           in_contact;

    /// w_h at the Gauss points of owned cell c.
    void
    deflection_at_gauss_points(const LA::MPI::Vector &ghosted_solution,
                               const unsigned int     c,
                               std::vector<double>   &w) const;
  };
} // namespace liftoff
