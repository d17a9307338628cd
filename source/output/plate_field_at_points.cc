#include <deal.II/fe/fe.h>

#include <liftoff/fem/plate_fields.h>
#include <liftoff/output/plate_field_at_points.h>

namespace liftoff
{
  PlateFieldAtPoints::PlateFieldAtPoints(const Mapping<2>       &mapping,
                                         const FiniteElement<2> &system,
                                         const Quadrature<2>    &points)
      : w(points.size())
      , grad_w(points.size())
      , psi(points.size())
      , grad_psi(points.size())
      , base_values(mapping,
                    system.base_element(0),
                    points,
                    update_values | update_gradients | update_quadrature_points)
  {
    AssertThrow(system.n_base_elements() == 1
                  && system.n_components() % PlateFields::per_layer == 0,
                ExcInternalError());
    shape_functions.resize(system.n_components());
    sums.assign(3 * system.n_components(), std::vector<double>(points.size()));
    if (system.n_components() > PlateFields::n_components)
      grad_psi_base.resize(points.size());
    for (unsigned int i = 0; i < system.n_dofs_per_cell(); ++i)
      {
        const auto [component, base_index] =
          system.system_to_component_index(i);
        shape_functions[component].emplace_back(i, base_index);
      }
  }


  void
  PlateFieldAtPoints::reinit(const DoFHandler<2>::active_cell_iterator &cell,
                             const ArrayView<const double> &dof_values)
  {
    base_values.reinit(Triangulation<2>::cell_iterator(cell));
    const unsigned int n = n_points();
    const unsigned int m = base_values.dofs_per_cell;
    phi.resize(m * n);
    dphi_x.resize(m * n);
    dphi_y.resize(m * n);
    for (unsigned int b = 0; b < m; ++b)
      for (unsigned int q = 0; q < n; ++q)
        {
          phi[b * n + q]    = base_values.shape_value(b, q);
          dphi_x[b * n + q] = base_values.shape_grad(b, q)[0];
          dphi_y[b * n + q] = base_values.shape_grad(b, q)[1];
        }
    // As FEValues' get_function_values and get_function_gradients: shape
    // function after shape function, a zero dof value skipped.
    for (unsigned int c = 0; c < shape_functions.size(); ++c)
      {
        double *value = sums[3 * c].data(), *dx = sums[3 * c + 1].data(),
               *dy = sums[3 * c + 2].data();
        std::fill(value, value + n, 0.0);
        std::fill(dx, dx + n, 0.0);
        std::fill(dy, dy + n, 0.0);
        for (const auto &[i, b] : shape_functions[c])
          {
            const double d = dof_values[i];
            if (d == 0.0)
              continue;
            const double *p = &phi[b * n], *px = &dphi_x[b * n],
                         *py = &dphi_y[b * n];
            for (unsigned int q = 0; q < n; ++q)
              {
                value[q] += d * p[q];
                dx[q] += d * px[q];
                dy[q] += d * py[q];
              }
          }
      }
    const auto sum = [&](const unsigned int c, const unsigned int k) {
      return sums[3 * c + k].data();
    };
    const unsigned int x = PlateFields::psi_x, y = PlateFields::psi_y;
    for (unsigned int q = 0; q < n; ++q)
      {
        w[q] = sum(PlateFields::w, 0)[q];
        grad_w[q] =
          Tensor<1, 2>({sum(PlateFields::w, 1)[q], sum(PlateFields::w, 2)[q]});
        psi[q]      = Tensor<1, 2>({sum(x, 0)[q], sum(y, 0)[q]});
        grad_psi[q] = Tensor<2, 2>(
          {{sum(x, 1)[q], sum(x, 2)[q]}, {sum(y, 1)[q], sum(y, 2)[q]}});
      }
    const unsigned int bx = PlateFields::rotation(0, 1),
                       by = PlateFields::rotation(1, 1);
    for (unsigned int q = 0; q < grad_psi_base.size(); ++q)
      grad_psi_base[q] = Tensor<2, 2>(
        {{sum(bx, 1)[q], sum(bx, 2)[q]}, {sum(by, 1)[q], sum(by, 2)[q]}});
  }


  unsigned int
  PlateFieldAtPoints::n_points() const
  {
    return base_values.n_quadrature_points;
  }


  const std::vector<Point<2>> &
  PlateFieldAtPoints::unit_points() const
  {
    return base_values.get_quadrature().get_points();
  }


  const std::vector<Point<2>> &
  PlateFieldAtPoints::points() const
  {
    return base_values.get_quadrature_points();
  }
} // namespace liftoff
