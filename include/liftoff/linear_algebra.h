#pragma once

#include <deal.II/lac/generic_linear_algebra.h>

namespace liftoff
{
  // One alias for the distributed linear algebra, as in step-40: every class
  // speaks of LA::MPI::Vector and LA::MPI::SparseMatrix, so a switch of
  // backend is a change here and in LinearSolver only.
  namespace LA = dealii::LinearAlgebraTrilinos;
} // namespace liftoff
