#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_values.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/mindlin_plate.h>

#include <functional>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class ContactLaw;
  class Discretization;

  /**
   * The quantities design reads off a plate (the deflection, the bed's
   * spring pressure, the principal moments and the magnitude of the shear
   * force) at the output points of every cell of this rank, for the
   * history's extremes and the envelopes. The output points are those at
   * which the field files are written (DataOut with as many subdivisions as
   * the element's degree): equidistant, (p + 1)^2 per cell, which are the
   * support points of FE_DGQ(p) in its order, so that a FE_DGQ(p) field
   * holds one value per output point and is written exactly. The moments
   * and shear forces are StressResultants', so every output agrees.
   */
  class ResultantSweep
  {
  public:
    struct Values
    {
      double w        = 0;
      double pressure = 0;
      double m_1      = 0;
      double m_2      = 0;
      double shear    = 0;
    };

    /// What visit() hands on for each cell: the cell of the plate's
    /// DoFHandler, the points in real coordinates and their values.
    using Work =
      std::function<void(const DoFHandler<2>::active_cell_iterator &cell,
                         const std::vector<Point<2>>               &points,
                         const std::vector<Values>                 &values)>;

    ResultantSweep(const MindlinPlate   &plate,
                   const Discretization &discretization,
                   const ContactLaw     &law);

    /// The element whose support points are the output points.
    const FE_DGQ<2> &
    point_element() const;

    void
    visit(const LA::MPI::Vector &ghosted_u, const Work &work) const;

  private:
    const MindlinPlate   &plate;
    const Discretization &discretization;
    const ContactLaw     &law;
    const FE_DGQ<2>       points;
  };
} // namespace liftoff
