#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

namespace liftoff
{
  using namespace dealii;

  /**
   * The largest of values met at points of the plate (and times), with the
   * point and time where it was met. Ties go to the point first in x, then
   * in y, then to the earlier time, so that the answer depends neither on
   * the order of the cells nor on the number of ranks.
   */
  struct LocatedMaximum
  {
    double   value = 0;
    Point<2> point;
    double   time  = 0;
    bool     found = false;

    void
    consider(const double v, const Point<2> &at, const double when = 0);

    /// The largest over all ranks (collective); not found where no rank
    /// found one.
    LocatedMaximum
    over_ranks(const MPI_Comm comm) const;
  };
} // namespace liftoff
