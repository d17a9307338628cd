#pragma once

#include <liftoff/base/archive_types.h>
#include <liftoff/solver/linear_solver.h>

#include <functional>
#include <list>
#include <optional>
#include <vector>

namespace liftoff
{
  /**
   * The factors of a few system matrices that take turns, kept so that a
   * return to one costs no factorisation: with Time step control = error
   * the matrix K + c M + K_f(S) depends on the step's level through
   * c = 1/(beta dt^2) and the dashpots' kappa. Each kept factor is stored
   * with what builds its matrix again (the level names the base matrix;
   * the statuses of the terms and kappa the rest), so that it can be used
   * for the matrix of the current statuses as a stale factor is, and
   * rebuilt from a checkpoint. At most `capacity` are kept; beyond, the
   * least recently used is dropped (a factor of a large plate holds
   * hundreds of MB).
   */
  class FactorCache
  {
  public:
    /// A factor, what its matrix was built from, and its state.
    struct Entry
    {
      unsigned int key = 0;
      /// The statuses of the terms (StatusTerm) the factorised matrix held.
      std::vector<std::vector<unsigned char>> factorised_status;
      double                                  velocity_factor = 0;
      KeptFactor                              factor;
    };

    explicit FactorCache(const unsigned int capacity);

    /// Keep `entry` as the most recently used.
    void
    keep(Entry &&entry);
    /// The entry of `key`, taken out, if one is kept.
    std::optional<Entry>
    take(const unsigned int key);
    void
    clear();
    unsigned int
    n_kept() const;

    /// Keys, statuses, kappa and the factors' states, the least recently
    /// used first.
    void
    save(OutputArchive &archive) const;
    /// The entries of save(), each factor built anew by `factorise`, which
    /// fills the entry's factor from its key, statuses and kappa.
    void
    load(InputArchive &archive, const std::function<void(Entry &)> &factorise);

  private:
    unsigned int     capacity;
    std::list<Entry> kept;
  };
} // namespace liftoff
