#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <liftoff/base/section_timer.h>

#include <liftoff/contact/active_set_iteration.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/initial_conditions.h>
#include <liftoff/fem/load_set.h>
#include <liftoff/fem/mesh_refinement.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_matrices.h>
#include <liftoff/output/field_output.h>
#include <liftoff/output/output.h>
#include <liftoff/output/profile_output.h>
#include <liftoff/output/progress_line.h>
#include <liftoff/output/time_history.h>
#include <liftoff/run/checkpoint.h>
#include <liftoff/run/output_directory.h>
#include <liftoff/time/energy_check.h>
#include <liftoff/time/newmark_integrator.h>
#include <liftoff/time/plate_state.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * One scene from start to end: reads the parameters of every part, checks
   * them against each other, builds the discretisation and runs the static
   * analysis or the Newmark time loop with the active-set iteration in every
   * step, writing what the scene asks for. Tests drive it the same way the
   * executable does and read the results it keeps.
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

    /// `Analysis/Type`.
    enum class Analysis
    {
      static_analysis,
      dynamic_analysis
    };

    /// With verbose = false nothing is printed (tests); show_progress =
    /// false leaves out the progress line only (`liftoff --quiet`).
    explicit Simulator(const MPI_Comm comm,
                       const bool     verbose       = true,
                       const bool     show_progress = true);

    static void
    declare_parameters(ParameterHandler &prm);
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
    const std::vector<TimeHistory::Row> &
    history() const;
    const LA::MPI::Vector &
    solution() const;
    /// The foundation pressure Gamma (w - g) + c v at the Gauss points of
    /// the state (collective; see
    /// FoundationDiagnostics::pressure_range()).
    FoundationDiagnostics::PressureRange
    contact_pressure_range() const;
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

  private:
    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    /// `liftoff --quiet`: no progress line and the summary only in
    /// summary.txt, one line on the terminal.
    const bool   is_quiet;
    SectionTimer timer;
    Timer        wall_clock;

    MindlinPlate                 plate;
    Discretization               discretization;
    PlateMatrices                matrices;
    TensionlessWinklerFoundation foundation;
    LoadSet                      loads;
    NewmarkIntegrator            newmark;
    EnergyCheck                  energy_check;
    MeshRefinement               mesh_refinement;
    ActiveSetIteration           active_set;
    TimeHistory                  time_history;
    ProfileOutput                profile_output;
    FieldOutput                  field_output;
    ProgressLine                 progress_line;
    /// What is written after each step, in this order.
    std::vector<Output *> outputs;
    Checkpoint            checkpoint;

    Analysis    analysis          = Analysis::dynamic_analysis;
    int         stopped_by_signal = 0;
    std::string output_directory;
    /// The scene as Checkpoint compares it, and the step resumed from.
    std::string  scene;
    unsigned int resume_step = 0;
    /// The parameters as used_parameters.prm records them.
    std::string used_parameters;
    /// The output directory, locked while run() runs.
    std::unique_ptr<OutputDirectory> output_folder;
    /// False while a resumed run has not yet replaced the files of the run
    /// it continues (see take_over_output()).
    bool              has_taken_over_output = true;
    InitialConditions initial_conditions;

    PlateState state;
    /// The next step's load, right-hand side and solution, and scratch.
    LA::MPI::Vector next_load, rhs, u_next, scratch, scratch_2;
    /// With dashpots: their force c int_S v phi at the state, and a
    /// ghosted vector to evaluate velocities at the Gauss points.
    LA::MPI::Vector dashpot_force, ghosted_scratch;
    /// omega_max^2 of M^-1 (K + K_f) with every spring in contact (an
    /// estimate from below), once it was needed; 0 before (and after the
    /// mesh changed).
    double largest_eigenvalue = 0;
    /// New meshes of an adaptive run, and the largest change of the total
    /// energy (kinetic + strain + foundation) a transfer caused, relative
    /// to the energy before it.
    unsigned int n_adaptations       = 0;
    double       largest_energy_jump = 0;
    /// The mesh was due to adapt after the last step, which skips it: a
    /// checkpoint of that step keeps this, and a resume that goes further
    /// adapts before its first step, as a run without the stop did.
    bool adaptation_pending = false;

    /// The checks across parts that need no mesh (and a warning about
    /// profile times a run does not reach).
    void
    check_scene() const;
    /// Mesh, matrices, foundation, loads and state vectors, and the checks
    /// that need the mesh; writes nothing.
    void
    setup();
    std::unique_ptr<OutputDirectory>
    prepare_output_directory(const Start start) const;
    /// What can be refused only once the matrices exist, before any file is
    /// written: non-finite initial conditions, a time step beyond the
    /// stability limit of a conditionally stable scheme.
    void
    check_before_run();
    /// The largest stable time step of the scheme (infinite if it is
    /// unconditionally stable).
    double
    stable_time_step();
    /// Refuse a time step beyond the stability limit of a conditionally
    /// stable scheme on the current mesh.
    void
    check_time_step();
    /// The loads at tau; a non-finite entry stops the run naming the load.
    void
    assemble_loads(const unsigned int step,
                   const double       tau,
                   LA::MPI::Vector   &load);
    /// One rule for every value a step produces: if any entry of `vectors`
    /// or any of `numbers` is not finite on any rank, stop the run with a
    /// message naming the step, tau, `what` and cause() (collective).
    void
    require_finite(const unsigned int                          step,
                   const double                                tau,
                   const std::string                          &what,
                   const std::vector<const LA::MPI::Vector *> &vectors,
                   const std::vector<double>                  &numbers,
                   const std::function<std::string()>         &cause);
    /// require_finite() for the state's vectors and energies, whose
    /// non-finite values come from the scheme or an overflow.
    void
    require_finite_state(const std::string                          &what,
                         const std::vector<const LA::MPI::Vector *> &vectors,
                         const std::vector<double>                  &numbers,
                         const LA::MPI::Vector                      &load);
    /// Why the state may have become non-finite with finite loads: the
    /// stability limit of a conditionally stable scheme, or an overflow.
    std::string
    cause_of_non_finite_state(const LA::MPI::Vector &load);
    /// Whether the energy balance is checked: a dynamic run, the check
    /// on, and a scheme for which the balance is a law.
    bool
    checks_energy() const;
    /// Stop (Energy check/Mode = fail) or warn once if the balance error
    /// of the state exceeds the check's tolerance.
    void
    check_energy_balance();
    /// What makes the energy balance fail in the scene at hand: a time
    /// step long for the bed, a loose solver tolerance, or else the
    /// parameters' extremes.
    std::string
    likely_cause_of_energy_error() const;
    /// What makes a static system too ill-conditioned to solve: a plate
    /// that can turn about its only supported edge, very long cells, or a
    /// very soft bed under free edges.
    std::string
    likely_cause_of_ill_conditioning() const;
    /// The energy check's warning, for the summary ("" if none).
    std::string energy_warning;
    /// End the run as interrupted by `signal` (the exit code is 128 +
    /// signal); `when` completes the message.
    [[noreturn]] void
    stop_for_signal(const int signal, const std::string &when);
    void
    write_used_parameters() const;
    /// A resumed run leaves every file of the run it continues as it is
    /// until it has something newer (step `step` done, or the end), so a
    /// refused or killed start-up changes nothing; then it replaces them.
    void
    take_over_output(const unsigned int step);
    /// Check the newest checkpoint against the scene; returns its step.
    unsigned int
    open_checkpoint();
    /// The analysis, the end of the output and its status.
    void
    run_analysis();
    void
    run_static();
    /// One static solve on the current mesh, with its checks.
    ActiveSetIteration::Result
    solve_static();
    void
    run_dynamic();
    /// The static equilibrium K u + R_f(u) = load into state.u with the
    /// active set, refused (naming `what`) if it does not exist or is not
    /// accurate; `during` names it in the message of a stop request.
    /// Leaves the active set's base matrix at K.
    ActiveSetIteration::Result
    solve_static(const LA::MPI::Vector &load,
                 const std::string     &what,
                 const std::string     &during);
    /// state.u += the static equilibrium under the permanent loads, from
    /// which a time integration starts.
    void
    settle_under_permanent_loads();
    /// The bed's pressure at the state's velocity (for the contact rule
    /// and the force balance at a given state).
    SpringPressure
    pressure_at_state_velocity();
    /// dashpot_force = c int_S v phi of the state.
    void
    compute_dashpot_force();

    /// Mark cells and, if the mesh changes, move u, v and a to the new mesh
    /// and rebuild what depends on it; returns whether it changed.
    bool
    adapt_mesh();
    /// Matrices, foundation points, loads, vector layouts and the outputs'
    /// point searches on the current mesh; u, v and a are kept.
    void
    rebuild_on_new_mesh();
    /// The state's contact status, load (at `step`, `tau`) and force
    /// balance, with dashpots as at the end of a step, and the
    /// acceleration of the equation of motion M a = balance: at the start,
    /// and on a new mesh, where the interpolated acceleration is in balance
    /// with nothing (`what` names it in an error).
    void
    equilibrate(const unsigned int step,
                const double       tau,
                const std::string &what);
    /// Before the first step of an adaptive dynamic run that does not start
    /// at rest: `Initial refinements` adaptations to the initial
    /// displacement, the initial conditions interpolated anew on each mesh.
    void
    adapt_to_initial_state();
    /// After a step of an adaptive run: a new mesh when one is due, with
    /// the contact status, force balance and factor of the time loop.
    void
    adapt_mesh_if_due();
    /// The state's energies, whether or not the history writes them
    /// (collective).
    EnergyBalance
    state_energies();

    /// The steps of run_dynamic(), in their order.
    void
    start_from_initial_state();
    void
    resume_from_checkpoint();
    void
    assemble_right_hand_side(const unsigned int step);
    ActiveSetIteration::Result
    solve_contact_problem(const unsigned int step);
    void
    advance(const unsigned int step);
    void
    record(const ActiveSetIteration::Result &iteration);
    void
    write_checkpoint_if_due(const bool is_stopping);
    void
    stop_if_signalled(const int signal);

    /// K + c M, the effective matrix without the foundation, for
    /// ActiveSetIteration to write into its system matrix.
    ActiveSetIteration::BaseMatrix
    effective_base_matrix() const;
    /// The whole state of the time loop, bit for bit, in one list for
    /// both directions (a checkpoint of format `version`).
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int version);
    /// The state's energies (zero unless the history writes them).
    EnergyBalance
    energies();
    /// F - K u - K_f(S) u + f_g(S) for the current state u and contact set
    /// S (f_g: the springs' push on a gap, for `pressure`).
    void
    force_balance(const LA::MPI::Vector &load,
                  const SpringPressure  &pressure,
                  LA::MPI::Vector       &balance) const;
    void
    write_summary(const std::string &status) const;
    bool
    writes_files() const;
  };
} // namespace liftoff
