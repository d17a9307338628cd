#pragma once

#include <deal.II/base/mpi.h>

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace liftoff
{
  class Discretization;
  class EnergyCheck;
  class StepSizeController;
  class TimeStepper;
  class PhysicalUnits;
  class LinearSolver;
  class SectionTimer;

  /**
   * How a run ended and what it cost, as one list of named values written
   * twice: summary.txt ("key: value" lines, a section's entries indented
   * under its key) for people and summary.json for scripts, so that a
   * script never parses the text.
   */
  class RunSummary
  {
  public:
    using Section = std::vector<std::pair<std::string, double>>;
    using Value   = std::variant<std::string, double, Section>;

    void
    add(const std::string &key, const Value &value);
    /// An SI scene's unit system and groups (nothing for a dimensionless
    /// one).
    void
    add_units(const PhysicalUnits &units);
    /// The entries every run reports the same way, in the summary's order:
    /// the mesh (ranks, cells, element, dofs, collective), ...
    void
    add_mesh(const Discretization &discretization);
    /// ... the checks the run made of its answer: the energy balance (or
    /// why it was not checked, with Newmark's `beta`), the static
    /// equilibrium of bed and loads, ...
    void
    add_checks(const TimeStepper &stepper,
               const EnergyCheck &energy_check,
               const bool         is_dynamic,
               const double       beta);
    /// ... with Time step control = error, the steps taken, repeated and
    /// changed (from add_checks()), ...
    void
    add_step_control(const StepSizeController &control);
    /// ... the linear solver's factorisations, substitutions and CG work,
    /// ...
    void
    add_linear_solver(const LinearSolver &solver);
    /// ... and the peak memory per rank and the wall time, by section
    /// (collective).
    void
    add_resources(const SectionTimer &timer,
                  const double        wall_time,
                  const MPI_Comm      comm);

    std::string
    text() const;
    std::string
    json() const;

    /// summary.txt and summary.json in `directory`, each replaced
    /// atomically, from rank 0 (collective).
    void
    write(const std::string &directory, const MPI_Comm comm) const;

  private:
    std::vector<std::pair<std::string, Value>> entries;
  };
} // namespace liftoff
