#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <liftoff/fem/plate_fields.h>
#include <liftoff/fem/plate_matrices.h>
#include <liftoff/fem/transverse_shear_strain.h>

#include <cmath>

namespace liftoff
{
  namespace
  {
    // Bending (psi only) and inertia of one cell at the full Gauss rule of
    // fe_values, added to the cell matrices.
    void
    add_bending_and_inertia(const FEValues<2>         &fe_values,
                            const unsigned int         layer,
                            const double               nu,
                            const SectionCoefficients &section,
                            FullMatrix<double>        &cell_stiffness,
                            FullMatrix<double>        &cell_mass)
    {
      const auto [w, psi_x, psi_y] = PlateFields::extractors(layer);
      // (1 - nu) / 2, MindlinPlate::twisting_stiffness() of the layer.
      const double       twisting = 0.5 * (1.0 - nu);
      const double       rotary   = section.rotary;
      const unsigned int n_dofs   = cell_stiffness.m();
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        {
          const double dx      = fe_values.JxW(q);
          const double bend_dx = section.bending * dx;
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const Tensor<1, 2> gx_i    = fe_values[psi_x].gradient(i, q);
              const Tensor<1, 2> gy_i    = fe_values[psi_y].gradient(i, q);
              const double       twist_i = gx_i[1] + gy_i[0];
              for (unsigned int j = 0; j < n_dofs; ++j)
                {
                  const Tensor<1, 2> gx_j    = fe_values[psi_x].gradient(j, q);
                  const Tensor<1, 2> gy_j    = fe_values[psi_y].gradient(j, q);
                  const double       twist_j = gx_j[1] + gy_j[0];
                  cell_stiffness(i, j) +=
                    (gx_i[0] * gx_j[0] + gy_i[1] * gy_j[1]
                     + nu * (gx_i[0] * gy_j[1] + gy_i[1] * gx_j[0])
                     + twisting * twist_i * twist_j)
                    * bend_dx;
                  cell_mass(i, j) +=
                    (section.mass * fe_values[w].value(i, q)
                       * fe_values[w].value(j, q)
                     + rotary
                         * (fe_values[psi_x].value(i, q)
                              * fe_values[psi_x].value(j, q)
                            + fe_values[psi_y].value(i, q)
                                * fe_values[psi_y].value(j, q)))
                    * dx;
                }
            }
        }
    }

    // The mass couples w with w, psi_x with psi_x, psi_y with psi_y only
    // (translational and rotary inertia), and so do the constraints
    // (hanging nodes and edges tie a component to itself): its own pattern
    // holds a third of the plate's entries. The entries between other
    // components are exact zeros, which distribute_local_to_global skips.
    void
    reinit_mass(const Discretization &disc, LA::MPI::SparseMatrix &mass)
    {
      const unsigned int n_components =
        disc.dof_handler.get_fe().n_components();
      Table<2, DoFTools::Coupling> same_component(n_components, n_components);
      same_component.fill(DoFTools::none);
      for (unsigned int c = 0; c < n_components; ++c)
        same_component(c, c) = DoFTools::always;
      disc.reinit_matrix(mass, same_component);
    }


    // The transverse shear energy of one cell with the strains of the
    // scene's treatment.
    void
    add_shear(const TransverseShearStrain &shear_strain,
              const double                 shear,
              FullMatrix<double>          &cell_stiffness)
    {
      const unsigned int n_dofs = cell_stiffness.m();
      for (unsigned int q = 0; q < shear_strain.n_points(); ++q)
        {
          const double dx = shear_strain.JxW(q);
          for (unsigned int i = 0; i < n_dofs; ++i)
            for (unsigned int j = 0; j < n_dofs; ++j)
              cell_stiffness(i, j) += shear * shear_strain.strain(i, q)
                                      * shear_strain.strain(j, q) * dx;
        }
    }
  } // namespace


  void
  PlateMatrices::assemble(const Discretization &disc, const MindlinPlate &plate)
  {
    discretization = &disc;
    disc.reinit_matrix(stiffness);
    reinit_mass(disc, mass);

    const auto           &fe     = disc.dof_handler.get_fe();
    const unsigned int    p      = fe.degree;
    const unsigned int    n_dofs = fe.n_dofs_per_cell();
    const QGauss<2>       full_rule(p + 1);
    FEValues<2>           fe_values(disc.mapping(),
                          fe,
                          full_rule,
                          update_values | update_gradients | update_JxW_values);
    TransverseShearStrain shear_strain(disc.mapping(),
                                       fe,
                                       disc.element().shear_integration());

    // A base of its own (tensionless) is a second layer of the same kind.
    const unsigned int                   layers = PlateFields::n_layers(fe);
    FullMatrix<double>                   cell_stiffness(n_dofs, n_dofs);
    FullMatrix<double>                   cell_mass(n_dofs, n_dofs);
    std::vector<types::global_dof_index> dof_indices(n_dofs);

    for (const auto &cell : disc.locally_owned_cells())
      {
        cell_stiffness = 0;
        cell_mass      = 0;
        fe_values.reinit(cell);
        for (unsigned int layer = 0; layer < layers; ++layer)
          {
            const SectionCoefficients section =
              plate.layer_section(cell->material_id(), layer);
            add_bending_and_inertia(fe_values,
                                    layer,
                                    layer == 0 ? plate.poisson_ratio
                                               : plate.base.poisson_ratio,
                                    section,
                                    cell_stiffness,
                                    cell_mass);
            shear_strain.set_layer(layer);
            shear_strain.reinit(cell);
            add_shear(shear_strain, section.shear, cell_stiffness);
          }

        cell->get_dof_indices(dof_indices);
        disc.constraints.distribute_local_to_global(cell_stiffness,
                                                    dof_indices,
                                                    stiffness);
        disc.constraints.distribute_local_to_global(cell_mass,
                                                    dof_indices,
                                                    mass);
      }
    stiffness.compress(VectorOperation::add);
    mass.compress(VectorOperation::add);
  }


  double
  PlateMatrices::quadratic_form(const LA::MPI::SparseMatrix &A,
                                const LA::MPI::Vector       &x,
                                LA::MPI::Vector             &product) const
  {
    // A x and its dot product with x, in `product` instead of the vector
    // (and Epetra map) that matrix_norm_square allocates per call, which
    // costs more than the product itself on small problems.
    A.vmult(product, x);
    // The condensed matrices have rows and columns of their own for the
    // constrained entries (a diagonal that keeps them regular, no coupling
    // to the free entries), which are not the plate's: the form is that of
    // the free entries, so the constrained rows of A x drop out. Entries
    // fixed to zero are zero in x already; only hanging nodes need it.
    if (discretization->has_hanging_nodes())
      discretization->constraints.set_zero(product);
    return product * x;
  }


  void
  PlateMatrices::solve_with_mass(LA::MPI::Vector       &x,
                                 const LA::MPI::Vector &b) const
  {
    SolverControl control(10000, std::max(1e-13 * b.l2_norm(), 1e-300));
    SolverCG<LA::MPI::Vector>            cg(control);
    TrilinosWrappers::PreconditionJacobi jacobi;
    jacobi.initialize(mass);
    cg.solve(mass, x, b, jacobi);
  }


  double
  PlateMatrices::largest_eigenvalue(
    const Discretization &discretization,
    const std::function<void(const LA::MPI::Vector &, LA::MPI::Vector &)>
      &add_extra) const
  {
    LA::MPI::Vector x, y, z;
    for (auto *vector : {&x, &y, &z})
      discretization.reinit_vector(*vector);
    // A start with a component along every mode: a deterministic pattern,
    // so every run (and every rank count) gets the same estimate.
    for (const auto i : discretization.locally_owned_dofs)
      x(i) = 1.0 + std::sin(1.0 + 0.37 * i);
    x.compress(VectorOperation::insert);
    // Vectors that vanish on the constrained entries see the forms of the
    // free ones (hanging nodes included).
    discretization.constraints.set_zero(x);

    // The Rayleigh quotient rises monotonically to omega_max^2; the
    // iteration ends when it stalls to 1e-4 (its accuracy is that of an
    // estimate, not a bound, only in that it lies below).
    double lambda = 0;
    for (unsigned int k = 0; k < 200; ++k)
      {
        stiffness.vmult(y, x);
        add_extra(x, y);
        mass.vmult(z, x);
        const double next = (x * y) / (x * z);
        if (k > 5 && next - lambda <= 1e-4 * next)
          return std::max(lambda, next);
        lambda = std::max(lambda, next);
        solve_with_mass(z, y);
        discretization.constraints.set_zero(z);
        x.equ(1.0 / z.l2_norm(), z);
      }
    return lambda;
  }
} // namespace liftoff
