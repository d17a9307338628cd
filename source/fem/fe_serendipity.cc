#include <deal.II/base/table_indices.h>

#include <liftoff/fem/fe_serendipity.h>

namespace liftoff
{
  namespace
  {
    // The monomials x^a y^b that span the serendipity space.
    constexpr std::array<std::array<unsigned int, 2>, 8> exponents = {
      {{{0, 0}},
       {{1, 0}},
       {{0, 1}},
       {{2, 0}},
       {{1, 1}},
       {{0, 2}},
       {{2, 1}},
       {{1, 2}}}};

    // d^k/dt^k t^a.
    double
    power_derivative(const double t, const unsigned int a, const unsigned int k)
    {
      if (k > a)
        return 0.0;
      double result = 1.0;
      for (unsigned int j = 0; j < k; ++j)
        result *= a - j;
      for (unsigned int j = k; j < a; ++j)
        result *= t;
      return result;
    }
  } // namespace


  SerendipityPolynomials::SerendipityPolynomials()
      : ScalarPolynomialsBase<2>(2, n_shape_functions)
      , coefficients(n_shape_functions, n_shape_functions)
  {
    // The nodal basis: coefficients * V^T = I with V(j, m) the monomial m at
    // node j. V is the interpolation matrix of the space at its nodes, which
    // is regular (the nodes are unisolvent for it).
    const std::vector<Point<2>> points = nodes();
    FullMatrix<double>          vandermonde_transposed(n_shape_functions,
                                              n_shape_functions);
    for (unsigned int j = 0; j < n_shape_functions; ++j)
      for (unsigned int m = 0; m < n_shape_functions; ++m)
        vandermonde_transposed(m, j) =
          power_derivative(points[j][0], exponents[m][0], 0)
          * power_derivative(points[j][1], exponents[m][1], 0);
    coefficients.invert(vandermonde_transposed);
  }


  std::vector<Point<2>>
  SerendipityPolynomials::nodes()
  {
    return {Point<2>(0, 0),
            Point<2>(1, 0),
            Point<2>(0, 1),
            Point<2>(1, 1),
            Point<2>(0, 0.5),
            Point<2>(1, 0.5),
            Point<2>(0.5, 0),
            Point<2>(0.5, 1)};
  }


  double
  SerendipityPolynomials::derivative(
    const unsigned int               i,
    const Point<2>                  &p,
    const std::vector<unsigned int> &indices) const
  {
    unsigned int n_along[2] = {0, 0};
    for (const unsigned int d : indices)
      ++n_along[d];
    double result = 0;
    for (unsigned int m = 0; m < n_shape_functions; ++m)
      result += coefficients(i, m)
                * power_derivative(p[0], exponents[m][0], n_along[0])
                * power_derivative(p[1], exponents[m][1], n_along[1]);
    return result;
  }


  template <int order>
  Tensor<order, 2>
  SerendipityPolynomials::derivative_tensor(const unsigned int i,
                                            const Point<2>    &p) const
  {
    // Every entry of the tensor: the bits of `entry` are the directions.
    Tensor<order, 2> result;
    for (unsigned int entry = 0; entry < (1u << order); ++entry)
      {
        std::vector<unsigned int> indices(order);
        TableIndices<order>       position;
        for (unsigned int k = 0; k < order; ++k)
          {
            indices[k]  = (entry >> k) & 1u;
            position[k] = indices[k];
          }
        result[position] = derivative(i, p, indices);
      }
    return result;
  }


  void
  SerendipityPolynomials::evaluate(
    const Point<2>            &unit_point,
    std::vector<double>       &values,
    std::vector<Tensor<1, 2>> &grads,
    std::vector<Tensor<2, 2>> &grad_grads,
    std::vector<Tensor<3, 2>> &third_derivatives,
    std::vector<Tensor<4, 2>> &fourth_derivatives) const
  {
    for (unsigned int i = 0; i < n_shape_functions; ++i)
      {
        if (!values.empty())
          values[i] = compute_value(i, unit_point);
        if (!grads.empty())
          grads[i] = derivative_tensor<1>(i, unit_point);
        if (!grad_grads.empty())
          grad_grads[i] = derivative_tensor<2>(i, unit_point);
        if (!third_derivatives.empty())
          third_derivatives[i] = derivative_tensor<3>(i, unit_point);
        if (!fourth_derivatives.empty())
          fourth_derivatives[i] = derivative_tensor<4>(i, unit_point);
      }
  }


  double
  SerendipityPolynomials::compute_value(const unsigned int i,
                                        const Point<2>    &p) const
  {
    return derivative(i, p, {});
  }


  Tensor<1, 2>
  SerendipityPolynomials::compute_1st_derivative(const unsigned int i,
                                                 const Point<2>    &p) const
  {
    return derivative_tensor<1>(i, p);
  }


  Tensor<2, 2>
  SerendipityPolynomials::compute_2nd_derivative(const unsigned int i,
                                                 const Point<2>    &p) const
  {
    return derivative_tensor<2>(i, p);
  }


  Tensor<3, 2>
  SerendipityPolynomials::compute_3rd_derivative(const unsigned int i,
                                                 const Point<2>    &p) const
  {
    return derivative_tensor<3>(i, p);
  }


  Tensor<4, 2>
  SerendipityPolynomials::compute_4th_derivative(const unsigned int i,
                                                 const Point<2>    &p) const
  {
    return derivative_tensor<4>(i, p);
  }


  Tensor<1, 2>
  SerendipityPolynomials::compute_grad(const unsigned int i,
                                       const Point<2>    &p) const
  {
    return derivative_tensor<1>(i, p);
  }


  Tensor<2, 2>
  SerendipityPolynomials::compute_grad_grad(const unsigned int i,
                                            const Point<2>    &p) const
  {
    return derivative_tensor<2>(i, p);
  }


  std::unique_ptr<ScalarPolynomialsBase<2>>
  SerendipityPolynomials::clone() const
  {
    return std::make_unique<SerendipityPolynomials>(*this);
  }


  std::string
  SerendipityPolynomials::name() const
  {
    return "SerendipityPolynomials";
  }


  FE_Serendipity::FE_Serendipity()
      : FE_Poly<2>(
        SerendipityPolynomials(),
        FiniteElementData<2>({1, 1, 0}, 1, 2, FiniteElementData<2>::H1),
        std::vector<bool>(SerendipityPolynomials::n_shape_functions, false),
        std::vector<ComponentMask>(SerendipityPolynomials::n_shape_functions,
                                   ComponentMask(1, true)))
  {
    this->unit_support_points        = SerendipityPolynomials::nodes();
    this->generalized_support_points = this->unit_support_points;
    // On a face: its two vertices, then its mid-point.
    this->unit_face_support_points.resize(1);
    this->unit_face_support_points[0] = {Point<1>(0),
                                         Point<1>(1),
                                         Point<1>(0.5)};

    // Hanging nodes: the refined side's degrees of freedom (the middle
    // vertex, then the mid-points of the two child lines) as values of the
    // coarse side's trace, read off face 0 (x = 0) of the reference cell.
    const std::array<double, 3> refined_side = {{0.5, 0.25, 0.75}};
    this->interface_constraints.reinit(3, this->n_dofs_per_face(0));
    for (unsigned int r = 0; r < refined_side.size(); ++r)
      for (unsigned int k = 0; k < this->n_dofs_per_face(0); ++k)
        this->interface_constraints(r, k) =
          this->shape_value(this->face_to_cell_index(k, 0),
                            Point<2>(0, refined_side[r]));
  }


  std::string
  FE_Serendipity::get_name() const
  {
    return "FE_Serendipity<2>(2)";
  }


  std::unique_ptr<FiniteElement<2, 2>>
  FE_Serendipity::clone() const
  {
    return std::make_unique<FE_Serendipity>(*this);
  }


  void
  FE_Serendipity::convert_generalized_support_point_values_to_dof_values(
    const std::vector<Vector<double>> &support_point_values,
    std::vector<double>               &nodal_values) const
  {
    // The degrees of freedom are the point values at the nodes.
    AssertDimension(support_point_values.size(), this->n_dofs_per_cell());
    AssertDimension(nodal_values.size(), this->n_dofs_per_cell());
    for (unsigned int i = 0; i < support_point_values.size(); ++i)
      nodal_values[i] = support_point_values[i](0);
  }
} // namespace liftoff
