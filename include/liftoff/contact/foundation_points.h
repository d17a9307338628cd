#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/discretization.h>

#include <functional>
#include <memory>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The foundation's quadrature data: the (p+1)^2 Gauss points of the
   * locally owned cells, numbered cell by cell (point i = c n_q + q of owned
   * cell c), with their JxW and position, the w shape functions' values
   * (the same on every cell) and, for a shear layer, gradients, and each
   * cell's w dofs with their constraints. It reads w_h at the points and
   * sends cell vectors and matrices of the w dofs to global ones.
   *
   * A flat store rather than deal.II's CellDataStorage: the contact status
   * is one vector over these points that the active-set iteration copies,
   * compares and checkpoints as a whole, and the cached positions of the w
   * dofs in Epetra vectors (positions_in()) need one numbering of them.
   */
  class FoundationPoints
  {
  public:
    /// The points of `discretization`'s owned cells; the shape gradients
    /// only `with_gradients`.
    void
    setup(const Discretization &discretization, const bool with_gradients);
    /// A field the points measure: `factor` times a component.
    struct Part
    {
      unsigned int component;
      double       factor;
    };
    /// The same points measuring the sum of the `measured` fields (the
    /// bed's: its component, 1; an interface's: the slab's w, 1, and the
    /// base's, -1) instead of the bed's w: "w" below is that sum.
    void
    setup(const Discretization   &discretization,
          const bool              with_gradients,
          const std::vector<Part> measured);

    const Discretization &
    discretization() const;

    /// Points and owned cells of this rank, points per cell, w dofs per
    /// cell.
    unsigned int
    n_points() const;
    unsigned int
    n_cells() const;
    unsigned int
    n_q_points() const;
    unsigned int
    n_w_dofs() const;

    double
    JxW(const unsigned int i) const;
    const Point<2> &
    point(const unsigned int i) const;
    /// The active cell index of owned cell c.
    unsigned int
    active_cell_index(const unsigned int c) const;

    /// phi_k(x_q), the same on every cell.
    double
    shape_value(const unsigned int q, const unsigned int k) const;
    /// grad phi_k(x_q) on owned cell c for k = 0, ..., n_w_dofs() - 1.
    const Tensor<1, 2> *
    shape_gradients(const unsigned int c, const unsigned int q) const;

    /// u_h's w at the points of owned cell c (u ghosted).
    void
    values_at_points(const LA::MPI::Vector &u,
                     const unsigned int     c,
                     std::vector<double>   &values) const;
    /// grad w of u_h at the points of owned cell c (with gradients).
    void
    gradients_at_points(const LA::MPI::Vector     &u,
                        const unsigned int         c,
                        std::vector<Tensor<1, 2>> &gradients) const;

    /// vector += the cell vectors f(c, cell_vector) (zeroed before) of the
    /// owned cells, condensed. Collective (compress).
    void
    add_cell_vectors(
      const std::function<void(const unsigned int, Vector<double> &)> &f,
      LA::MPI::Vector &vector) const;

    /// dst += the vector of owned cell c, condensed: written straight into
    /// dst's own storage where it holds the entry. dst has no ghosts; call
    /// dst.compress(VectorOperation::add) after the last cell.
    void
    add_cell_vector(const unsigned int    c,
                    const Vector<double> &cell_vector,
                    LA::MPI::Vector      &dst) const;

    /// matrix += the matrix of owned cell c, without the constrained rows
    /// and columns (condensed on a cell with hanging nodes). Call
    /// matrix.compress(VectorOperation::add) after the last cell.
    void
    add_cell_matrix(const unsigned int        c,
                    const FullMatrix<double> &cell_matrix,
                    LA::MPI::SparseMatrix    &matrix) const;

  private:
    const Discretization *mesh              = nullptr;
    unsigned int          q_points_per_cell = 0;
    /// Local indices (within a cell) of the w shape functions.
    std::vector<unsigned int> w_dofs;
    FullMatrix<double>        values;
    /// grad phi_k(x_q) per (owned cell, q, k): only with gradients.
    std::vector<Tensor<1, 2>> gradients;
    /// Flat per (owned cell, q) or per (owned cell, w dof) data.
    std::vector<types::global_dof_index> cell_w_dof_indices;
    std::vector<unsigned int>            cell_index;
    std::vector<double>                  jxw;
    std::vector<Point<2>>                gauss_points;
    /// Whether dof i (by local w index within a cell c) is constrained;
    /// constrained rows and columns carry no foundation term.
    std::vector<unsigned char> cell_w_dof_is_constrained;
    /// Whether an owned cell has a hanging w node (an adaptive mesh).
    std::vector<unsigned char> cell_has_hanging_node;

    /// Where the entries of cell_w_dof_indices sit in the local storage
    /// (owned and ghost entries) of ghosted vectors of one layout. Epetra
    /// finds a global index in a ghosted layout through a hash table, one
    /// lookup per cell and w dof at every contact update; the Example 2
    /// pulse's contact updates took 0.083 s before and 0.071 s after.
    /// Kept per layout: the copy of the map holds Epetra's map data, so its
    /// address, which identifies the layout, cannot pass to another map.
    struct LocalPositions
    {
      std::unique_ptr<Epetra_BlockMap> map;
      /// -1 stands for the entries `map` does not hold (positions_in()).
      bool             owned_only = false;
      std::vector<int> positions;
    };
    mutable std::vector<LocalPositions> local_positions;

    /// The positions of cell_w_dof_indices in the storage of u, which
    /// must hold every one of them (a ghosted vector); with `owned_only`,
    /// -1 for those it does not hold (a vector without ghosts).
    const int *
    positions_in(const LA::MPI::Vector &u, const bool owned_only = false) const;

    /// Append the w dofs of a cell (of global dofs `dofs`) and whether
    /// they are constrained.
    void
    add_cell_dofs(const std::vector<types::global_dof_index> &dofs);

    /// add_cell_matrix() for a cell with hanging nodes: the cell matrix
    /// condensed with the constraints.
    void
    add_condensed(const unsigned int        c,
                  const FullMatrix<double> &cell_matrix,
                  LA::MPI::SparseMatrix    &matrix) const;
  };
} // namespace liftoff
