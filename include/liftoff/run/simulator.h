#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <liftoff/base/physical_units.h>
#include <liftoff/base/section_timer.h>

#include <liftoff/output/output_list.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/run/checkpoint.h>
#include <liftoff/run/output_directory.h>
#include <liftoff/run/scene_parts.h>
#include <liftoff/time/time_stepper.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class Envelopes;

  /**
   * One scene from start to end, the main loop in the sense of step-69:
   * reads the parameters of every part (SceneParts) and the outputs',
   * checks them against each other, owns the output folder, and runs the
   * static analysis or the time loop, deciding when the mesh adapts, a
   * checkpoint is written and a stop request ends the run; the numerics of
   * each solve and step are the TimeStepper's. Writes what the scene asks
   * for and the summary. Tests drive it the same way the executable does
   * and read the results it keeps.
   */
  class Simulator
  {
  public:
    /// How a run treats its output directory. A run owns it while it runs
    /// (OutputDirectory); `fresh` refuses a directory holding an earlier
    /// run's results, `overwrite` removes them first, `resume` continues
    /// the earlier run from its newest checkpoint.
    enum class Start
    {
      fresh,
      overwrite,
      resume
    };

    /// With verbose = false nothing is printed (tests); show_progress =
    /// false leaves out the progress line only (`liftoff --quiet`).
    explicit Simulator(const MPI_Comm comm,
                       const bool     verbose       = true,
                       const bool     show_progress = true);

    static void
    declare_parameters(ParameterHandler &prm);
    /// declare_parameters() on the handler a scene is read into, which
    /// this simulator's units watch for the entries the scene sets
    /// (PhysicalUnits::watch()).
    void
    declare_scene(ParameterHandler &prm);
    /// Read and check everything that needs no mesh; throws with a message
    /// naming the offending parameter. Builds and writes nothing, so it
    /// may be called again with other parameters before run().
    void
    parse_parameters(ParameterHandler &prm);

    /// Build the scene and run it, started as `start` says. `prm` is
    /// recorded with the results and compared with the checkpoint's scene.
    void
    run(const ParameterHandler &prm, const Start start = Start::fresh);

    /// See LoadSet::set_body_force(); for manufactured solutions.
    void
    set_body_force(Function<2> *force);

    /// Deflection at a point of the full plate (collective).
    double
    deflection_at(const Point<2> &p) const;

    /// The rows of the time history, one per step (and tau = 0).
    const std::vector<HistoryRow> &
    history() const;
    /// The envelopes (Output/Write envelopes).
    const Envelopes &
    get_envelopes() const;
    /// The output of class T (tests read their results).
    template <class T>
    const T &
    get_output() const
    {
      return outputs.get<T>();
    }
    const LA::MPI::Vector &
    solution() const;
    /// The foundation pressure Gamma (w - g) + c v at the Gauss points of
    /// the state (collective; see
    /// TensionlessWinklerFoundation::pressure_range()).
    FoundationDiagnostics::PressureRange
    contact_pressure_range() const;
    /// StaticEquilibrium::check()'s imbalance of a static run's solution (-1
    /// where it does not apply).
    double
    static_equilibrium_imbalance() const;
    /// The signal (SIGINT, SIGTERM) that stopped the run, or 0.
    int
    stopping_signal() const;

    /// Factorisations (or preconditioner set-ups) of the run.
    unsigned int
    n_factorizations() const;
    /// The linear solver: its factor and counters.
    const LinearSolver &
    linear_solver() const;
    const Discretization &
    get_discretization() const;
    /// The plate's material and section.
    const MindlinPlate &
    get_plate() const;

  private:
    MPI_Comm mpi_communicator;
    /// Rank 0's terminal, each stream on or off: `liftoff --quiet` writes
    /// the one status line alone (the summary only in summary.txt), else
    /// the start-up lines, the progress line and the summary.
    ConditionalOStream pcout, status_out;
    SectionTimer       timer;
    Timer              wall_clock;

    /// The scene's unit system; converts an SI scene before the parts
    /// read it, and gives the outputs their units.
    PhysicalUnits units;
    SceneParts    parts;
    /// What is written after each step.
    OutputList outputs;
    Checkpoint checkpoint;

    int         stopped_by_signal = 0;
    std::string output_directory;
    /// The scene as Checkpoint compares it, and the step resumed from.
    std::string  scene;
    unsigned int resume_step = 0;
    /// The parameters as used_parameters.prm records them
    /// (PhysicalUnits::record_of()).
    std::string used_parameters;
    /// The output directory, locked while run() runs.
    std::unique_ptr<OutputDirectory> output_folder;
    /// False while a resumed run has not yet replaced the files of the run
    /// it continues (see take_over_output()).
    bool has_taken_over_output = true;

    /// The numerics of the run, on the parts above; made by setup().
    std::unique_ptr<TimeStepper> stepper;
    /// The largest change of the total energy (kinetic + strain +
    /// foundation) a transfer to a new mesh caused, relative to the energy
    /// before it.
    double largest_energy_jump = 0;

    /// The warnings of the checks the run made of its answer (the energy
    /// balance or static equilibrium, small deflections), one text.
    std::string
    warnings() const;
    /// The mesh was due to adapt after the last step, which skips it: a
    /// checkpoint of that step keeps this, and a resume that goes further
    /// adapts before its first step, as a run without the stop did.
    bool adaptation_pending = false;

    /// The checks across parts and outputs that need no mesh (and a
    /// warning about profile times a run does not reach).
    void
    check_scene() const;
    /// Mesh, matrices, foundation, loads and state vectors (the stepper),
    /// and the checks that need the mesh; writes nothing.
    void
    setup();
    std::unique_ptr<OutputDirectory>
    prepare_output_directory(const Start start) const;
    /// What can be refused only once the matrices exist, before any file is
    /// written: non-finite initial conditions, a time step beyond the
    /// stability limit of a conditionally stable scheme.
    void
    check_before_run();
    /// End the run as interrupted by `signal` (the exit code is 128 +
    /// signal); `when` completes the message.
    [[noreturn]] void
    stop_for_signal(const int signal, const std::string &when);
    /// The stepper's check for a stop request after a static solve.
    TimeStepper::StopCheck
    stop_check();
    /// A resumed run leaves every file of the run it continues as it is
    /// until it has something newer (step `step` done, or the end), so a
    /// refused or killed start-up changes nothing; then it replaces them.
    void
    take_over_output(const unsigned int step);
    /// run() from the set-up to the end of the output, in the solver's
    /// units (run() tells its errors in the scene's).
    void
    set_up_and_run(const Start start);
    /// Check the newest checkpoint against the scene; returns its step.
    unsigned int
    open_checkpoint();
    /// The analysis, the end of the output and its status.
    void
    run_analysis();
    /// The static solve, on each mesh of the static cycles.
    void
    run_static();
    void
    run_dynamic();

    /// A new mesh where one is due (the stepper's adapt_mesh()), and the
    /// outputs' points found on it; returns whether it changed.
    bool
    adapt_mesh();
    /// The outputs' point searches on the current mesh.
    void
    find_points_on_new_mesh();
    /// Before the first step of an adaptive dynamic run that does not start
    /// at rest: `Initial refinements` adaptations to the initial
    /// displacement, the initial conditions interpolated anew on each mesh.
    void
    adapt_to_initial_state();
    /// After a step of an adaptive run: a new mesh when one is due, with
    /// the contact status, force balance and factor of the time loop.
    void
    adapt_mesh_if_due();

    /// The steps of run_dynamic(), in their order.
    void
    start_from_initial_state();
    void
    resume_from_checkpoint();
    void
    record(const ActiveSetIteration::Result &iteration);
    void
    write_checkpoint_if_due(const bool is_stopping);
    void
    stop_if_signalled(const int signal);

    /// The whole state of the time loop, bit for bit, in one list for
    /// both directions (a checkpoint of format `version`).
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int version);
    /// The parts as the outputs see them.
    SceneView
    scene_view() const;

    /// How the run ended and what it cost.
    RunSummary
    summary_of_run(const std::string &status) const;
    void
    write_summary(const std::string &status) const;
    bool
    writes_files() const;
  };


  // The accessors, inline: each hands out a part or a result.

  inline void
  Simulator::set_body_force(Function<2> *force)
  {
    parts.loads.set_body_force(force);
  }


  inline const std::vector<HistoryRow> &
  Simulator::history() const
  {
    return outputs.history().rows();
  }


  inline double
  Simulator::static_equilibrium_imbalance() const
  {
    return stepper->static_equilibrium().imbalance;
  }


  inline double
  Simulator::deflection_at(const Point<2> &p) const
  {
    return stepper->deflection_at(p);
  }


  inline FoundationDiagnostics::PressureRange
  Simulator::contact_pressure_range() const
  {
    return stepper->contact_pressure_range();
  }


  inline const LA::MPI::Vector &
  Simulator::solution() const
  {
    return stepper->state().ghosted_u;
  }


  inline int
  Simulator::stopping_signal() const
  {
    return stopped_by_signal;
  }


  inline unsigned int
  Simulator::n_factorizations() const
  {
    return parts.active_set.linear_solver().n_preparations;
  }


  inline const LinearSolver &
  Simulator::linear_solver() const
  {
    return parts.active_set.linear_solver();
  }


  inline const Discretization &
  Simulator::get_discretization() const
  {
    return parts.discretization;
  }


  inline const MindlinPlate &
  Simulator::get_plate() const
  {
    return parts.plate;
  }
} // namespace liftoff
