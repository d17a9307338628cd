#pragma once

#include <liftoff/base/archives.h>
#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/time/clock.h>
#include <liftoff/time/energy_balance.h>

namespace liftoff
{
  using namespace dealii;

  /**
   * Everything the time loop carries from one step to the next: the
   * Newmark state (u, v, a) at tau, the load F(tau), the force balance
   * F - K u - K_f u that generalized-alpha weighs into the next step, and
   * the work of the loads so far. A checkpoint saves it as it is, bit for
   * bit; a static analysis uses u and the load only. The TimeStepper lays
   * the vectors out on a mesh in one list with its own
   * (TimeStepper::build_on_current_mesh()).
   */
  struct PlateState
  {
    /// The step and tau of the state.
    Clock clock;
    /// Owned entries, constraints distributed.
    LA::MPI::Vector u, v, a;
    /// u with ghost entries, for evaluation at quadrature points.
    LA::MPI::Vector ghosted_u;
    /// The plate at rest, from which the joints' load transfer is
    /// measured (as a deflectometer measures): u at tau = 0 in a time
    /// integration (settled under the loads that act from before it), and
    /// in a static analysis the equilibrium under the weight and the
    /// temperature loads alone (0 if they have none). Owned, and with
    /// ghosts.
    LA::MPI::Vector rest, ghosted_rest;
    LA::MPI::Vector load, balance;
    double          work = 0;
    /// Energy the foundation's dashpots have taken out since tau = 0.
    double dissipated = 0;
    /// At tau, and at tau = 0 (the reference of the balance error).
    EnergyBalance energies, initial_energies;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &clock &work &dissipated &energies &initial_energies;
      for (LA::MPI::Vector *vector : {&u, &v, &a, &load, &balance, &rest})
        serialize_entries(archive, *vector);
      if constexpr (Archive::is_loading::value)
        {
          ghosted_u    = u;
          ghosted_rest = rest;
        }
    }
  };
} // namespace liftoff
