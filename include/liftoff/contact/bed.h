#pragma once

#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/contact_law.h>
#include <liftoff/contact/foundation_diagnostics.h>
#include <liftoff/contact/status_term.h>

#include <vector>

namespace liftoff
{
  /**
   * The role of the term the plate rests on, as the numerics ask it: the
   * law of its springs and dashpots (whether it damps, holds the plate
   * against rigid-body motion, presses it), what it carries now
   * (diagnostics: resultant, contact, rigid-body restraint), every point
   * engaged as a first iterate, and its dashpots' force. The time stepping,
   * the active-set iteration and the outputs reach the bed only through
   * here; which term plays it is found in the term list (of()), so a scene
   * whose bed is another class (under a base layer) changes no caller.
   */
  class Bed : public StatusTerm
  {
  public:
    /// Gamma, c, G_p, g, and the pressure k (w - e) for a velocity of the
    /// plate.
    virtual const ContactLaw &
    law() const = 0;
    /// What it carries in its current status.
    virtual const FoundationDiagnostics &
    diagnostics() const = 0;
    /// The pressure k (w - e) for the plate's velocity that the status
    /// and the status load take from now on: the solve's (v = kappa w - o)
    /// before a solve, the state's before its status or force balance.
    virtual void
    use_pressure(SpringPressure pressure) = 0;
    /// Every point engaged: the first iterate of a solve from nothing.
    virtual void
    activate_all() = 0;
    /// vector += its dashpots' force at the given state (no dashpots: 0).
    virtual void
    add_dissipative_force(const LA::MPI::Vector &ghosted_solution,
                          const LA::MPI::Vector &ghosted_velocity,
                          LA::MPI::Vector       &vector) const = 0;

    /// The one term of `terms` that is a bed; refuses a list without one.
    static Bed &
    of(const std::vector<SystemTerm *> &terms);
  };
} // namespace liftoff
