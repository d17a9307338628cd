#pragma once

#include <liftoff/base/archive_types.h>
#include <liftoff/contact/active_set_result.h>

#include <string>

namespace liftoff
{

  // StepData holds references only: the outputs include what they use.
  class Discretization;
  class JointSprings;
  class JointDowels;
  class PhysicalUnits;
  class ResultantSweep;
  class TimeHistory;
  class RunSummary;
  class TensionlessWinklerFoundation;
  struct PlateState;

  /// What an Output sees after a step (or the one solve of a static
  /// analysis): the state (with its clock: step, tau, dt, the last step)
  /// and the parts that give it meaning.
  struct StepData
  {
    const PlateState                   &state;
    const Discretization               &discretization;
    const TensionlessWinklerFoundation &foundation;
    /// What the joints between slabs pass (a plate of one slab has none).
    const JointSprings    &joints;
    const JointDowels     &dowels;
    const ActiveSetResult &iteration;
    /// The resultants at the output points, computed by the first output
    /// that reads them.
    const ResultantSweep &resultants;
    /// Share of the plate in contact (computed once for all outputs: it is
    /// a collective sum).
    double contact_fraction;
  };

  /**
   * One thing a run writes after its steps, in the spirit of ASPECT's
   * postprocessors: the time history, profiles, fields. The Simulator
   * calls every output the same way, so a new one is a new class and one
   * line in the Simulator's list. Its parameters are entries of the
   * `Output` subsection, which the Simulator enters around the output's
   * declare_parameters() and parse_parameters().
   */
  class Output
  {
  public:
    virtual ~Output() = default;

    /// Its columns of history.csv, if it has any (TimeHistory::add_columns).
    virtual void
    add_columns_to(TimeHistory &) const
    {}
    /// Its lines in the run's summary, if it has any.
    virtual void
    add_to(RunSummary &) const
    {}

    /// Write in the scene's units (an SI scene's outputs in SI, with the
    /// units in the headers); an output that does not convert keeps the
    /// solver's dimensionless values.
    virtual void
    write_in_units_of(const PhysicalUnits &)
    {}

    /// Before the first step: the mesh, and the folder to write to (empty:
    /// keep results in memory only).
    virtual void
    setup(const Discretization &discretization,
          const std::string    &directory) = 0;

    /// The mesh has been refined or coarsened (Mesh refinement): whatever
    /// the output keeps per cell or point (probe cells, point searches,
    /// vector layouts) must be found again on `discretization`.
    virtual void
    mesh_changed(const Discretization &discretization) = 0;

    /// After every step. Collective.
    virtual void
    execute(const StepData &step) = 0;

    /// Write what is due now: at the end of a run (also a failed one), and
    /// when a resumed run replaces the files of the run it continues.
    /// Collective.
    virtual void
    flush() = 0;

    /// What a resumed run needs to go on writing as if never stopped.
    /// After load() the output writes nothing until flush(), so a refused
    /// or killed resume leaves the earlier run's files as they are.
    virtual void
    save(OutputArchive &archive) const = 0;
    virtual void
    load(InputArchive &archive) = 0;
  };
} // namespace liftoff
