#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <liftoff/contact/foundation_points.h>
#include <liftoff/fem/plate_fields.h>

#include <algorithm>

namespace liftoff
{
  void
  FoundationPoints::setup(const Discretization &disc, const bool with_gradients)
  {
    const auto &fe = disc.dof_handler.get_fe();
    setup(disc, with_gradients, {{PlateFields::bed_component(fe), 1.0}});
  }


  void
  FoundationPoints::setup(const Discretization   &disc,
                          const bool              with_gradients,
                          const std::vector<Part> measured)
  {
    mesh               = &disc;
    const auto     &fe = disc.dof_handler.get_fe();
    const QGauss<2> rule(fe.degree + 1);
    q_points_per_cell = rule.size();

    w_dofs.clear();
    std::vector<double> signs;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      for (const Part &part : measured)
        if (fe.system_to_component_index(i).first == part.component)
          {
            w_dofs.push_back(i);
            signs.push_back(part.factor);
          }

    // Lagrange shape values at the Gauss points do not depend on the cell.
    values.reinit(q_points_per_cell, w_dofs.size());
    for (unsigned int q = 0; q < q_points_per_cell; ++q)
      for (unsigned int k = 0; k < w_dofs.size(); ++k)
        values(q, k) = signs[k] * fe.shape_value(w_dofs[k], rule.point(q));

    // Gradients only for a shear layer: they depend on the cell.
    FEValues<2>                          fe_values(disc.mapping(),
                          fe,
                          rule,
                          update_JxW_values | update_quadrature_points
                            | (with_gradients ? update_gradients
                                                                       : update_default));
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    cell_w_dof_indices.clear();
    local_positions.clear();
    cell_w_dof_is_constrained.clear();
    cell_has_hanging_node.clear();
    cell_index.clear();
    jxw.clear();
    gauss_points.clear();
    gradients.clear();
    for (const auto &cell : disc.locally_owned_cells())
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
        add_cell_dofs(dofs);
        for (unsigned int q = 0; q < q_points_per_cell; ++q)
          {
            jxw.push_back(fe_values.JxW(q));
            gauss_points.push_back(fe_values.quadrature_point(q));
            if (with_gradients)
              for (const unsigned int i : w_dofs)
                gradients.push_back(fe_values.shape_grad(i, q));
          }
        cell_index.push_back(cell->active_cell_index());
      }
  }


  void
  FoundationPoints::add_cell_dofs(
    const std::vector<types::global_dof_index> &dofs)
  {
    bool is_hanging = false;
    for (const unsigned int i : w_dofs)
      {
        cell_w_dof_indices.push_back(dofs[i]);
        // Constraints w_i = 0 (edges) drop a row and column of the cell
        // term; a hanging node (w_i a combination of other nodes) sends
        // them to those nodes (add_cell_matrix()).
        const auto *entries = mesh->constraints.get_constraint_entries(dofs[i]);
        is_hanging          = is_hanging || (entries && !entries->empty());
        cell_w_dof_is_constrained.push_back(
          mesh->constraints.is_constrained(dofs[i]));
      }
    cell_has_hanging_node.push_back(is_hanging);
  }


  const Discretization &
  FoundationPoints::discretization() const
  {
    return *mesh;
  }


  unsigned int
  FoundationPoints::n_points() const
  {
    return jxw.size();
  }


  unsigned int
  FoundationPoints::n_cells() const
  {
    return cell_index.size();
  }


  unsigned int
  FoundationPoints::n_q_points() const
  {
    return q_points_per_cell;
  }


  unsigned int
  FoundationPoints::n_w_dofs() const
  {
    return w_dofs.size();
  }


  double
  FoundationPoints::JxW(const unsigned int i) const
  {
    return jxw[i];
  }


  const Point<2> &
  FoundationPoints::point(const unsigned int i) const
  {
    return gauss_points[i];
  }


  unsigned int
  FoundationPoints::active_cell_index(const unsigned int c) const
  {
    return cell_index[c];
  }


  double
  FoundationPoints::shape_value(const unsigned int q,
                                const unsigned int k) const
  {
    return values(q, k);
  }


  const Tensor<1, 2> *
  FoundationPoints::shape_gradients(const unsigned int c,
                                    const unsigned int q) const
  {
    return &gradients[(c * q_points_per_cell + q) * w_dofs.size()];
  }


  const int *
  FoundationPoints::positions_in(const LA::MPI::Vector &u,
                                 const bool             owned_only) const
  {
    const Epetra_BlockMap &map = u.trilinos_vector().Map();
    for (const auto &known : local_positions)
      if (known.map->DataPtr() == map.DataPtr()
          && known.owned_only == owned_only)
        return known.positions.data();
    // The program's ghosted vectors come in a few layouts (solution,
    // velocity, scratch), and the solver's products one owned layout; a
    // few more would mean layouts made per call.
    if (local_positions.size() == 5)
      local_positions.erase(local_positions.begin());
    LocalPositions known;
    known.map        = std::make_unique<Epetra_BlockMap>(map);
    known.owned_only = owned_only;
    known.positions.reserve(cell_w_dof_indices.size());
    for (const auto index : cell_w_dof_indices)
      {
        const int position = map.LID(static_cast<int>(index));
        AssertThrow(position >= 0 || owned_only,
                    ExcMessage("The foundation reads w_h from a vector "
                               "without the ghost entries of its cells."));
        known.positions.push_back(position);
      }
    local_positions.push_back(std::move(known));
    return local_positions.back().positions.data();
  }


  void
  FoundationPoints::values_at_points(const LA::MPI::Vector &u,
                                     const unsigned int     c,
                                     std::vector<double>   &w) const
  {
    const unsigned int n_w       = w_dofs.size();
    const int         *positions = positions_in(u) + c * n_w;
    const double      *u_values  = u.trilinos_vector()[0];
    w.assign(q_points_per_cell, 0.0);
    for (unsigned int k = 0; k < n_w; ++k)
      {
        const double u_k = u_values[positions[k]];
        for (unsigned int q = 0; q < q_points_per_cell; ++q)
          w[q] += values(q, k) * u_k;
      }
  }


  void
  FoundationPoints::gradients_at_points(
    const LA::MPI::Vector     &u,
    const unsigned int         c,
    std::vector<Tensor<1, 2>> &gradient) const
  {
    const unsigned int n_w       = w_dofs.size();
    const int         *positions = positions_in(u) + c * n_w;
    const double      *u_values  = u.trilinos_vector()[0];
    gradient.assign(q_points_per_cell, Tensor<1, 2>());
    for (unsigned int k = 0; k < n_w; ++k)
      {
        const double u_k = u_values[positions[k]];
        for (unsigned int q = 0; q < q_points_per_cell; ++q)
          gradient[q] += u_k * shape_gradients(c, q)[k];
      }
  }


  void
  FoundationPoints::add_cell_vectors(
    const std::function<void(const unsigned int, Vector<double> &)> &f,
    LA::MPI::Vector &vector) const
  {
    const unsigned int                   n_w = w_dofs.size();
    Vector<double>                       cell_vector(n_w);
    std::vector<types::global_dof_index> dofs(n_w);
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        cell_vector = 0;
        f(c, cell_vector);
        std::copy(cell_w_dof_indices.begin() + c * n_w,
                  cell_w_dof_indices.begin() + (c + 1) * n_w,
                  dofs.begin());
        mesh->constraints.distribute_local_to_global(cell_vector, dofs, vector);
      }
    vector.compress(VectorOperation::add);
  }


  void
  FoundationPoints::add_cell_vector(const unsigned int    c,
                                    const Vector<double> &cell_vector,
                                    LA::MPI::Vector      &dst) const
  {
    const unsigned int n_w   = w_dofs.size();
    const auto         first = cell_w_dof_indices.begin() + c * n_w;
    if (cell_has_hanging_node[c])
      {
        const std::vector<types::global_dof_index> dofs(first, first + n_w);
        mesh->constraints.distribute_local_to_global(cell_vector, dofs, dst);
        return;
      }
    const int *positions  = positions_in(dst, true) + c * n_w;
    double    *dst_values = dst.trilinos_vector()[0];
    std::vector<types::global_dof_index> others;
    std::vector<double>                  other_values;
    for (unsigned int k = 0; k < n_w; ++k)
      if (!cell_w_dof_is_constrained[c * n_w + k])
        {
          if (positions[k] >= 0)
            dst_values[positions[k]] += cell_vector(k);
          else
            {
              others.push_back(first[k]);
              other_values.push_back(cell_vector(k));
            }
        }
    if (!others.empty())
      dst.add(others, other_values);
  }


  void
  FoundationPoints::add_cell_matrix(const unsigned int        c,
                                    const FullMatrix<double> &cell_matrix,
                                    LA::MPI::SparseMatrix    &matrix) const
  {
    if (cell_has_hanging_node[c])
      {
        add_condensed(c, cell_matrix, matrix);
        return;
      }
    const unsigned int                   n_w = w_dofs.size();
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  row_values;
    for (unsigned int i = 0; i < n_w; ++i)
      {
        if (cell_w_dof_is_constrained[c * n_w + i])
          continue;
        columns.clear();
        row_values.clear();
        for (unsigned int j = 0; j < n_w; ++j)
          if (!cell_w_dof_is_constrained[c * n_w + j])
            {
              columns.push_back(cell_w_dof_indices[c * n_w + j]);
              row_values.push_back(cell_matrix(i, j));
            }
        matrix.add(cell_w_dof_indices[c * n_w + i], columns, row_values, false);
      }
  }


  void
  FoundationPoints::add_condensed(const unsigned int        c,
                                  const FullMatrix<double> &cell_matrix,
                                  LA::MPI::SparseMatrix    &matrix) const
  {
    // Row and column i of the cell go to the nodes w_i depends on, with
    // its weights: itself, the masters of a hanging node, or none (w_i =
    // 0). All constraints here are homogeneous.
    const unsigned int n_w         = w_dofs.size();
    const auto        &constraints = mesh->constraints;
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>
      targets(n_w);
    for (unsigned int i = 0; i < n_w; ++i)
      {
        const auto dof = cell_w_dof_indices[c * n_w + i];
        if (!constraints.is_constrained(dof))
          targets[i] = {{dof, 1.0}};
        else if (const auto *entries = constraints.get_constraint_entries(dof))
          targets[i].assign(entries->begin(), entries->end());
      }
    for (unsigned int i = 0; i < n_w; ++i)
      for (const auto &[row, row_weight] : targets[i])
        for (unsigned int j = 0; j < n_w; ++j)
          for (const auto &[column, column_weight] : targets[j])
            matrix.add(row,
                       column,
                       row_weight * column_weight * cell_matrix(i, j));
  }
} // namespace liftoff
