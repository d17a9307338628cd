#pragma once

#include <liftoff/base/linear_algebra.h>

namespace liftoff
{
  class Discretization;
  class Bed;

  /**
   * The check a static run makes of its own answer: a plate that no edge
   * holds is carried by its bed alone, so the bed's resultant and its
   * moments about the plate's axes must equal those of the loads. The
   * loads' side is the load vector applied to the rigid motions (w = 1;
   * w = x with psi_x = 1; w = y with psi_y = 1, which the stiffness does
   * not resist), the bed's side its pressure integrated at the Gauss points
   * (FoundationDiagnostics::resultant()), so the check catches a wrong
   * solve, a stiffness that resists a rigid motion and a bed force that
   * is not the one the system used. Moments about a symmetry plane vanish
   * by construction and are not compared, nor moments with a shear layer
   * (which takes moments through the slope of w in the contact region).
   */
  struct StaticEquilibrium
  {
    /// The largest of |loads - bed| over the force and the compared
    /// moments, relative to the loads' magnitude (sum of |load entries|),
    /// and the part of it that round-off alone can make.
    struct Result
    {
      /// -1 where the check does not apply (a supported edge, no bed, no
      /// load).
      double imbalance = -1;
      /// The share of the loads by which the bed and the loads may differ
      /// through round-off in the system A u = f that gave u: 16 eps
      /// ||r o (|A| |u|)||_2 (o entrywise) over the compared rigid motions
      /// r. A free plate on a soft bed carries a rigid motion of order
      /// 1 / Gamma, whose products with the stiffness cancel in exact
      /// arithmetic only; each row's error is of order eps (|A| |u|)_i
      /// with signs that do not line up, hence the 2-norm. Over 108 static
      /// scenes (rectangle, disc, annulus; Gamma 1e-2 to 1e-5; loads at
      /// x = 0.3 to 0.45; 0 to 2 refinements; doc/reliability.md) the
      /// imbalance was at most 6.3 times the 2-norm term.
      double round_off = 0;

      /// The imbalance a run accepts without a warning: `tolerance`, or
      /// the round-off where that is larger.
      double
      accepted() const;
      bool
      holds() const;
    };

    /// Collective.
    static Result
    check(const Discretization        &discretization,
          const Bed                   &foundation,
          const LA::MPI::Vector       &ghosted_solution,
          const LA::MPI::Vector       &load,
          const LA::MPI::SparseMatrix &system_matrix);

    /// The largest imbalance a static run accepts without a warning where
    /// round-off allows it: the direct solves leave about 1e-12.
    static constexpr double tolerance = 1e-8;
  };
} // namespace liftoff
