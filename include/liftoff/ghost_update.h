#pragma once

#include <deal.II/lac/affine_constraints.h>

#include <liftoff/linear_algebra.h>

#include <memory>

class Epetra_Import;

namespace liftoff
{
  using namespace dealii;

  /**
   * Copies a vector of owned entries into a vector with ghost entries, as
   * `ghosted = owned` does, but with one Epetra_Import kept for the pair of
   * layouts instead of one built per copy. Building the import costs far
   * more than the copy on small problems (it is a third of the per-step
   * overhead of the 246-unknown beam, doc/performance.md); the values
   * copied are the same (Epetra's Insert of the same entries).
   */
  class GhostUpdate
  {
  public:
    GhostUpdate();
    ~GhostUpdate();

    /// ghosted = owned. Collective. The import is rebuilt whenever either
    /// layout differs from the one it was built for (a new mesh); the test
    /// is Epetra's SameAs, which agrees on all ranks.
    void
    copy(const LA::MPI::Vector &owned, LA::MPI::Vector &ghosted);

    /// What `constraints.distribute(x); ghosted = x;` does, with the
    /// ghosted vector, not a temporary one, holding the constraints'
    /// sources: ghosted = x, then every constrained entry of x is set from
    /// the ghosted sources (the constraints are closed, so the sources are
    /// not constrained and final), then ghosted = x again. The same
    /// operations in the same order as AffineConstraints::distribute, so
    /// the same bits.
    void
    distribute(const AffineConstraints<double> &constraints,
               LA::MPI::Vector                 &x,
               LA::MPI::Vector                 &ghosted);

  private:
    std::unique_ptr<Epetra_Import> importer;
  };
} // namespace liftoff
