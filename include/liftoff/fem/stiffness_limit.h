#pragma once

#include <liftoff/fem/system_term.h>

#include <vector>

namespace liftoff
{
  /**
   * Refuses a coupling stiffness (a joint's springs, a dowel) that the
   * linear solve cannot carry. Springs between two slabs are a penalty: in
   * the rows they touch, an entry C times the plate's own drowns the
   * plate's digits once C / K_ii nears 1 / epsilon, and a status term that
   * adds and later subtracts C loses them for good (two slabs, dowels of
   * 1e300: `completed` with every dowel force 0). Beyond a ratio of
   * `largest_ratio` the joint is as stiff as it gets (the penalty's own
   * error, about K_ii / C, is below the solve's tolerance), so nothing is
   * lost by refusing more.
   */
  class StiffnessLimit
  {
  public:
    /// The largest C / K_ii accepted, K_ii the plate's stiffness on the
    /// diagonal in a row the coupling touches. Measured on two 8 x 8 Q1
    /// slabs with dowels under self-weight (doc/reliability.md): the
    /// round-off in the settled deflection is about 7e-12 times the ratio
    /// (9e-8 at 4.2e4, 3e-5 at 4.2e6; refinement refuses 4.2e7), the
    /// penalty's distance from the stiff limit about 6e-3 over it (1.4e-5
    /// at 417, 6e-8 at 4.2e4). At 1e5 both stay near 1e-6.
    static constexpr double largest_ratio = 1e5;

    /// Throws, naming the entry, its value and the largest value this
    /// scene carries, if a coupling of `terms` exceeds largest_ratio in any
    /// row (collective).
    static void
    check(const LA::MPI::SparseMatrix     &plate_stiffness,
          const AffineConstraints<double> &constraints,
          const std::vector<SystemTerm *> &terms);

    /// The largest d_i / K_ii over the rows this rank owns and that are not
    /// constrained, over all ranks: how many times the plate's own entry
    /// one unit of the coupling adds.
    static double
    largest_relative_entry(const LA::MPI::Vector           &diagonal_per_unit,
                           const LA::MPI::SparseMatrix     &plate_stiffness,
                           const AffineConstraints<double> &constraints);
  };
} // namespace liftoff
