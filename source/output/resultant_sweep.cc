#include <liftoff/contact/contact_law.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/stress_resultants.h>

#include <cmath>

namespace liftoff
{
  ResultantSweep::ResultantSweep(const MindlinPlate   &plate,
                                 const Discretization &discretization,
                                 const ContactLaw     &law)
      : plate(plate)
      , discretization(discretization)
      , law(law)
      , points(discretization.element().degree())
  {}


  const FE_DGQ<2> &
  ResultantSweep::point_element() const
  {
    return points;
  }


  void
  ResultantSweep::visit(const LA::MPI::Vector &ghosted_u,
                        const Work            &work) const
  {
    const Discretization  &disc = discretization;
    const StressResultants resultants(plate,
                                      disc.mapping,
                                      disc.element().shear_integration(),
                                      ghosted_u);
    const unsigned int     m_1 = StressResultants::field_index("M_1"),
                       m_2     = StressResultants::field_index("M_2"),
                       q_x     = StressResultants::field_index("Q_x"),
                       q_y     = StressResultants::field_index("Q_y");
    FEValues<2>                 fe_values(disc.mapping,
                          disc.dof_handler.get_fe(),
                          Quadrature<2>(points.get_unit_support_points()),
                          update_values | update_gradients
                            | update_quadrature_points);
    const unsigned int          n = fe_values.n_quadrature_points;
    std::vector<Vector<double>> fields;
    std::vector<double>         w(n);
    std::vector<Values>         values(n);
    for (const auto &cell : disc.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          resultants.evaluate(cell, fe_values, fields);
          fe_values[FEValuesExtractors::Scalar(0)].get_function_values(
            ghosted_u, w);
          const auto &x = fe_values.get_quadrature_points();
          for (unsigned int k = 0; k < n; ++k)
            {
              const double g     = (law.has_gap() ? law.gap_at(x[k]) : 0.0);
              values[k].w        = w[k];
              values[k].pressure = law.spring_pressure(w[k] - g);
              values[k].m_1      = fields[k][m_1];
              values[k].m_2      = fields[k][m_2];
              values[k].shear    = std::hypot(fields[k][q_x], fields[k][q_y]);
            }
          work(cell, x, values);
        }
  }
} // namespace liftoff
