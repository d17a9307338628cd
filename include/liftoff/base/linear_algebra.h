#pragma once

#include <deal.II/base/mpi.h>

#include <deal.II/lac/generic_linear_algebra.h>

#include <Epetra_FEVector.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  // One alias for the distributed linear algebra, as in step-40: every class
  // speaks of LA::MPI::Vector and LA::MPI::SparseMatrix, so a switch of
  // backend is a change here and in LinearSolver only.
  namespace LA = dealii::LinearAlgebraTrilinos;

  /// `to = from` for two vectors of one layout (the same map on every rank),
  /// without communication. deal.II 9.4's operator= builds an
  /// Epetra_Import for each copy unless both vectors share one Epetra
  /// communicator object, which vectors set up separately do not; that
  /// cost more than the copy on small problems (doc/performance.md). The
  /// values are the ones the import inserts.
  inline void
  copy_values(const LA::MPI::Vector &from, LA::MPI::Vector &to)
  {
    Assert(to.trilinos_vector().Map().PointSameAs(from.trilinos_vector().Map()),
           dealii::ExcMessage("copy_values() needs vectors of one layout."));
    static_cast<Epetra_MultiVector &>(to.trilinos_vector()) =
      from.trilinos_vector();
  }

  /// Whether every entry this rank owns is a finite number (not collective).
  inline bool
  has_finite_local_entries(const LA::MPI::Vector &v)
  {
    return std::all_of(v.begin(), v.end(), [](const double x) {
      return std::isfinite(x);
    });
  }

  /// Whether every entry on every rank is a finite number (collective).
  inline bool
  is_finite(const LA::MPI::Vector &v)
  {
    return dealii::Utilities::MPI::min(static_cast<int>(
                                         has_finite_local_entries(v)),
                                       v.get_mpi_communicator())
           == 1;
  }
} // namespace liftoff
