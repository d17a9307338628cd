#pragma once

// The energy balance of a run as the tests read it.

#include <liftoff/run/simulator.h>

#include <algorithm>
#include <cmath>

namespace liftoff_tests
{
  /// max |balance error| / max |work| over a run's history (the error
  /// against the state of its first row).
  inline double
  relative_balance_error(const liftoff::Simulator &simulator)
  {
    const auto &history = simulator.history();
    double      error = 0, work = 0;
    for (const auto &row : history)
      {
        error = std::max(error,
                         std::abs(row.energies().error(history[0].energies())));
        work  = std::max(work, std::abs(row.energies().work));
      }
    return error / work;
  }

  /// |strain + foundation energy - work| / work of a static run's row:
  /// Clapeyron's identity, which only an equilibrium satisfies.
  inline double
  clapeyron_error(const liftoff::HistoryRow &row)
  {
    return std::abs(row.energies().strain + row.energies().supports
                    - row.energies().work)
           / row.energies().work;
  }
} // namespace liftoff_tests
