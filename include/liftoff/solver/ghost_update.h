#pragma once

#include <deal.II/lac/affine_constraints.h>

#include <liftoff/base/linear_algebra.h>

#include <memory>
#include <vector>

class Epetra_Import;
class Epetra_BlockMap;

namespace liftoff
{
  using namespace dealii;

  /**
   * Copies a vector of owned entries into a vector with ghost entries, as
   * `ghosted = owned` does, but with one Epetra_Import kept for the pair of
   * layouts instead of one built per copy. Building the import costs far
   * more than the copy on small problems (it is a third of the per-step
   * overhead of the 246-unknown beam, doc/performance.md, "Outputs and
   * other per-step work"); the values
   * copied are the same (Epetra's Insert of the same entries).
   */
  class GhostUpdate
  {
  public:
    GhostUpdate();
    ~GhostUpdate();

    /// ghosted = owned. Collective. The import is rebuilt whenever either
    /// layout differs from the one it was built for (a new mesh); the test
    /// is Epetra's SameAs, which agrees on all ranks. Its answer is kept
    /// for the layouts' Epetra data (see `known_layouts`).
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

    /// Pairs of layouts (source, target) whose SameAs answer is known,
    /// with the answer. SameAs compares vectors set up separately entry by
    /// entry (6 % of the Example 2 pulse's run); layouts that share
    /// Epetra's map data (copies of one map) are the same object. The
    /// copies kept here hold that data, so its address stays theirs, and
    /// whether two vectors share map data follows from how the program
    /// built them, which every rank does alike: every rank finds a pair
    /// here or none does.
    struct KnownLayouts
    {
      std::unique_ptr<Epetra_BlockMap> source, target;
      bool                             same = false;
    };
    std::vector<KnownLayouts> known_layouts;

    /// Whether target has source's layout, from known_layouts or, for a
    /// pair not seen before, Epetra's SameAs (collective).
    bool
    is_same_layout(const Epetra_BlockMap &source,
                   const Epetra_BlockMap &target);
  };
} // namespace liftoff
