#pragma once

#include <deal.II/base/point.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/loads/free_bending.h>
#include <liftoff/output/stress_resultants.h>

#include <vector>

namespace liftoff
{
  using namespace dealii;

  class ContactLaw;
  class Discretization;

  /**
   * The quantities design reads off a plate (the deflection, the bed's
   * spring pressure, the principal moments, the magnitude of the shear
   * force and the largest principal stress of each face, with the slab) at the
   * output points of every cell of this rank, for the history's extremes and
   * the envelopes. The output points are those at which the field files are
   * written (DataOut with as many subdivisions as the element's degree):
   * equidistant, (p + 1)^2 per cell, which are the support points of FE_DGQ(p)
   * in its order, so that a FE_DGQ(p) field holds one value per output point
   * and is written exactly. The moments and shear forces are StressResultants',
   * so every output agrees.
   *
   * One object per step, made by the Simulator and handed to every output
   * in StepData: the values are computed at the first call of values() and
   * kept, so the outputs that read them share one pass over the points.
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
      /// The largest principal stress of each face (StressResultants'
      /// sigma_1_top, sigma_1_bottom); 0 unless the sweep computes them.
      FaceStresses faces;
      /// The slab of the point's cell (0, 1, ...; 0 on a plate of one).
      unsigned int slab = 0;
    };

    /// `free_bending`: the temperature loads' at the step's time (empty:
    /// none), which every output's StressResultants take from here. The
    /// face stresses are computed `with_faces` only: an output reads them
    /// (OutputList::needs_face_stresses()).
    ResultantSweep(const MindlinPlate     &plate,
                   const Discretization   &discretization,
                   const ContactLaw       &law,
                   const LA::MPI::Vector  &ghosted_solution,
                   const FreeBendingField &free_bending = {},
                   const bool              with_faces   = true);

    const FreeBendingField &
    free_bending() const;

    /// The output points of this rank: its cells in the order of the
    /// active cells, in each the support points of FE_DGQ(p).
    const std::vector<Point<2>> &
    points() const;
    /// The values at points().
    const std::vector<Values> &
    values() const;

  private:
    const MindlinPlate           &plate;
    const Discretization         &discretization;
    const ContactLaw             &law;
    const LA::MPI::Vector        &solution;
    const FreeBendingField        thermal_bending;
    const bool                    with_faces;
    mutable std::vector<Point<2>> point_list;
    mutable std::vector<Values>   value_list;
    mutable bool                  is_computed = false;

    void
    compute() const;
  };
} // namespace liftoff
