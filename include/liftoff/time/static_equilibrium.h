#pragma once

#include <liftoff/base/linear_algebra.h>

namespace liftoff
{
  class Discretization;
  class TensionlessWinklerFoundation;

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
    /// moments, relative to the loads' magnitude (sum of |load entries|).
    /// -1 where the check does not apply (a supported edge, no bed, no
    /// load). Collective.
    static double
    imbalance(const Discretization               &discretization,
              const TensionlessWinklerFoundation &foundation,
              const LA::MPI::Vector              &ghosted_solution,
              const LA::MPI::Vector              &load);

    /// The largest imbalance a static run accepts without a warning: the
    /// direct solves leave about 1e-12.
    static constexpr double tolerance = 1e-8;
  };
} // namespace liftoff
