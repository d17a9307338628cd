#include <deal.II/base/mpi.h>

#include <liftoff/contact/spring_term.h>

#include <algorithm>

namespace liftoff
{
  namespace
  {
    bool
    is_zero(const std::vector<double> &weight)
    {
      return std::all_of(weight.begin(), weight.end(), [](const double x) {
        return x == 0.0;
      });
    }
  } // namespace


  void
  SpringTerm::setup(const FoundationPoints &foundation_points,
                    const double            modulus)
  {
    points        = &foundation_points;
    layer_modulus = modulus;
  }


  template <class FactorOf>
  bool
  SpringTerm::cell_weights(const unsigned int   c,
                           const FactorOf      &factor,
                           const double         k,
                           std::vector<double> &weight,
                           std::vector<double> &layer_weight) const
  {
    const unsigned int n_q = points->n_q_points();
    weight.resize(n_q);
    layer_weight.resize(n_q);
    bool any = false;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const unsigned int i = c * n_q + q;
        const double       f = factor(i);
        weight[q]            = f * k * points->JxW(i);
        layer_weight[q]      = f * layer_modulus * points->JxW(i);
        any                  = any || f != 0.0;
      }
    return any;
  }


  void
  SpringTerm::add_cell_term(const unsigned int         c,
                            const std::vector<double> &weight,
                            const std::vector<double> &layer_weight,
                            LA::MPI::SparseMatrix     &matrix) const
  {
    const unsigned int n_w = points->n_w_dofs();
    const unsigned int n_q = points->n_q_points();
    FullMatrix<double> cell_matrix(n_w, n_w);
    for (unsigned int q = 0; q < n_q; ++q)
      if (weight[q] != 0.0)
        for (unsigned int i = 0; i < n_w; ++i)
          for (unsigned int j = 0; j < n_w; ++j)
            cell_matrix(i, j) +=
              weight[q] * points->shape_value(q, i) * points->shape_value(q, j);
    // The shear layer at the same points: the same status, one path.
    if (layer_modulus > 0)
      for (unsigned int q = 0; q < n_q; ++q)
        if (layer_weight[q] != 0.0)
          {
            const Tensor<1, 2> *grad = points->shape_gradients(c, q);
            for (unsigned int i = 0; i < n_w; ++i)
              for (unsigned int j = 0; j < n_w; ++j)
                cell_matrix(i, j) += layer_weight[q] * (grad[i] * grad[j]);
          }
    points->add_cell_matrix(c, cell_matrix, matrix);
  }


  void
  SpringTerm::apply_weights(const std::vector<double> &weight,
                            const std::vector<double> &values,
                            Vector<double>            &cell_vector) const
  {
    for (unsigned int k = 0; k < cell_vector.size(); ++k)
      {
        double sum = 0;
        for (unsigned int q = 0; q < weight.size(); ++q)
          sum += weight[q] * values[q] * points->shape_value(q, k);
        cell_vector(k) = sum;
      }
  }


  void
  SpringTerm::cell_product(const unsigned int         c,
                           const std::vector<double> &weight,
                           const std::vector<double> &layer_weight,
                           const LA::MPI::Vector     &u,
                           Vector<double>            &cell_vector) const
  {
    cell_vector = 0;
    if (!is_zero(weight))
      {
        std::vector<double> w;
        points->values_at_points(u, c, w);
        apply_weights(weight, w, cell_vector);
      }
    if (layer_modulus == 0 || is_zero(layer_weight))
      return;
    std::vector<Tensor<1, 2>> gradient;
    points->gradients_at_points(u, c, gradient);
    for (unsigned int q = 0; q < weight.size(); ++q)
      if (layer_weight[q] != 0.0)
        {
          const Tensor<1, 2> *grad = points->shape_gradients(c, q);
          for (unsigned int k = 0; k < cell_vector.size(); ++k)
            cell_vector(k) += layer_weight[q] * (gradient[q] * grad[k]);
        }
  }


  void
  SpringTerm::add_to_matrix(const Factor                    &factor,
                            const std::vector<unsigned int> *listed,
                            const double                     k,
                            LA::MPI::SparseMatrix           &matrix) const
  {
    std::vector<double> weight, layer_weight;
    const auto          add_cell = [&](const unsigned int c) {
      if (cell_weights(c, factor, k, weight, layer_weight))
        add_cell_term(c, weight, layer_weight, matrix);
    };
    if (listed == nullptr)
      for (unsigned int c = 0; c < points->n_cells(); ++c)
        add_cell(c);
    else
      {
        // Each cell of a listed point once.
        const unsigned int n_q = points->n_q_points();
        for (auto p = listed->begin(); p != listed->end();)
          {
            const unsigned int c = *p / n_q;
            add_cell(c);
            for (; p != listed->end() && *p / n_q == c; ++p)
              ;
          }
      }
  }


  void
  SpringTerm::add_product(const Factor          &factor,
                          const double           k,
                          const LA::MPI::Vector &ghosted_src,
                          LA::MPI::Vector       &dst) const
  {
    std::vector<double> weight, layer_weight;
    Vector<double>      cell_vector(points->n_w_dofs());
    for (unsigned int c = 0; c < points->n_cells(); ++c)
      if (cell_weights(c, factor, k, weight, layer_weight))
        {
          cell_product(c, weight, layer_weight, ghosted_src, cell_vector);
          points->add_cell_vector(c, cell_vector, dst);
        }
    dst.compress(VectorOperation::add);
  }


  void
  SpringTerm::add_reaction(const std::vector<unsigned char> &status,
                           const double                      k,
                           const LA::MPI::Vector            &u,
                           LA::MPI::Vector                  &vector) const
  {
    const auto is_in = [&](const unsigned int i) { return 1.0 * status[i]; };
    std::vector<double>       weight, layer_weight;
    const std::vector<double> none(points->n_q_points(), 0.0);
    // Springs and layer each summed into `vector` on its own, as before the
    // term had one place: one pass would round the reaction of a scene
    // with a layer differently (benchmarks/same_results.sh).
    points->add_cell_vectors(
      [&](const unsigned int c, Vector<double> &cell_vector) {
        if (cell_weights(c, is_in, k, weight, layer_weight))
          cell_product(c, weight, none, u, cell_vector);
      },
      vector);
    if (layer_modulus > 0)
      points->add_cell_vectors(
        [&](const unsigned int c, Vector<double> &cell_vector) {
          if (cell_weights(c, is_in, k, weight, layer_weight))
            cell_product(c, none, layer_weight, u, cell_vector);
        },
        vector);
  }


  void
  SpringTerm::add_integral(
    const Factor &factor,
    const double  k,
    const std::function<void(const unsigned int, std::vector<double> &)> &f,
    LA::MPI::Vector &vector) const
  {
    std::vector<double> weight, layer_weight, values;
    points->add_cell_vectors(
      [&](const unsigned int c, Vector<double> &cell_vector) {
        if (cell_weights(c, factor, k, weight, layer_weight))
          {
            f(c, values);
            apply_weights(weight, values, cell_vector);
          }
      },
      vector);
  }
} // namespace liftoff
