#pragma once

#include <liftoff/base/archive_types.h>
#include <liftoff/base/linear_algebra.h>
#include <liftoff/base/section_timer.h>
#include <liftoff/contact/active_set_iteration.h>
#include <liftoff/contact/bed.h>
#include <liftoff/time/energy_balance.h>
#include <liftoff/time/newmark_integrator.h>
#include <liftoff/time/plate_state.h>
#include <liftoff/time/static_equilibrium.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class Discretization;
  class EnergyCheck;
  class InitialConditions;
  class LoadSet;
  class MeshRefinement;
  class MindlinPlate;
  class PlateMatrices;

  /**
   * The numerics of a run, apart from the main loop that decides when they
   * happen (Simulator), as step-69 keeps TimeStepping apart from MainLoop:
   * the static solve, the equilibrium at the start and on a new mesh, the
   * Newmark step with its contact problem and dashpots, and every check of
   * what they produce (finiteness, stability limit, energy balance). It
   * owns the state and the vectors of the step; the physical parts are the
   * Simulator's, which reads and checks their parameters, and are held
   * here by reference for the life of a run, as step-69's TimeStepping
   * holds OfflineData.
   */
  class TimeStepper
  {
  public:
    /// The parts of the scene the numerics work on, set up by the
    /// Simulator from its parameters.
    struct Parts
    {
      const MindlinPlate &plate;
      Discretization     &discretization;
      PlateMatrices      &matrices;
      /// The terms of the plate's system, the plate first
      /// (SceneParts::system_terms()); the bed is one of them (Bed::of()).
      std::vector<SystemTerm *> terms;
      LoadSet                  &loads;
      const NewmarkIntegrator  &newmark;
      EnergyCheck              &energy_check;
      const MeshRefinement     &mesh_refinement;
      ActiveSetIteration       &active_set;
    };

    /// What the scene asks of the numerics beyond its parts.
    struct Options
    {
      /// Analysis/Type = dynamic: decides the likely causes of a failure
      /// and whether the energy balance is a law.
      bool is_dynamic;
      /// The history writes the energies, so every state's are computed.
      bool records_energies;
      /// The scene's clock at step 0 (a static analysis: the default).
      Clock clock;
      /// A warning's text in the scene's units (PhysicalUnits'
      /// in_scene_terms()); none: as the solver writes it.
      std::function<std::string(const std::string &)> in_scene_terms;
    };

    /// Called once a static solve is done, to end the run there if a stop
    /// was requested; `when` completes the message.
    using StopCheck = std::function<void(const std::string &when)>;

    TimeStepper(const Parts   &parts,
                const Options &options,
                SectionTimer  &timer);

    /// Matrices, foundation points, loads and every vector on the current
    /// mesh, the state zero: before a run, and on the mesh a checkpoint is
    /// read into.
    void
    setup();
    /// The state at tau = 0 from `initial_conditions`, interpolated at the
    /// nodes of the current mesh.
    void
    set_initial_state(const InitialConditions &initial_conditions);
    /// Refuse a time step beyond the stability limit of a conditionally
    /// stable scheme on the current mesh.
    void
    check_time_step();

    /// Mark cells and, if the mesh changes, move u, v and a to the new mesh
    /// and rebuild what depends on it; returns whether it changed. For a
    /// state that the caller sets anew (initial refinements) or solves
    /// again (static cycles).
    bool
    adapt_mesh();
    /// adapt_mesh() within the time loop: on a new mesh also the contact
    /// status, load and force balance at the new Gauss points, an
    /// acceleration in balance with them, the system matrix and its
    /// factor, and the time step's stability. Returns the change of the
    /// stored energy (kinetic + strain + foundation) the transfer caused,
    /// relative to the energy before it, if the mesh changed.
    std::optional<double>
    adapt_mesh_in_time_loop();

    /// The static equilibrium under the loads at tau = 0 on the current
    /// mesh, with its checks, the work of the loads and the energies.
    ActiveSetIteration::Result
    solve_static_analysis(const StopCheck &stop_if_requested);
    /// From the initial state: the equilibrium under the permanent loads,
    /// the initial acceleration and energies, and the system matrix of the
    /// time steps.
    void
    start_time_integration(const StopCheck &stop_if_requested);
    /// Step `step` of the time loop: right-hand side, contact problem and
    /// the update of (u, v, a), with the checks of the new state. With
    /// Time step control = error, the steps of the controller from
    /// tau_at(step - 1) to tau_at(step); their active-set iterations are
    /// summed.
    ActiveSetIteration::Result
    do_step(const unsigned int step);

    const PlateState &
    state() const;
    /// Deflection of the state at a point of the full plate (collective).
    double
    deflection_at(const Point<2> &p) const;
    /// The foundation pressure Gamma (w - g) + c v of the state at the
    /// Gauss points (collective).
    FoundationDiagnostics::PressureRange
    contact_pressure_range() const;
    /// Whether the energy balance is checked: a dynamic run, the check
    /// on, and a scheme for which the balance is a law.
    bool
    checks_energy() const;
    /// The warnings of the mesh's area and of the energy check or the
    /// static equilibrium, one text for the summary ("" if none).
    std::string
    warnings() const;
    /// StaticEquilibrium::check() of the static solution (an imbalance of
    /// -1 where it does not apply or the run is dynamic).
    const StaticEquilibrium::Result &
    static_equilibrium() const;
    /// New meshes of the time loop or the static cycles.
    unsigned int
    n_adaptations() const;
    /// The scene's step control, with the record of the steps taken.
    const StepSizeController &
    step_control() const;

    /// The checkpoint's part of the stepper, in its two places of the
    /// format: the state with the energy check's record, and the contact
    /// status with the system matrix and factor. Both directions.
    template <class Archive>
    void
    serialize_state(Archive &archive);
    template <class Archive>
    void
    serialize_contact(Archive &archive);

  private:
    const MindlinPlate             &plate;
    Discretization                 &discretization;
    PlateMatrices                  &matrices;
    const std::vector<SystemTerm *> terms;
    /// The term the plate rests on, in its role.
    Bed     &bed;
    LoadSet &loads;
    /// The scene's scheme, and the one of the step being taken (its time
    /// step the controller's).
    const NewmarkIntegrator &scene_newmark;
    NewmarkIntegrator        newmark;
    EnergyCheck             &energy_check;
    const MeshRefinement    &mesh_refinement;
    ActiveSetIteration      &active_set;
    /// A copy of the scene's: it keeps the level and counts of the run.
    StepSizeController controller;
    const Options      options;
    SectionTimer      &timer;

    PlateState state_;
    /// The next step's load, right-hand side and solution, and scratch.
    LA::MPI::Vector next_load, rhs, u_next, scratch, scratch_2;
    /// With dashpots: their force c int_S v phi at the state, and a
    /// ghosted vector to evaluate velocities at the Gauss points.
    LA::MPI::Vector dissipative_force, ghosted_scratch;
    /// omega_max^2 of M^-1 (K + K_f) with every spring in contact (an
    /// estimate from below), once it was needed; 0 before (and after the
    /// mesh changed).
    double       largest_eigenvalue = 0;
    unsigned int n_new_meshes       = 0;
    /// Whether the next step starts the time integration: its first
    /// iterate is the bilateral problem, set up by the step itself so that
    /// the record of the initial state (tau = 0) reads that state's own
    /// contact set.
    bool first_step_pending = false;
    /// The controller's level whose time step `newmark` and the system
    /// matrix have.
    unsigned int level_in_use = 0;
    /// The locally owned entries of w, where the error is measured.
    IndexSet    w_entries;
    std::string warning;
    /// The mesh's area check, apart: a later warning must not hide it.
    std::string mesh_warning;
    /// A static analysis whose rest state has no equilibrium.
    std::string               rest_warning;
    StaticEquilibrium::Result equilibrium;

    /// `message` in the scene's units into `kept` (one of the warnings
    /// above), and on std::cerr.
    void
    warn(std::string &kept, const std::string &message) const;

    /// Matrices, foundation points, loads and the layout of every vector
    /// on the current mesh; u, v and a are kept unless `keep_motion` is
    /// false. The one list of what a mesh change rebuilds.
    void
    build_on_current_mesh(const bool keep_motion);
    /// The plate at rest is the current state (tau = 0 of a time
    /// integration, or the static equilibrium of solve_rest_state()).
    void
    set_rest_state();
    /// In a static analysis of a jointed plate: the equilibrium under the
    /// weight and the temperature loads alone, as the rest state.
    void
    solve_rest_state();

    /// The largest stable time step of the scheme (infinite if it is
    /// unconditionally stable).
    double
    stable_time_step();
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
    /// Stop (Energy check/Mode = fail) or warn once if the balance error
    /// of the state exceeds the check's tolerance.
    void
    check_energy_balance();
    /// What makes the energy balance fail in the scene at hand: a time
    /// step long for the bed, a loose solver tolerance, or else the
    /// parameters' extremes.
    std::string
    likely_cause_of_energy_error() const;
    void
    check_static_equilibrium(const LA::MPI::Vector &load);
    /// What makes a static system too ill-conditioned to solve: a plate
    /// that can turn about its only supported edge, very long cells, or a
    /// very soft bed under free edges.
    std::string
    likely_cause_of_ill_conditioning() const;
    /// The slab of a jointed plate that touches the bed least, if it
    /// touches it over less than 10 % of its area, as a likely cause: a
    /// slab the joints hold too little tips about its edge (empty if none;
    /// a free joint with the load 1e-3 from it: 3.5 %).
    std::string
    slab_barely_in_contact() const;

    /// The static equilibrium K u + R_f(u) = load into state.u with the
    /// active set, refused (naming `what`) if it does not exist or is not
    /// accurate; `during` names it in the message of a stop request, and
    /// `remedy` is the advice for a plate that lifts off everywhere.
    /// Leaves the active set's base matrix at K.
    ActiveSetIteration::Result
    solve_static(const LA::MPI::Vector &load,
                 const std::string     &what,
                 const std::string     &during,
                 const std::string     &remedy,
                 const StopCheck       &stop_if_requested);
    /// Refuse a static solution that does not exist or is not accurate.
    void
    check_static_solution(const ActiveSetIteration::Result &result,
                          const ActiveSetIteration::System &system,
                          const std::string                &what,
                          const std::string                &remedy);
    /// state.u += the static equilibrium under the permanent loads, from
    /// which a time integration starts.
    void
    settle_under_permanent_loads(const StopCheck &stop_if_requested);
    /// The state's contact status, load (at `step`, `tau`) and force
    /// balance, with dashpots as at the end of a step, and the
    /// acceleration of the equation of motion M a = balance: at the start,
    /// and on a new mesh, where the interpolated acceleration is in balance
    /// with nothing (`what` names it in an error).
    void
    equilibrate(const unsigned int step,
                const double       tau,
                const std::string &what);
    /// Give the bed its pressure at the state's velocity (for the contact
    /// rule and the force balance at a given state).
    void
    use_pressure_at_state_velocity();
    /// dissipative_force = c int_S v phi of the state, plus the springs'
    /// force the foundation energy does not hold
    /// (Bed::add_dissipative_force()).
    void
    compute_dissipative_force();
    /// The system matrix of the time steps from the bilateral set.
    void
    use_time_step_matrix();

    /// Kinetic + strain + foundation energy of the state (collective).
    double
    stored_energy();

    /// do_step() with Time step control = error.
    ActiveSetIteration::Result
    do_controlled_steps(const unsigned int step);
    /// Give `newmark` and the system matrix the time step of `level`.
    void
    use_level(const unsigned int level);
    /// The scene's scheme with the time step of `level`.
    NewmarkIntegrator
    scheme_of_level(const unsigned int level) const;
    /// The relative local error of the solved step in u_next
    /// (StepSizeController::relative_error(), collective).
    double
    relative_step_error();

    /// The parts of do_step(), in their order; `tau` the time of the new
    /// state. `from_prediction`: the iteration may start from the
    /// predictor's set (not the first step).
    void
    assemble_right_hand_side(const unsigned int step, const double tau);
    ActiveSetIteration::Result
    solve_contact_problem(const unsigned int step,
                          const double       tau,
                          const bool         from_prediction);
    void
    advance(const unsigned int step);
    /// The dashpots' work over the step just taken (advance()).
    void
    add_dissipated_energy();

    /// The sum of the matrices of the terms without a status (K + c M,
    /// with `factors` = {c, kappa}), for ActiveSetIteration to write into
    /// its system matrix; the terms with a status it adds itself.
    ActiveSetIteration::BaseMatrix
    base_matrix(const MatrixFactors &factors) const;
    /// base_matrix() of a time step: {mass_factor(), velocity_factor()}.
    ActiveSetIteration::BaseMatrix
    effective_base_matrix() const;
    /// The state's energies, whether or not the history writes them
    /// (collective).
    EnergyBalance
    state_energies();
    /// The state's energies where the history writes them or the balance
    /// is checked (else zero but for the work and dissipation).
    EnergyBalance
    energies();
    /// F - K u - K_f(S) u + f_g(S) for the current state u and contact set
    /// S (f_g: the springs' push on a gap, for the pressure the bed uses):
    /// the load less every term's force. `scratch` is overwritten.
    void
    force_balance(const LA::MPI::Vector &load, LA::MPI::Vector &balance);
  };
} // namespace liftoff
