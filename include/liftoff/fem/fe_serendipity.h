#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/scalar_polynomials_base.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_poly.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The eight-node serendipity space on the unit square: span{1, x, y, x^2,
   * xy, y^2, x^2 y, x y^2}, the complete quadratics and the two cubic terms
   * that are quadratic along each edge. Its basis is the nodal one at the
   * four vertices and the four edge mid-points, in deal.II's order (vertices
   * (0,0), (1,0), (0,1), (1,1), then the mid-points of the lines x = 0,
   * x = 1, y = 0, y = 1), so that vertex and line degrees of freedom are
   * shared with the neighbours. Shape functions are kept as coefficients in
   * the monomials, whose derivatives of every order are exact.
   */
  class SerendipityPolynomials : public ScalarPolynomialsBase<2>
  {
  public:
    static constexpr unsigned int n_shape_functions = 8;

    SerendipityPolynomials();

    /// The nodes in deal.II's numbering (vertices, then edge mid-points).
    static std::vector<Point<2>>
    nodes();

    void
    evaluate(const Point<2>            &unit_point,
             std::vector<double>       &values,
             std::vector<Tensor<1, 2>> &grads,
             std::vector<Tensor<2, 2>> &grad_grads,
             std::vector<Tensor<3, 2>> &third_derivatives,
             std::vector<Tensor<4, 2>> &fourth_derivatives) const override;

    double
    compute_value(const unsigned int i, const Point<2> &p) const override;
    Tensor<1, 2>
    compute_1st_derivative(const unsigned int i,
                           const Point<2>    &p) const override;
    Tensor<2, 2>
    compute_2nd_derivative(const unsigned int i,
                           const Point<2>    &p) const override;
    Tensor<3, 2>
    compute_3rd_derivative(const unsigned int i,
                           const Point<2>    &p) const override;
    Tensor<4, 2>
    compute_4th_derivative(const unsigned int i,
                           const Point<2>    &p) const override;
    Tensor<1, 2>
    compute_grad(const unsigned int i, const Point<2> &p) const override;
    Tensor<2, 2>
    compute_grad_grad(const unsigned int i, const Point<2> &p) const override;

    std::unique_ptr<ScalarPolynomialsBase<2>>
    clone() const override;
    std::string
    name() const override;

  private:
    /// coefficients(i, m): shape function i in monomial m.
    FullMatrix<double> coefficients;

    /// The derivative of shape function i at p of the order given by the
    /// indices (each 0 for d/dx or 1 for d/dy).
    double
    derivative(const unsigned int               i,
               const Point<2>                  &p,
               const std::vector<unsigned int> &indices) const;

    template <int order>
    Tensor<order, 2>
    derivative_tensor(const unsigned int i, const Point<2> &p) const;
  };


  /**
   * The eight-node serendipity quadrilateral (the element of Ascione, Bruno
   * & Olivito, 1984): one degree of freedom at each vertex and on each line,
   * none inside, continuous across cells (H1). Its trace on an edge is the
   * quadratic of FE_Q(2), so the hanging-node constraints of a refined edge
   * are those of FE_Q(2)'s face; they are provided. Interpolation (also
   * through FESystem and VectorTools::interpolate) takes point values at the
   * nodes. Not provided: restriction and prolongation matrices (no
   * SolutionTransfer or multigrid) and hp-compatibility.
   */
  class FE_Serendipity : public FE_Poly<2>
  {
  public:
    FE_Serendipity();

    std::string
    get_name() const override;

    std::unique_ptr<FiniteElement<2, 2>>
    clone() const override;

    void
    convert_generalized_support_point_values_to_dof_values(
      const std::vector<Vector<double>> &support_point_values,
      std::vector<double>               &nodal_values) const override;
  };
} // namespace liftoff
