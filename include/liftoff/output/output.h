#pragma once

#include <liftoff/base/archive_types.h>
#include <liftoff/contact/active_set_result.h>

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace liftoff
{
  using dealii::ParameterHandler;

  // StepData holds references only: the outputs include what they use.
  class PhysicalUnits;
  class ResultantSweep;
  class TimeHistory;
  class RunSummary;
  struct PlateState;
  struct SceneView;

  /// What an Output sees after a step (or the one solve of a static
  /// analysis): the state (with its clock: step, tau, dt, the last step)
  /// and the parts that give it meaning.
  struct StepData
  {
    const PlateState &state;
    /// The scene's parts by role (output/scene_view.h).
    const SceneView       &scene;
    const ActiveSetResult &iteration;
    /// The resultants at the output points, computed by the first output
    /// that reads them (the face stresses only if an output needs them).
    const ResultantSweep &resultants;
    /// Share of the plate in contact (computed once for all outputs: it is
    /// a collective sum).
    double contact_fraction;
  };

  /**
   * One thing a run writes after its steps, in the spirit of ASPECT's
   * postprocessors: the time history, profiles, fields. Every output is
   * called the same way, so a new one is a new class with its own
   * parameters and one line in OutputList's list (output_list.cc); the
   * Simulator does not change. Its parameters are entries of the `Output`
   * subsection, which OutputList enters around the output's
   * declare_parameters() and parse_parameters().
   */
  class Output
  {
  public:
    virtual ~Output() = default;

    /// Its entries (none by default); each output declares its own.
    static void
    declare_parameters(ParameterHandler &)
    {}
    /// Read its entries (inside `Output`) and check them against the
    /// scene's parts; throws naming the entry. May be called again with
    /// other parameters before setup().
    virtual void
    parse_parameters(ParameterHandler &, const SceneView &)
    {}
    /// The checks against the scene that follow the parts' own (a probe
    /// on the plate), after every output has read its entries.
    virtual void
    check(const SceneView &) const
    {}
    /// What the output found wrong with the run's answer (empty: nothing),
    /// for the summary's status.
    virtual std::string
    warning() const
    {
      return {};
    }

    /// Whether it reads the face stresses of the step's ResultantSweep
    /// (after parse_parameters()): the sweep computes them for the run only
    /// if an output does.
    virtual bool
    needs_face_stresses() const
    {
      return false;
    }

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
    setup(const SceneView &scene, const std::string &directory) = 0;

    /// The mesh has been refined or coarsened (Mesh refinement): whatever
    /// the output keeps per cell or point (probe cells, point searches,
    /// vector layouts) must be found again on the scene's discretization.
    virtual void
    mesh_changed(const SceneView &scene) = 0;

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
