// The eight-node serendipity element (FE_Serendipity) against independent
// references:
// (a) its shape functions against the textbook closed forms on [-1, 1]^2
//     (corner: (1+xi xi_i)(1+eta eta_i)(xi xi_i+eta eta_i-1)/4, mid-side:
//     (1-xi^2)(1+eta eta_i)/2 and (1+xi xi_i)(1-eta^2)/2), values exactly,
//     first to third derivatives against central differences of them;
// (b) interpolation through FESystem(FE_Serendipity, 3) and
//     VectorTools::interpolate reproduces 1, x, y, x^2, xy, y^2, x^2 y, x y^2
//     to round-off on a mesh of unequal rectangles, and not x^2 y^2 (which
//     FE_Q(2) does reproduce: the element really has no centre node);
// (c) patch test: -Laplace u = 0 with u = 1 + 2x - 3y on the boundary of a
//     distorted mesh, one cell of which is refined (hanging nodes), is
//     solved exactly;
// (d) the hanging-node constraints leave a field of the space unchanged on
//     that mesh and change one outside it (x^3);
// (e) DataOut's patches of an interpolated x^2 y + x y^2 hold its values.
// The plate runs (Navier plate against Q2 and the closed form, and refused
// combinations) are in serendipity_plate.cc and tests/bad_input/.

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/fem/fe_serendipity.h>

#include "test_tools.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using liftoff::FE_Serendipity;

  // Textbook shape function i on [0, 1]^2 through xi = 2x - 1, eta = 2y - 1,
  // node i at (xi_i, eta_i) in deal.II's order.
  double
  textbook_shape(const unsigned int i, const Point<2> &p)
  {
    const double xi_i[8]  = {-1, 1, -1, 1, -1, 1, 0, 0};
    const double eta_i[8] = {-1, -1, 1, 1, 0, 0, -1, 1};
    const double xi = 2 * p[0] - 1, eta = 2 * p[1] - 1;
    if (xi_i[i] != 0 && eta_i[i] != 0)
      return 0.25 * (1 + xi * xi_i[i]) * (1 + eta * eta_i[i])
             * (xi * xi_i[i] + eta * eta_i[i] - 1);
    if (xi_i[i] == 0)
      return 0.5 * (1 - xi * xi) * (1 + eta * eta_i[i]);
    return 0.5 * (1 + xi * xi_i[i]) * (1 - eta * eta);
  }

  // Central difference of f along direction d.
  template <typename T>
  T
  central_difference(const std::function<T(const Point<2> &)> &f,
                     const Point<2>                           &p,
                     const unsigned int                        d)
  {
    const double h    = 1e-4;
    Point<2>     plus = p, minus = p;
    plus[d] += h;
    minus[d] -= h;
    return (f(plus) - f(minus)) / (2 * h);
  }

  void
  check_shape_functions(liftoff_tests::Checks &checks)
  {
    const FE_Serendipity fe;
    double               value_error = 0, first = 0, second = 0, third = 0;
    // Points inside the cell and on its boundary.
    for (unsigned int k = 0; k < 25; ++k)
      {
        const Point<2> p(std::fmod(0.37 * k, 1.0), std::fmod(0.61 * k, 1.0));
        for (unsigned int i = 0; i < 8; ++i)
          {
            value_error =
              std::max(value_error,
                       std::abs(fe.shape_value(i, p) - textbook_shape(i, p)));
            const std::function<double(const Point<2> &)> value =
              [i](const Point<2> &q) { return textbook_shape(i, q); };
            const std::function<Tensor<1, 2>(const Point<2> &)> grad =
              [&fe, i](const Point<2> &q) { return fe.shape_grad(i, q); };
            const std::function<Tensor<2, 2>(const Point<2> &)> hessian =
              [&fe, i](const Point<2> &q) { return fe.shape_grad_grad(i, q); };
            for (unsigned int d = 0; d < 2; ++d)
              {
                first  = std::max(first,
                                 std::abs(fe.shape_grad(i, p)[d]
                                          - central_difference(value, p, d)));
                second = std::max(second,
                                  (fe.shape_grad_grad(i, p)[d]
                                   - central_difference(grad, p, d))
                                    .norm());
                third  = std::max(third,
                                 (fe.shape_3rd_derivative(i, p)[d]
                                  - central_difference(hessian, p, d))
                                   .norm());
              }
          }
      }
    checks.less("(a) shape values vs textbook closed form", value_error, 1e-14);
    checks.less("(a) gradients vs central differences of the closed form",
                first,
                1e-7);
    checks.less("(a) second derivatives vs differences of the gradients",
                second,
                1e-7);
    checks.less("(a) third derivatives vs differences of the second",
                third,
                1e-7);
  }


  // f = x^a y^b in all three components.
  class Monomial : public Function<2>
  {
  public:
    Monomial(const unsigned int a, const unsigned int b)
        : Function<2>(3)
        , a(a)
        , b(b)
    {}
    double
    value(const Point<2> &p, const unsigned int) const override
    {
      return std::pow(p[0], a) * std::pow(p[1], b);
    }
    const unsigned int a, b;
  };


  // Max |u_h - f| over Gauss points of every cell, all components.
  double
  interpolation_error(const FiniteElement<2> &base,
                      const Triangulation<2> &tria,
                      const Function<2>      &f)
  {
    const FESystem<2> fe(base, 3);
    DoFHandler<2>     dofs(tria);
    dofs.distribute_dofs(fe);
    Vector<double> u(dofs.n_dofs());
    VectorTools::interpolate(dofs, f, u);
    Vector<double> cellwise(tria.n_active_cells());
    VectorTools::integrate_difference(
      dofs, u, f, cellwise, QGauss<2>(5), VectorTools::Linfty_norm);
    return cellwise.linfty_norm();
  }


  void
  check_interpolation(liftoff_tests::Checks &checks)
  {
    // Rectangles of unequal sizes (the space is invariant under maps that
    // scale x and y, not under general affine ones).
    Triangulation<2>                       tria;
    const std::vector<std::vector<double>> steps = {{0.5, 0.3, 0.2},
                                                    {0.25, 0.4, 0.35}};
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              steps,
                                              Point<2>(-0.3, 0.1),
                                              Point<2>(0.7, 1.1));
    const FE_Serendipity serendipity;
    for (const auto &[a, b] :
         std::vector<std::pair<unsigned int, unsigned int>>{
           {0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {2, 1}, {1, 2}})
      checks.less("(b) x^" + std::to_string(a) + " y^" + std::to_string(b)
                    + ": max interpolation error",
                  interpolation_error(serendipity, tria, Monomial(a, b)),
                  1e-14);
    // The bubble x^2 y^2 is outside the space: its error is of the size
    // of h^4 times its fourth derivative (here about 1e-3), not round-off.
    checks.within("(b) x^2 y^2 (not in the space): max interpolation error",
                  interpolation_error(serendipity, tria, Monomial(2, 2)),
                  1e-5,
                  1e-1);
    checks.less("(b) x^2 y^2 with FE_Q(2) (in its space): max error",
                interpolation_error(FE_Q<2>(2), tria, Monomial(2, 2)),
                1e-14);
  }


  // A 3 x 3 mesh of the unit square with its interior vertices moved (no
  // two cells parallelograms) and its centre cell refined once.
  void
  distorted_mesh_with_hanging_nodes(Triangulation<2> &tria)
  {
    GridGenerator::subdivided_hyper_cube(tria, 3);
    for (auto &cell : tria.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          Point<2> &p = cell->vertex(v);
          if (p[0] > 1e-12 && p[0] < 1 - 1e-12 && p[1] > 1e-12
              && p[1] < 1 - 1e-12)
            {
              const double phase = 7 * p[0] + 13 * p[1];
              p += Point<2>(0.08 * std::sin(phase), 0.07 * std::cos(phase));
            }
        }
    for (auto &cell : tria.active_cell_iterators())
      if (cell->center().distance(Point<2>(0.5, 0.5)) < 0.2)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
  }


  // u = 1 + 2x - 3y with its exact gradient (FunctionParser differentiates
  // by finite differences).
  class LinearField : public Function<2>
  {
  public:
    double
    value(const Point<2> &p, const unsigned int = 0) const override
    {
      return 1 + 2 * p[0] - 3 * p[1];
    }
    Tensor<1, 2>
    gradient(const Point<2> &, const unsigned int = 0) const override
    {
      return Tensor<1, 2>({2.0, -3.0});
    }
  };


  void
  check_patch_test(liftoff_tests::Checks &checks)
  {
    Triangulation<2> tria;
    distorted_mesh_with_hanging_nodes(tria);
    const FE_Serendipity fe;
    DoFHandler<2>        dofs(tria);
    dofs.distribute_dofs(fe);

    const LinearField         linear;
    AffineConstraints<double> constraints;
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    VectorTools::interpolate_boundary_values(dofs, 0, linear, constraints);
    constraints.close();
    checks.within("(c) hanging-node and boundary constraints made",
                  constraints.n_constraints(),
                  1,
                  dofs.n_dofs());

    DynamicSparsityPattern dsp(dofs.n_dofs());
    DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> matrix(pattern);
    Vector<double>       rhs(dofs.n_dofs()), u(dofs.n_dofs());

    const QGauss<2>    rule(3);
    FEValues<2>        values(fe, rule, update_gradients | update_JxW_values);
    FullMatrix<double> cell_matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell());
    Vector<double>     cell_rhs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      {
        values.reinit(cell);
        cell_matrix = 0;
        cell_rhs    = 0;
        for (unsigned int q = 0; q < rule.size(); ++q)
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
              cell_matrix(i, j) += values.shape_grad(i, q)
                                   * values.shape_grad(j, q) * values.JxW(q);
        cell->get_dof_indices(indices);
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, indices, matrix, rhs);
      }
    SparseDirectUMFPACK solver;
    solver.initialize(matrix);
    solver.vmult(u, rhs);
    constraints.distribute(u);

    Vector<double> cellwise(tria.n_active_cells());
    VectorTools::integrate_difference(
      dofs, u, linear, cellwise, QGauss<2>(4), VectorTools::Linfty_norm);
    checks.less("(c) patch test, distorted mesh with hanging nodes: "
                "max |u_h - u|",
                cellwise.linfty_norm(),
                1e-12);
    // The gradient at the Gauss points, against the exact (2, -3).
    FEValues<2>               gradients(fe, QGauss<2>(4), update_gradients);
    std::vector<Tensor<1, 2>> grad_u(gradients.n_quadrature_points);
    double                    gradient_error = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      {
        gradients.reinit(cell);
        gradients.get_function_gradients(u, grad_u);
        for (const auto &g : grad_u)
          gradient_error =
            std::max(gradient_error, (g - linear.gradient(Point<2>())).norm());
      }
    checks.less("(c) patch test: max |grad u_h - grad u|",
                gradient_error,
                1e-12);
  }


  void
  check_hanging_nodes(liftoff_tests::Checks &checks)
  {
    // On an undistorted mesh the space holds x^2 y + x y^2 on every cell,
    // so its interpolant is continuous across the refined edges and the
    // constraints must not change it; x^3 is quadratic along no edge of the
    // x direction, so the fine side's mid-points disagree with the coarse
    // side's trace and the constraints must move them.
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_cube(tria, 3);
    for (auto &cell : tria.active_cell_iterators())
      if (cell->center().distance(Point<2>(0.5, 0.5)) < 0.2)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    const FE_Serendipity fe;
    DoFHandler<2>        dofs(tria);
    dofs.distribute_dofs(fe);
    AffineConstraints<double> constraints;
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();
    // Each of the 4 refined edges: its middle vertex and 2 child mid-points.
    checks.within("(d) hanging-node constraints: 3 per refined edge",
                  constraints.n_constraints(),
                  12,
                  12);

    for (const auto &[expression, in_space] :
         std::vector<std::pair<std::string, bool>>{{"x^2*y + x*y^2", true},
                                                   {"x^3", false}})
      {
        const FunctionParser<2> f(expression);
        Vector<double>          u(dofs.n_dofs());
        VectorTools::interpolate(dofs, f, u);
        Vector<double> constrained = u;
        constraints.distribute(constrained);
        constrained -= u;
        if (in_space)
          checks.less("(d) " + expression + ": change by the constraints",
                      constrained.linfty_norm(),
                      1e-14);
        else
          checks.within("(d) " + expression + ": change by the constraints",
                        constrained.linfty_norm(),
                        1e-4,
                        1);
      }
  }


  void
  check_data_out(liftoff_tests::Checks &checks)
  {
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_cube(tria, 2);
    const FESystem<2> fe(FE_Serendipity(), 3);
    DoFHandler<2>     dofs(tria);
    dofs.distribute_dofs(fe);
    const FunctionParser<2> f("x^2*y + x*y^2; x; y");
    Vector<double>          u(dofs.n_dofs());
    VectorTools::interpolate(dofs, f, u);
    DataOut<2> data_out;
    data_out.attach_dof_handler(dofs);
    data_out.add_data_vector(u, std::vector<std::string>{"w", "px", "py"});
    data_out.build_patches(2);
    double error = 0;
    for (const auto &patch : data_out.get_patches())
      for (unsigned int k = 0; k < patch.data.n_cols(); ++k)
        {
          // Patch points in lexicographic order on the 3 x 3 subdivision.
          const double   s = (k % 3) / 2.0, t = (k / 3) / 2.0;
          const Point<2> p = patch.vertices[0]
                             + s * (patch.vertices[1] - patch.vertices[0])
                             + t * (patch.vertices[2] - patch.vertices[0]);
          for (unsigned int c = 0; c < 3; ++c)
            error = std::max(error, std::abs(patch.data(c, k) - f.value(p, c)));
        }
    checks.less("(e) DataOut patches: max |value - field|", error, 1e-14);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);
  check_shape_functions(checks);
  check_interpolation(checks);
  check_patch_test(checks);
  check_hanging_nodes(checks);
  check_data_out(checks);
  return checks.exit_code();
}
