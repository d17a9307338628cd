#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <liftoff/tensionless_winkler_foundation.h>

namespace liftoff
{
  void
  TensionlessWinklerFoundation::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Foundation");
    prm.declare_entry("Model",
                      "tensionless",
                      Patterns::Selection("tensionless|bilateral|none"),
                      "tensionless: springs act only where w > 0; bilateral: "
                      "linear springs of both signs (for checks); none: no "
                      "foundation.");
    prm.declare_entry("Stiffness",
                      "1",
                      Patterns::Double(0.0),
                      "Gamma = K_f L^4 / D, the dimensionless Winkler "
                      "modulus.");
    prm.leave_subsection();
  }


  void
  TensionlessWinklerFoundation::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Foundation");
    const std::string name = prm.get("Model");
    model                  = (name == "tensionless"
                                ? Model::tensionless
                                : (name == "bilateral" ? Model::bilateral : Model::none));
    stiffness              = prm.get_double("Stiffness");
    prm.leave_subsection();
    AssertThrow(model == Model::none || stiffness > 0,
                ExcMessage("Foundation/Stiffness (Gamma) must be > 0, or set "
                           "Foundation/Model = none."));
  }


  void
  TensionlessWinklerFoundation::setup(const Discretization &disc)
  {
    discretization     = &disc;
    const auto     &fe = *disc.fe;
    const QGauss<2> rule(fe.degree + 1);
    n_q_points = rule.size();

    w_dofs.clear();
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == 0)
        w_dofs.push_back(i);

    // Lagrange shape values at the Gauss points do not depend on the cell.
    shape_values.reinit(n_q_points, w_dofs.size());
    for (unsigned int q = 0; q < n_q_points; ++q)
      for (unsigned int k = 0; k < w_dofs.size(); ++k)
        shape_values(q, k) = fe.shape_value(w_dofs[k], rule.point(q));

    FEValues<2> fe_values(disc.mapping, fe, rule, update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    cell_w_dof_indices.clear();
    cell_index.clear();
    jxw.clear();
    for (const auto &cell : disc.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (const unsigned int i : w_dofs)
            cell_w_dof_indices.push_back(dofs[i]);
          for (unsigned int q = 0; q < n_q_points; ++q)
            jxw.push_back(fe_values.JxW(q));
          cell_index.push_back(cell->active_cell_index());
        }
    in_contact.assign(jxw.size(), model == Model::none ? 0 : 1);
  }


  void
  TensionlessWinklerFoundation::activate_all()
  {
    std::fill(in_contact.begin(),
              in_contact.end(),
              model == Model::none ? 0 : 1);
  }


  void
  TensionlessWinklerFoundation::deflection_at_gauss_points(
    const LA::MPI::Vector &u,
    const unsigned int     c,
    std::vector<double>   &w) const
  {
    const unsigned int n_w = w_dofs.size();
    w.assign(n_q_points, 0.0);
    for (unsigned int k = 0; k < n_w; ++k)
      {
        const double u_k = u(cell_w_dof_indices[c * n_w + k]);
        for (unsigned int q = 0; q < n_q_points; ++q)
          w[q] += shape_values(q, k) * u_k;
      }
  }


  unsigned long
  TensionlessWinklerFoundation::update_contact_status(const LA::MPI::Vector &u)
  {
    unsigned long n_changed = 0;
    if (model == Model::tensionless)
      {
        std::vector<double> w;
        for (unsigned int c = 0; c < cell_index.size(); ++c)
          {
            deflection_at_gauss_points(u, c, w);
            for (unsigned int q = 0; q < n_q_points; ++q)
              {
                const unsigned char now    = (w[q] > 0.0 ? 1 : 0);
                unsigned char      &status = in_contact[c * n_q_points + q];
                n_changed += (now != status);
                status = now;
              }
          }
      }
    return Utilities::MPI::sum(n_changed, discretization->mpi_communicator);
  }


  void
  TensionlessWinklerFoundation::assemble_matrix(
    LA::MPI::SparseMatrix &matrix) const
  {
    matrix                                   = 0;
    const unsigned int                   n_w = w_dofs.size();
    FullMatrix<double>                   cell_matrix(n_w, n_w);
    std::vector<types::global_dof_index> dofs(n_w);
    if (model != Model::none)
      for (unsigned int c = 0; c < cell_index.size(); ++c)
        {
          cell_matrix = 0;
          bool any    = false;
          for (unsigned int q = 0; q < n_q_points; ++q)
            if (in_contact[c * n_q_points + q])
              {
                any            = true;
                const double k = stiffness * jxw[c * n_q_points + q];
                for (unsigned int i = 0; i < n_w; ++i)
                  for (unsigned int j = 0; j < n_w; ++j)
                    cell_matrix(i, j) +=
                      k * shape_values(q, i) * shape_values(q, j);
              }
          if (!any)
            continue;
          std::copy(cell_w_dof_indices.begin() + c * n_w,
                    cell_w_dof_indices.begin() + (c + 1) * n_w,
                    dofs.begin());
          discretization->constraints.distribute_local_to_global(cell_matrix,
                                                                 dofs,
                                                                 matrix);
        }
    matrix.compress(VectorOperation::add);
  }


  double
  TensionlessWinklerFoundation::energy(const LA::MPI::Vector &u) const
  {
    double              local = 0;
    std::vector<double> w;
    if (model != Model::none)
      for (unsigned int c = 0; c < cell_index.size(); ++c)
        {
          deflection_at_gauss_points(u, c, w);
          for (unsigned int q = 0; q < n_q_points; ++q)
            {
              const double compression =
                (model == Model::bilateral ? w[q] : std::max(w[q], 0.0));
              local += 0.5 * stiffness * compression * compression
                       * jxw[c * n_q_points + q];
            }
        }
    return Utilities::MPI::sum(local, discretization->mpi_communicator);
  }


  double
  TensionlessWinklerFoundation::contact_area_fraction() const
  {
    double in_contact_area = 0, area = 0;
    for (unsigned int i = 0; i < jxw.size(); ++i)
      {
        area += jxw[i];
        in_contact_area += in_contact[i] * jxw[i];
      }
    const MPI_Comm comm = discretization->mpi_communicator;
    return Utilities::MPI::sum(in_contact_area, comm)
           / Utilities::MPI::sum(area, comm);
  }


  Vector<float>
  TensionlessWinklerFoundation::contact_fraction_per_cell() const
  {
    Vector<float> fraction(discretization->triangulation.n_active_cells());
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        double sum = 0, area = 0;
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            area += jxw[c * n_q_points + q];
            sum += in_contact[c * n_q_points + q] * jxw[c * n_q_points + q];
          }
        fraction[cell_index[c]] = sum / area;
      }
    return fraction;
  }
} // namespace liftoff
