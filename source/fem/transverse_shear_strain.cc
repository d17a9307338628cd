#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <liftoff/fem/plate_fields.h>
#include <liftoff/fem/transverse_shear_strain.h>

namespace liftoff
{
  namespace
  {
    // Tying points of the covariant component `direction` (0: xi, 1: eta):
    // Gauss abscissae along the component, Gauss-Lobatto across it, and the
    // tensor-product Lagrange weights that interpolate from them at the
    // points of `targets`.
    std::pair<Quadrature<2>, FullMatrix<double>>
    tying_rule(const unsigned int   degree,
               const unsigned int   direction,
               const Quadrature<2> &targets)
    {
      const QGauss<1>        along(degree);
      const QGaussLobatto<1> across(degree + 1);
      const auto             along_basis =
        Polynomials::generate_complete_Lagrange_basis(along.get_points());
      const auto across_basis =
        Polynomials::generate_complete_Lagrange_basis(across.get_points());

      std::vector<Point<2>>                              points;
      std::vector<std::pair<unsigned int, unsigned int>> index;
      for (unsigned int b = 0; b < across.size(); ++b)
        for (unsigned int a = 0; a < along.size(); ++a)
          {
            Point<2> p;
            p[direction]     = along.point(a)[0];
            p[1 - direction] = across.point(b)[0];
            points.push_back(p);
            index.emplace_back(a, b);
          }

      FullMatrix<double> weights(targets.size(), points.size());
      for (unsigned int q = 0; q < targets.size(); ++q)
        for (unsigned int t = 0; t < points.size(); ++t)
          weights(q, t) =
            along_basis[index[t].first].value(targets.point(q)[direction])
            * across_basis[index[t].second].value(
              targets.point(q)[1 - direction]);
      return {Quadrature<2>(points), weights};
    }

    const UpdateFlags strain_flags =
      update_values | update_gradients | update_jacobians;
  } // namespace


  TransverseShearStrain::TransverseShearStrain(const Mapping<2>       &mapping,
                                               const FiniteElement<2> &fe,
                                               const Treatment treatment)
      : TransverseShearStrain(mapping,
                              fe,
                              treatment,
                              QGauss<2>(treatment == Treatment::reduced
                                          ? fe.degree
                                          : fe.degree + 1))
  {}


  TransverseShearStrain::TransverseShearStrain(const Mapping<2>       &mapping,
                                               const FiniteElement<2> &fe,
                                               const Treatment      treatment,
                                               const Quadrature<2> &points)
      : treatment(treatment)
      , integration_values(mapping,
                           fe,
                           points,
                           strain_flags | update_inverse_jacobians
                             | update_JxW_values)
      , strains(fe.n_dofs_per_cell(), integration_values.n_quadrature_points)
  {
    if (treatment == Treatment::mitc)
      for (unsigned int c = 0; c < 2; ++c)
        {
          auto rule =
            tying_rule(fe.degree, c, integration_values.get_quadrature());
          tying_values[c]  = std::make_unique<FEValues<2>>(mapping,
                                                          fe,
                                                          rule.first,
                                                          strain_flags);
          interpolation[c] = rule.second;
        }
  }


  void
  TransverseShearStrain::set_layer(const unsigned int new_layer)
  {
    layer = new_layer;
  }


  Tensor<1, 2>
  TransverseShearStrain::cartesian_strain(const FEValues<2> &values,
                                          const unsigned int i,
                                          const unsigned int q) const
  {
    const auto [w, psi_x, psi_y] = PlateFields::extractors(layer);
    return values[w].gradient(i, q)
           - Tensor<1, 2>(
             {values[psi_x].value(i, q), values[psi_y].value(i, q)});
  }


  void
  TransverseShearStrain::reinit(const DoFHandler<2>::active_cell_iterator &cell)
  {
    integration_values.reinit(cell);
    const unsigned int n_dofs = strains.size(0);
    const unsigned int n_q    = strains.size(1);

    if (treatment != Treatment::mitc)
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int q = 0; q < n_q; ++q)
            strains(i, q) = cartesian_strain(integration_values, i, q);
        return;
      }

    // Covariant components gamma_c = gamma . dx/dxi_c are what is tied: they
    // are the strains along the cell's edges whatever its shape.
    for (unsigned int i = 0; i < n_dofs; ++i)
      for (unsigned int q = 0; q < n_q; ++q)
        strains(i, q) = Tensor<1, 2>();
    Table<2, double> natural(n_dofs, n_q);
    for (unsigned int c = 0; c < 2; ++c)
      {
        FEValues<2> &tying = *tying_values[c];
        tying.reinit(cell);
        natural.fill(0.0);
        for (unsigned int t = 0; t < tying.n_quadrature_points; ++t)
          {
            const DerivativeForm<1, 2, 2> &J = tying.jacobian(t);
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const Tensor<1, 2> gamma = cartesian_strain(tying, i, t);
                const double       covariant =
                  gamma[0] * J[0][c] + gamma[1] * J[1][c];
                for (unsigned int q = 0; q < n_q; ++q)
                  natural(i, q) += interpolation[c](q, t) * covariant;
              }
          }
        // Back to Cartesian components: gamma_k = sum_c dxi_c/dx_k gamma_c.
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const DerivativeForm<1, 2, 2> &K =
              integration_values.inverse_jacobian(q);
            for (unsigned int i = 0; i < n_dofs; ++i)
              for (unsigned int k = 0; k < 2; ++k)
                strains(i, q)[k] += K[c][k] * natural(i, q);
          }
      }
  }


  unsigned int
  TransverseShearStrain::n_points() const
  {
    return integration_values.n_quadrature_points;
  }


  double
  TransverseShearStrain::JxW(const unsigned int q) const
  {
    return integration_values.JxW(q);
  }


  const Tensor<1, 2> &
  TransverseShearStrain::strain(const unsigned int i,
                                const unsigned int q) const
  {
    return strains(i, q);
  }
} // namespace liftoff
