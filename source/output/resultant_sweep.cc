#include <deal.II/fe/fe_dgq.h>

#include <liftoff/contact/contact_law.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/stress_resultants.h>

#include <cmath>

namespace liftoff
{
  namespace
  {
    /// Whether the entries of `v` on this rank are all of it, in the order
    /// of their indices, so that entry i is v.begin()[i] (one rank).
    /// deal.II's get_dof_values asks Epetra's map for every entry's place:
    /// a fifth of the sweep's time on S.
    bool
    is_whole_vector_in_order(const LA::MPI::Vector &v)
    {
      const Epetra_BlockMap &map = v.trilinos_vector().Map();
      if (static_cast<types::global_dof_index>(map.NumMyElements()) != v.size())
        return false;
      for (int i = 0; i < map.NumMyElements(); ++i)
        if (map.GID64(i) != i)
          return false;
      return true;
    }


    /// The cell's entries of `solution` into `dof_values`, through
    /// `indices` directly when the vector is whole and in order.
    void
    read_dof_values(const DoFHandler<2>::active_cell_iterator &cell,
                    const LA::MPI::Vector                     &solution,
                    const bool                                 in_order,
                    std::vector<types::global_dof_index>      &indices,
                    Vector<double>                            &dof_values)
    {
      if (!in_order)
        {
          cell->get_dof_values(solution, dof_values);
          return;
        }
      cell->get_dof_indices(indices);
      for (unsigned int i = 0; i < indices.size(); ++i)
        dof_values[i] = solution.begin()[indices[i]];
    }
  } // namespace


  ResultantSweep::ResultantSweep(const MindlinPlate     &plate,
                                 const Discretization   &discretization,
                                 const ContactLaw       &law,
                                 const LA::MPI::Vector  &ghosted_solution,
                                 const FreeBendingField &free_bending,
                                 const bool              with_faces)
      : plate(plate)
      , discretization(discretization)
      , law(law)
      , solution(ghosted_solution)
      , thermal_bending(free_bending)
      , with_faces(with_faces)
  {}


  const FreeBendingField &
  ResultantSweep::free_bending() const
  {
    return thermal_bending;
  }


  const std::vector<Point<2>> &
  ResultantSweep::points() const
  {
    compute();
    return point_list;
  }


  const std::vector<ResultantSweep::Values> &
  ResultantSweep::values() const
  {
    compute();
    return value_list;
  }


  void
  ResultantSweep::compute() const
  {
    if (is_computed)
      return;
    is_computed                 = true;
    const Discretization  &disc = discretization;
    const StressResultants resultants(plate,
                                      disc.mapping(),
                                      disc.element().shear_integration(),
                                      solution,
                                      thermal_bending);
    const FE_DGQ<2>        output_points(disc.element().degree());
    PlateFieldAtPoints     fields(disc.mapping(),
                              disc.dof_handler.get_fe(),
                              Quadrature<2>(
                                output_points.get_unit_support_points()));
    const unsigned int     n = fields.n_points();
    // Kept from cell to cell; the cell's dofs are read from the vector once.
    const unsigned int dofs_per_cell =
      disc.dof_handler.get_fe().n_dofs_per_cell();
    Vector<double>                       dof_values(dofs_per_cell);
    std::vector<types::global_dof_index> indices(dofs_per_cell);
    const bool                    in_order = is_whole_vector_in_order(solution);
    const ArrayView<const double> dofs(dof_values.begin(), dof_values.size());
    StressResultants::PrincipalValues principal;
    principal.with_faces = with_faces;
    // A plate of one slab keeps a mesh file's material ids.
    const bool is_jointed = disc.geometry().slabs().is_jointed();
    point_list.clear();
    value_list.clear();
    point_list.reserve(n * disc.triangulation.n_active_cells());
    value_list.reserve(point_list.capacity());
    // In the order of the cells' CellId: of two equal extremes (a vertex
    // of several cells) the first is taken, which must not depend on how
    // the mesh was reached (refined in the run or loaded at a resume).
    for (const auto &cell : disc.locally_owned_cells())
      {
        read_dof_values(cell, solution, in_order, indices, dof_values);
        fields.reinit(cell, dofs);
        resultants.principal(cell, fields, dofs, principal);
        const std::vector<double>   &w = fields.w;
        const std::vector<Point<2>> &x = fields.points();
        for (unsigned int k = 0; k < n; ++k)
          {
            const double g = (law.has_gap() ? law.gap_at(x[k]) : 0.0);
            Values       v;
            v.w        = w[k];
            v.pressure = law.spring_pressure(w[k] - g);
            v.m_1      = principal.m_1[k];
            v.m_2      = principal.m_2[k];
            v.shear    = std::hypot(principal.q[k][0], principal.q[k][1]);
            if (with_faces)
              v.faces = principal.faces[k];
            v.slab = is_jointed ? cell->material_id() : 0;
            point_list.push_back(x[k]);
            value_list.push_back(v);
          }
      }
  }
} // namespace liftoff
