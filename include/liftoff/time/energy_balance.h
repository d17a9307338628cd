#pragma once

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/system_term.h>

#include <vector>

namespace liftoff
{
  using namespace dealii;

  /// Energies of the full plate at one instant, and the work done on it.
  struct EnergyBalance
  {
    double kinetic = 0;
    /// The energy the plate stores, and its supports and couplings (the
    /// bed's springs, the joints', the dowels'): SystemTerm::stores().
    double strain     = 0;
    double supports   = 0;
    double work       = 0; // of the loads since tau = 0
    double dissipated = 0; // by the foundation's dashpots since tau = 0
    /// What each term of the system stores, in the term list's order
    /// (SystemTerm::energy_column() names each); empty where the energies
    /// were not computed.
    std::vector<double> by_term;
    /// Total energy minus the initial total minus the work plus what the
    /// dashpots took out: zero for an exactly conservative discrete scheme.
    double
    error(const EnergyBalance &initial) const
    {
      return kinetic + strain + supports
             - (initial.kinetic + initial.strain + initial.supports) - work
             + dissipated;
    }

    /// The five sums, for checks that treat them alike.
    std::vector<double>
    values() const
    {
      return {kinetic, strain, supports, work, dissipated};
    }

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &kinetic &strain &supports &work &dissipated &by_term;
    }
  };

  /// The kinetic energy, the plate's strain energy and the energy its
  /// supports and couplings store, each the sum of the terms'
  /// (SystemTerm::kinetic_energy(), stores()), and each term's, of the state
  /// (u, v) of the modelled part times `copies` (the full plate), with the
  /// work `work`. `ghosted_u` is u with ghosts, `product` scratch of u's
  /// layout (collective).
  EnergyBalance
  energies_of(const std::vector<SystemTerm *> &terms,
              const LA::MPI::Vector           &u,
              const LA::MPI::Vector           &ghosted_u,
              const LA::MPI::Vector           &v,
              const double                     copies,
              const double                     work,
              LA::MPI::Vector                 &product);

  /// Work of the loads over one step from (u_old, F_old) to (u_new, F_new)
  /// by the trapezoidal rule, 1/2 (u_new - u_old).(F_old + F_new), times
  /// `copies`: exact for Newmark's average acceleration rule on linear
  /// problems, so that the balance error measures the scheme. `increment`
  /// and `load_sum` are scratch vectors of the same layout (collective).
  double
  work_of_step(const LA::MPI::Vector &u_old,
               const LA::MPI::Vector &u_new,
               const LA::MPI::Vector &load_old,
               const LA::MPI::Vector &load_new,
               const double           copies,
               LA::MPI::Vector       &increment,
               LA::MPI::Vector       &load_sum);
} // namespace liftoff
