#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/discretization.h>
#include <liftoff/output_files.h>
#include <liftoff/point_functional.h>

#include <fstream>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /// Energies of the full plate at one instant, and the work done on it.
  struct EnergyBalance
  {
    double kinetic    = 0;
    double strain     = 0;
    double foundation = 0;
    double work       = 0; // of the loads since tau = 0
    /// Total energy minus the initial total minus the work: zero for an
    /// exactly conservative discrete scheme.
    double
    error(const EnergyBalance &initial) const
    {
      return kinetic + strain + foundation
             - (initial.kinetic + initial.strain + initial.foundation) - work;
    }

    /// The four numbers, for checks that treat them alike.
    std::vector<double>
    values() const
    {
      return {kinetic, strain, foundation, work};
    }

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &kinetic &strain &foundation &work;
    }
  };

  /**
   * The CSV time history a user plots: tau, w at the scene's probe points,
   * contact area fraction, active-set iterations, the length of an
   * active-set cycle resolved by the cycle rule (0: none) and, when asked for,
   * the energies and their balance. The file is replaced whole (atomically) at
   * most once a second and at the end, so a reader never sees a half-written
   * row.
   */
  class TimeHistory
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Probes inside the plate (full plate coordinates).
    void
    check_against(const Discretization &discretization) const;

    void
    setup(const Discretization &discretization, const std::string &directory);

    bool
    wants_energies() const;

    /// w at the probes (collective).
    std::vector<double>
    probe_values(const LA::MPI::Vector &ghosted_solution) const;

    /// One row; `probe_w` from probe_values().
    void
    record(const double               tau,
           const std::vector<double> &probe_w,
           const double               contact_fraction,
           const unsigned int         iterations,
           const unsigned int         cycle_length,
           const EnergyBalance       &energies,
           const EnergyBalance       &initial_energies);

    /// Write history.csv now (at the end of a run, also a failed one).
    /// Collective, as is record().
    void
    flush();

    /// Write nothing until flush(): a resumed run records the rows of its
    /// checkpoint again but leaves the file as it is until it has a step
    /// of its own.
    void
    hold();

  private:
    std::vector<Point<2>>        probe_points;
    bool                         write_energies = true;
    std::vector<PointFunctional> probes;
    const Discretization        *discretization = nullptr;
    GrowingTextFile              file;
  };
} // namespace liftoff
