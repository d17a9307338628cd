#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/base/output_files.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/run/simulator.h>
#include <liftoff/run/stop_signal.h>
#include <liftoff/version.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>

namespace liftoff
{
  namespace
  {
    using Analysis                     = Simulator::Analysis;
    const Selection<Analysis> analyses = {
      {"dynamic", Analysis::dynamic_analysis},
      {"static", Analysis::static_analysis}};

    // The name of an adaptive run's mesh in its checkpoint folder.
    const std::string mesh_file = "mesh";

    std::string
    format_time(const double tau)
    {
      std::ostringstream text;
      text << std::setprecision(8) << tau;
      return text.str();
    }

    // Why an active-set iteration did not settle, for error messages.
    std::string
    unsettled(const ActiveSetIteration::Result &result,
              const unsigned int                max_iterations)
    {
      if (result.cycle_length > 0)
        return "went round a cycle of " + std::to_string(result.cycle_length)
               + " sets";
      return "did not settle in " + std::to_string(max_iterations)
             + " iterations";
    }

    /// "a; or b; or c.": the likely causes of a failure, most likely first.
    std::string
    as_alternatives(const std::vector<std::string> &causes)
    {
      std::string text;
      for (const auto &cause : causes)
        text += (text.empty() ? "" : "; or ") + cause;
      return text + ".";
    }
  } // namespace

  Simulator::Simulator(const MPI_Comm comm,
                       const bool     verbose,
                       const bool     show_progress)
      : mpi_communicator(comm)
      , pcout(std::cout, verbose && Utilities::MPI::this_mpi_process(comm) == 0)
      , is_quiet(!show_progress)
      , discretization(comm)
      , active_set(discretization, foundation, timer)
      , progress_line(comm, std::cout)
  {
    outputs = {&time_history, &profile_output, &field_output};
    if (verbose && show_progress)
      outputs.push_back(&progress_line);
  }


  void
  Simulator::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Analysis");
    prm.declare_entry("Type",
                      "dynamic",
                      analyses.pattern(),
                      "dynamic: Newmark time integration to the end time; "
                      "static: equilibrium under the loads at tau = 0.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::Anything(),
                      "Folder for all results (created if needed). Empty: "
                      "write no files. A run owns it while it runs (a second "
                      "run into it is refused) and refuses it if it holds an "
                      "earlier run's results, unless started with `liftoff "
                      "--overwrite`, which removes them, or `--resume`. Only "
                      "the files liftoff writes are ever touched. `#` "
                      "starts a comment in a parameter file, so a name "
                      "cannot hold it: `run#3` is read as `run`.");
    TimeHistory::declare_parameters(prm);
    ProfileOutput::declare_parameters(prm);
    FieldOutput::declare_parameters(prm);
    prm.leave_subsection();

    InitialConditions::declare_parameters(prm);
    MindlinPlate::declare_parameters(prm);
    Discretization::declare_parameters(prm);
    MeshRefinement::declare_parameters(prm);
    TensionlessWinklerFoundation::declare_parameters(prm);
    LoadSet::declare_parameters(prm);
    NewmarkIntegrator::declare_parameters(prm);
    EnergyCheck::declare_parameters(prm);
    ActiveSetIteration::declare_parameters(prm);
    LinearSolver::declare_parameters(prm);
    Checkpoint::declare_parameters(prm);
  }


  void
  Simulator::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Analysis");
    analysis = analyses.parse(prm.get("Type"), "Analysis/Type");
    prm.leave_subsection();
    initial_conditions.parse_parameters(prm);
    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    time_history.parse_parameters(prm);
    profile_output.parse_parameters(prm);
    field_output.parse_parameters(prm);
    prm.leave_subsection();

    plate.parse_parameters(prm);
    discretization.parse_parameters(prm, plate);
    mesh_refinement.parse_parameters(prm);
    foundation.parse_parameters(prm);
    loads.parse_parameters(prm);
    newmark.parse_parameters(prm);
    energy_check.parse_parameters(prm);
    time_history.show_dissipated_energy(foundation.has_damping());
    active_set.parse_parameters(prm);
    active_set.linear_solver().parse_parameters(prm);
    checkpoint.parse_parameters(prm);

    check_scene();
  }


  void
  Simulator::check_scene() const
  {
    if (analysis == Analysis::static_analysis)
      AssertThrow(discretization.has_kinematic_support()
                    || foundation.law().model() != ContactLaw::Model::none,
                  ExcMessage("Analysis/Type = static: a plate with all edges "
                             "free and Foundation/Model = none has no static "
                             "equilibrium."));

    if (analysis == Analysis::dynamic_analysis)
      newmark.check_end_time();
    mesh_refinement.check_against(discretization);
    time_history.check_against(discretization);
    profile_output.check_against(discretization);

    // A shortened run (a try, or a resume to a later end) may skip
    // profiles; say so rather than drop them unnoticed.
    if (analysis == Analysis::dynamic_analysis)
      {
        const auto late =
          profile_output.times_not_reached(newmark.end_time, newmark.time_step);
        if (!late.empty()
            && Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          {
            std::cerr << "liftoff: warning: Output/Profile times";
            for (const double tau : late)
              std::cerr << ' ' << format_time(tau);
            std::cerr << " lie beyond Time integration/End time = "
                      << format_time(newmark.end_time)
                      << "; no profile is written for them." << std::endl;
          }
      }
  }


  bool
  Simulator::writes_files() const
  {
    return !output_directory.empty();
  }


  std::unique_ptr<OutputDirectory>
  Simulator::prepare_output_directory(const Start start) const
  {
    if (!writes_files())
      return nullptr;
    // A resume needs the folder of its checkpoint and creates none.
    auto folder = std::make_unique<OutputDirectory>(output_directory,
                                                    mpi_communicator,
                                                    start != Start::resume);
    if (start == Start::fresh)
      folder->refuse_earlier_results();
    else if (start == Start::overwrite)
      folder->remove_earlier_results();
    if (start != Start::resume)
      write_used_parameters();
    return folder;
  }


  void
  Simulator::write_used_parameters() const
  {
    collective_attempt(
      mpi_communicator,
      "Output/Directory = " + output_directory + " cannot be written",
      [&]() {
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          write_file_atomically(output_directory + "/used_parameters.prm",
                                [&](std::ostream &out) {
                                  out << used_parameters;
                                });
      });
  }


  void
  Simulator::take_over_output(const unsigned int step)
  {
    has_taken_over_output = true;
    // The old summary goes first: a run killed in between leaves none,
    // as any run that has not ended does. The field files of later steps
    // go last, once the PVD no longer lists them.
    output_folder->remove_summary();
    write_used_parameters();
    for (Output *output : outputs)
      output->flush();
    output_folder->remove_fields_after(step);
  }


  void
  Simulator::setup()
  {
    // The direct solver's factor dominates a large scene: what it and the
    // mesh would allocate is estimated before anything is built.
    discretization.check_memory(active_set.linear_solver().factor_placement());
    discretization.setup();
    mesh_refinement.refine_around_points(
      discretization, loads.point_load_positions(discretization));
    if (analysis == Analysis::static_analysis)
      loads.check_against(discretization, 0.0, 0);
    else
      loads.check_against(discretization, newmark.time_step, newmark.n_steps());

    {
      SectionTimer::Scope t(timer, "setup");
      foundation.setup(discretization);
    }
    // Nothing to compute: most likely a load whose Magnitude was left at its
    // default 0.
    if (loads.is_empty() && !foundation.law().is_pressing_plate())
      AssertThrow(analysis == Analysis::dynamic_analysis
                    && !initial_conditions.is_at_rest(discretization),
                  ExcMessage(
                    "The scene has no load (every Loads/.../Magnitude is 0)"
                    + std::string(analysis == Analysis::dynamic_analysis
                                    ? " and starts at rest (Initial "
                                      "conditions are 0)"
                                    : "")
                    + " on a bed that presses nowhere (Foundation/Initial "
                      "gap >= 0), so its solution is u = 0. Give a load a "
                      "Magnitude"
                    + (analysis == Analysis::dynamic_analysis
                         ? ", or the plate an initial displacement or "
                           "velocity."
                         : ".")));

    pcout << "liftoff: " << discretization.triangulation.n_global_active_cells()
          << " cells, " << discretization.dof_handler.n_dofs() << " dofs ("
          << discretization.element_name() << "), "
          << Utilities::MPI::n_mpi_processes(mpi_communicator) << " rank(s)"
          << std::endl;
    {
      SectionTimer::Scope t(timer, "assembly");
      matrices.assemble(discretization, plate);
    }
    SectionTimer::Scope t(timer, "setup");
    loads.setup(discretization);
    state.reinit(discretization);
    for (auto *vector :
         {&next_load, &rhs, &u_next, &scratch, &scratch_2, &dashpot_force})
      discretization.reinit_vector(*vector);
    discretization.reinit_ghosted_vector(ghosted_scratch);
  }


  void
  Simulator::check_before_run()
  {
    if (analysis == Analysis::static_analysis)
      return;
    // The initial fields are evaluated at the nodes only now; a nan there
    // (sqrt(x) on x < 0) would otherwise surface as a nan history.
    initial_conditions.interpolate(discretization, state.u, state.v);
    state.ghosted_u = state.u;

    check_time_step();
  }


  void
  Simulator::check_time_step()
  {
    if (!newmark.is_conditionally_stable())
      return;
    const double limit = stable_time_step();
    AssertThrow(
      newmark.time_step <= limit,
      ExcMessage(
        "Time integration/Time step = " + format_time(newmark.time_step)
        + " exceeds the stability limit " + format_time(limit)
        + " of Newmark's method with Beta = " + format_time(newmark.beta)
        + " < Gamma/2 = " + format_time(0.5 * newmark.gamma)
        + " (omega_max^2 of M^-1 (K + K_f) estimated as "
        + format_time(largest_eigenvalue)
        + (n_adaptations > 0
             ? " on the mesh refined at step " + std::to_string(state.step)
             : std::string())
        + "): the run would blow up. Use a smaller Time "
          "step or Beta >= Gamma/2 (e.g. 0.25 and 0.5)"
        + (mesh_refinement.is_enabled()
             ? ", or a smaller Mesh refinement/Maximum level."
             : ".")));
  }


  double
  Simulator::stable_time_step()
  {
    if (largest_eigenvalue == 0)
      {
        SectionTimer::Scope t(timer, "stability limit");
        // Every spring in contact (the status setup() leaves): the stiffest
        // the foundation can make the plate.
        LA::MPI::Vector ghosted;
        discretization.reinit_ghosted_vector(ghosted);
        largest_eigenvalue = matrices.largest_eigenvalue(
          discretization, [&](const LA::MPI::Vector &x, LA::MPI::Vector &y) {
            ghosted = x;
            foundation.add_reaction(ghosted, y);
          });
      }
    return newmark.stable_time_step(largest_eigenvalue);
  }


  void
  Simulator::require_finite(const unsigned int                          step,
                            const double                                tau,
                            const std::string                          &what,
                            const std::vector<const LA::MPI::Vector *> &vectors,
                            const std::vector<double>                  &numbers,
                            const std::function<std::string()>         &cause)
  {
    bool finite = std::all_of(numbers.begin(), numbers.end(), [](double x) {
      return std::isfinite(x);
    });
    for (const auto *vector : vectors)
      finite = finite && has_finite_local_entries(*vector);
    if (Utilities::MPI::min(static_cast<int>(finite), mpi_communicator) == 1)
      return;
    AssertThrow(false,
                ExcMessage("Step " + std::to_string(step)
                           + " (tau = " + format_time(tau) + "): " + what
                           + " is not a finite number. Likely cause: "
                           + cause()));
  }


  void
  Simulator::require_finite_state(
    const std::string                          &what,
    const std::vector<const LA::MPI::Vector *> &vectors,
    const std::vector<double>                  &numbers,
    const LA::MPI::Vector                      &load)
  {
    require_finite(state.step, state.tau, what, vectors, numbers, [&]() {
      return cause_of_non_finite_state(load);
    });
  }


  std::string
  Simulator::cause_of_non_finite_state(const LA::MPI::Vector &load)
  {
    if (newmark.is_conditionally_stable()
        && analysis == Analysis::dynamic_analysis)
      return "Newmark's method with Beta = " + format_time(newmark.beta)
             + " < Gamma/2 = " + format_time(0.5 * newmark.gamma)
             + " is stable only for Time step <= about "
             + format_time(stable_time_step())
             + " (an estimate from below of omega_max); Time integration/Time "
               "step = "
             + format_time(newmark.time_step) + " is too large for it.";
    return "the values overflow the range of double: the largest load "
           "entry is "
           + format_time(load.linfty_norm())
           + "; check Loads/.../Magnitude and the initial conditions.";
  }


  bool
  Simulator::checks_energy() const
  {
    // The balance is a law of the scheme only where the scheme conserves
    // the energy or can only lose it; Beta != 1/4 with Gamma = 1/2
    // conserves another energy (Beta = 1/2 on a quarter plate under a
    // sudden point load: 0.335 of the scale at the first step).
    return analysis == Analysis::dynamic_analysis && energy_check.is_enabled()
           && (newmark.conserves_energy() || newmark.dissipates_energy());
  }


  void
  Simulator::check_energy_balance()
  {
    if (!checks_energy())
      return;
    if (!energy_check.exceeds(state.step,
                              state.energies,
                              state.initial_energies,
                              newmark.dissipates_energy()))
      return;
    const std::string message =
      "Step " + std::to_string(state.step) + " (tau = " + format_time(state.tau)
      + "): " + energy_check.describe_violation()
      + ". Likely cause: " + likely_cause_of_energy_error();
    AssertThrow(energy_check.mode() != EnergyCheck::Mode::fail,
                ExcMessage(message));
    energy_warning = message;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cerr << "liftoff: warning: " << message << std::endl;
  }


  std::string
  Simulator::likely_cause_of_energy_error() const
  {
    std::vector<std::string> causes;
    // The plate on its springs swings at sqrt(Gamma) (unit mass): a step
    // longer than a radian of that swing lets contact switch within it.
    const double omega = foundation.law().rigid_body_frequency();
    if (newmark.time_step * omega > 1)
      causes.push_back(
        "Time integration/Time step = " + format_time(newmark.time_step)
        + " is long for the bed: the plate swings on it at "
          "sqrt(Gamma) = "
        + format_time(omega) + ", so Time step * sqrt(Gamma) = "
        + format_time(newmark.time_step * omega)
        + " > 1; use a Time step below " + format_time(1 / omega));
    const double tolerance = active_set.linear_solver().relative_tolerance();
    if (tolerance > 1e-8)
      causes.push_back("Linear solver/Tolerance = " + format_time(tolerance)
                       + " lets each solve miss its equations by that share; "
                         "use 1e-10 or less");
    if (causes.empty())
      causes.push_back(
        "a parameter near the end of its range (Foundation/Stiffness, Shear "
        "modulus, Damping) or a mesh too coarse for the contact front; "
        "compare a run with half the Time step");
    return as_alternatives(causes);
  }


  std::string
  Simulator::likely_cause_of_ill_conditioning() const
  {
    std::vector<std::string> causes;
    const std::string        edge = discretization.only_supported_edge();
    if (!edge.empty())
      causes.push_back("the plate is held on one edge only (Boundary "
                       "conditions/"
                       + edge
                       + "), about which it can turn: a mechanism that "
                         "only the foundation's contact holds; clamp that "
                         "edge or support another");
    const double elongation = discretization.largest_cell_aspect_ratio();
    if (elongation > 100)
      causes.push_back("the cells are " + format_time(elongation)
                       + " times longer than wide (Plate/Aspect ratio against "
                         "Discretization/Cells along x and y); use cells "
                         "closer to square");
    if (causes.empty())
      causes.push_back(
        "a very small Foundation/Stiffness under a thin plate (Plate/Thickness "
        "ratio) with free edges; use a stiffer foundation, support an edge "
        "or run a dynamic analysis");
    return as_alternatives(causes);
  }


  void
  Simulator::stop_for_signal(const int signal, const std::string &when)
  {
    stopped_by_signal = signal;
    AssertThrow(false,
                ExcMessage("Interrupted by signal " + std::to_string(signal)
                           + " " + when));
  }


  void
  Simulator::run(const ParameterHandler &prm, const Start start)
  {
    wall_clock.restart();
    scene = Checkpoint::comparable_scene(prm);
    std::ostringstream parameters;
    prm.print_parameters(parameters, ParameterHandler::ShortPRM);
    used_parameters = parameters.str();
    resume_step     = 0;
    if (start == Start::resume)
      {
        AssertThrow(analysis == Analysis::dynamic_analysis,
                    ExcMessage("--resume continues a time integration; "
                               "Analysis/Type = static has none."));
        AssertThrow(writes_files(),
                    ExcMessage("--resume reads the checkpoint in "
                               "Output/Directory, which is empty."));
      }
    // Checks that need the mesh and the matrices come before the folder is
    // touched.
    setup();
    check_before_run();

    // The folder is this run's from here until run() returns or throws.
    output_folder = prepare_output_directory(start);
    struct Release
    {
      std::unique_ptr<OutputDirectory> &folder;
      ~Release()
      {
        folder.reset();
      }
    } release{output_folder};

    if (start == Start::resume)
      resume_step = open_checkpoint();
    has_taken_over_output = (start != Start::resume);
    for (Output *output : outputs)
      output->setup(discretization, output_directory);
    // Every point of the scene has found its cell.
    discretization.release_grid_cache();
    run_analysis();
  }


  unsigned int
  Simulator::open_checkpoint()
  {
    // Everything is checked before a file is touched: a refused resume
    // leaves the output of the earlier run as it was.
    const unsigned int step =
      checkpoint.open(output_directory, mpi_communicator, scene);
    AssertThrow(step <= newmark.n_steps(),
                ExcMessage("Cannot resume: the checkpoint is of step "
                           + std::to_string(step)
                           + ", beyond Time integration/End time = "
                           + format_time(newmark.end_time) + " ("
                           + std::to_string(newmark.n_steps()) + " steps)."));
    // A killed run may have left temporary files (and checkpoint.new,
    // which the next checkpoint replaces).
    output_folder->remove_temporary_files();
    return step;
  }


  void
  Simulator::run_analysis()
  {
    try
      {
        if (analysis == Analysis::static_analysis)
          run_static();
        else
          run_dynamic();
        if (!has_taken_over_output)
          take_over_output(resume_step);
        for (Output *output : outputs)
          output->flush();
      }
    catch (...)
      {
        // Keep the rows computed so far and say how the run ended, unless
        // a resumed run has not written anything yet: then the earlier
        // run's files stay as they are. The original error is the one to
        // report: a second one while writing (a full disk) is dropped.
        const auto attempt = [](const std::function<void()> &write) {
          try
            {
              write();
            }
          catch (...)
            {}
        };
        if (has_taken_over_output)
          {
            for (Output *output : outputs)
              attempt([&]() { output->flush(); });
            attempt([&]() {
              write_summary(stopped_by_signal != 0 ? "interrupted" : "failed");
            });
          }
        throw;
      }
    write_summary(energy_warning.empty() ? "completed"
                                         : "completed with warnings");
  }


  EnergyBalance
  Simulator::energies()
  {
    if (!time_history.wants_energies() && !checks_energy())
      return EnergyBalance{0, 0, 0, state.work, state.dissipated};
    return state_energies();
  }


  void
  Simulator::record(const ActiveSetIteration::Result &iteration)
  {
    SectionTimer::Scope t(timer, "output");
    const bool          is_static = analysis == Analysis::static_analysis;
    const StepData      step{state,
                        discretization,
                        foundation,
                        iteration,
                        foundation.diagnostics().contact_area_fraction(),
                        is_static ? 0.0 : newmark.time_step,
                        is_static ? 0 : newmark.n_steps(),
                        is_static || state.step == newmark.n_steps()};
    for (Output *output : outputs)
      output->execute(step);
    if (!has_taken_over_output)
      take_over_output(state.step);
  }


  ActiveSetIteration::Result
  Simulator::solve_static(const LA::MPI::Vector &load,
                          const std::string     &what,
                          const std::string     &during)
  {
    // The plate at rest: the springs' Gamma (w - g), no dashpot force.
    const SpringPressure             pressure = foundation.law().pressure();
    const ActiveSetIteration::System system{
      load, pressure, !discretization.has_kinematic_support()};
    foundation.activate_all();
    active_set.set_base_matrix(
      [this](LA::MPI::SparseMatrix &base) {
        base.copy_from(matrices.stiffness);
      },
      0.0);

    const auto result = active_set.solve(system, state.u, state.ghosted_u);
    require_finite_state("the static solution", {&state.u}, {}, load);
    // The one "step" of a static analysis is done: a stop request ends the
    // run here, like a dynamic run after a step, with no result written.
    if (const int signal = StopSignal::received(mpi_communicator))
      stop_for_signal(signal, "during " + during + "; no result was written.");
    AssertThrow(!result.lost_contact,
                ExcMessage(what
                           + ": the plate lifts off the "
                             "foundation everywhere (or keeps too little "
                             "contact to be held) and has no support, so it "
                             "has no static equilibrium under these loads. "
                           + (analysis == Analysis::dynamic_analysis
                                ? "Give it a foundation (Foundation/Model) "
                                  "or support an edge."
                                : "Use a dynamic analysis or support an "
                                  "edge.")));
    AssertThrow(result.converged,
                ExcMessage(what + ": the active set "
                           + unsettled(result, active_set.max_iterations)
                           + (result.cycle_length > 0
                                ? " (Active set/Cycle rule = stop)."
                                : " (Active set/Maximum iterations).")));
    // A very soft foundation under a plate with free edges leaves the
    // rigid-body motion held by Gamma alone: the system is regular, its
    // residual small, and its answer still round-off. Measure, don't trust.
    const double change = active_set.refinement_change(state.u, system);
    AssertThrow(change <= 1e-3,
                ExcMessage(what
                           + ": the solution is not accurate to "
                             "0.1 %: one step of iterative refinement changes "
                             "it by "
                           + format_time(change)
                           + " (relative). The system is too ill-conditioned "
                             "for double precision. Likely cause: "
                           + likely_cause_of_ill_conditioning()));
    return result;
  }


  void
  Simulator::run_static()
  {
    LA::MPI::Vector &load               = state.load;
    const auto       solve_on_this_mesh = [&]() {
      assemble_loads(0, 0.0, load);
      return solve_static(load, "Static analysis", "the static analysis");
    };
    auto result = solve_on_this_mesh();
    for (unsigned int cycle = 1; cycle <= mesh_refinement.n_static_cycles();
         ++cycle)
      {
        if (!adapt_mesh())
          break;
        result = solve_on_this_mesh();
        pcout << "static cycle " << cycle << ": "
              << discretization.triangulation.n_global_active_cells()
              << " cells, " << discretization.dof_handler.n_dofs() << " dofs, "
              << result.iterations << " active-set iterations" << std::endl;
      }
    // Loads applied proportionally: the response is positively homogeneous
    // (max(w, 0) is), so their work is 1/2 F.u (Clapeyron) even with
    // lift-off, and the balance column checks it against the state at
    // rest. A gap makes the response affine; Clapeyron's identity at the
    // equilibrium then gains the gap's term (gap_work()).
    state.work =
      0.5 * discretization.n_symmetry_copies()
      * (load * state.u + foundation.diagnostics().gap_work(state.ghosted_u));
    state.energies = energies();
    require_finite_state("an energy", {}, state.energies.values(), load);
    record(result);
    pcout << "static: " << result.iterations << " active-set iterations, "
          << "contact fraction "
          << foundation.diagnostics().contact_area_fraction() << std::endl;
  }


  void
  Simulator::settle_under_permanent_loads()
  {
    SectionTimer::Scope t(timer, "permanent loads");
    // The initial displacement is measured from the settled state.
    LA::MPI::Vector initial_displacement = state.u;
    state.u                              = 0;
    loads.assemble_permanent(scratch);
    solve_static(scratch,
                 "The static equilibrium under Loads/Self weight, from "
                 "which the time integration starts",
                 "the static equilibrium under Loads/Self weight");
    state.u += initial_displacement;
    state.ghosted_u = state.u;
  }


  void
  Simulator::run_dynamic()
  {
    if (resume_step == 0)
      start_from_initial_state();
    else
      {
        resume_from_checkpoint();
        if (adaptation_pending)
          adapt_mesh_if_due();
      }

    for (unsigned int step = state.step + 1; step <= newmark.n_steps(); ++step)
      {
        assemble_right_hand_side(step);
        const auto iteration = solve_contact_problem(step);
        advance(step);
        record(iteration);
        adapt_mesh_if_due();
        const int signal = StopSignal::received(mpi_communicator);
        write_checkpoint_if_due(signal != 0);
        stop_if_signalled(signal);
      }
  }


  bool
  Simulator::adapt_mesh()
  {
    {
      SectionTimer::Scope t(timer, "mesh refinement");
      if (!mesh_refinement.mark_cells(
            discretization,
            foundation.diagnostics().contact_fraction_per_cell(),
            loads.point_load_positions(discretization),
            state.ghosted_u))
        return false;
      mesh_refinement.execute(discretization, {&state.u, &state.v, &state.a});
    }
    ++n_adaptations;
    rebuild_on_new_mesh();
    return true;
  }


  void
  Simulator::rebuild_on_new_mesh()
  {
    {
      SectionTimer::Scope t(timer, "assembly");
      matrices.assemble(discretization, plate);
    }
    SectionTimer::Scope t(timer, "setup");
    foundation.setup(discretization);
    loads.setup(discretization);
    for (auto *vector : {&state.load,
                         &state.balance,
                         &next_load,
                         &rhs,
                         &u_next,
                         &scratch,
                         &scratch_2,
                         &dashpot_force})
      discretization.reinit_vector(*vector);
    discretization.reinit_ghosted_vector(state.ghosted_u);
    discretization.reinit_ghosted_vector(ghosted_scratch);
    state.ghosted_u = state.u;
    for (Output *output : outputs)
      output->mesh_changed(discretization);
    discretization.release_grid_cache();
    largest_eigenvalue = 0;
  }


  EnergyBalance
  Simulator::state_energies()
  {
    EnergyBalance e = energies_of(matrices,
                                  foundation,
                                  state.u,
                                  state.ghosted_u,
                                  state.v,
                                  discretization.n_symmetry_copies(),
                                  state.work,
                                  scratch);
    e.dissipated    = state.dissipated;
    return e;
  }


  void
  Simulator::adapt_mesh_if_due()
  {
    if (!mesh_refinement.is_due(state.step))
      return;
    adaptation_pending = (state.step == newmark.n_steps());
    if (adaptation_pending)
      return;
    const auto stored = [this]() {
      const EnergyBalance e = state_energies();
      return e.kinetic + e.strain + e.foundation;
    };
    const double before = stored();
    if (!adapt_mesh())
      return;
    // The state on the new mesh: its contact status at the new Gauss
    // points, the load and force balance there, an acceleration in
    // balance with them, the system matrix and its factor (once per mesh).
    {
      SectionTimer::Scope t(timer, "mesh refinement");
      equilibrate(state.step, state.tau, "the acceleration after a new mesh");
    }
    // The time steps' matrix holds the dashpots too (Gamma + c kappa):
    // kappa is the argument, no longer a setting that the foundation's
    // setup on the new mesh reset to 0 (a damped adaptive run then solved
    // with Gamma alone: balance error 0.38 of the energy scale, issue 31).
    active_set.set_base_matrix(effective_base_matrix(),
                               newmark.velocity_factor());
    check_time_step();
    state.energies      = energies();
    const double after  = stored();
    const double jump   = before > 0 ? (after - before) / before : 0.0;
    largest_energy_jump = std::abs(jump) > std::abs(largest_energy_jump)
                            ? jump
                            : largest_energy_jump;
  }


  void
  Simulator::adapt_to_initial_state()
  {
    if (initial_conditions.is_at_rest(discretization))
      return;
    unsigned int r = 0;
    for (; r < mesh_refinement.n_initial_refinements(); ++r)
      {
        foundation.update_contact_status(state.ghosted_u,
                                         foundation.law().pressure());
        if (!adapt_mesh())
          break;
        // The fields themselves, not their interpolant on the old mesh.
        initial_conditions.interpolate(discretization, state.u, state.v);
        state.ghosted_u = state.u;
      }
    // The stability limit of the final mesh only.
    if (r > 0)
      check_time_step();
  }


  ActiveSetIteration::BaseMatrix
  Simulator::effective_base_matrix() const
  {
    return [this](LA::MPI::SparseMatrix &base) {
      base.copy_from(matrices.stiffness);
      base.add(newmark.mass_factor(), matrices.mass);
    };
  }


  void
  Simulator::equilibrate(const unsigned int step,
                         const double       tau,
                         const std::string &what)
  {
    const SpringPressure pressure = pressure_at_state_velocity();
    foundation.update_contact_status(state.ghosted_u, pressure);
    assemble_loads(step, tau, state.load);
    force_balance(state.load, pressure, state.balance);
    if (foundation.has_damping())
      compute_dashpot_force();
    matrices.solve_with_mass(state.a, state.balance);
    discretization.constraints.distribute(state.a);
    require_finite_state(what, {&state.a}, {}, state.load);
  }


  void
  Simulator::start_from_initial_state()
  {
    // check_before_run() set the initial state. The initial acceleration
    // solves M a0 = F(0) - (K + K_f(u0)) u0 with the contact set of u0.
    adapt_to_initial_state();
    if (loads.has_permanent_loads())
      settle_under_permanent_loads();
    {
      SectionTimer::Scope t(timer, "initial acceleration");
      equilibrate(0, 0.0, "the initial acceleration");
    }
    // The energies with the contact status of the initial state (the shear
    // layer's is taken over it), before the first iterate replaces it.
    state.energies         = energies();
    state.initial_energies = state.energies;
    require_finite_state("an energy", {}, state.energies.values(), state.load);
    // The first iterate is the bilateral problem.
    foundation.activate_all();
    active_set.set_base_matrix(effective_base_matrix(),
                               newmark.velocity_factor());
    record({});
  }


  void
  Simulator::resume_from_checkpoint()
  {
    SectionTimer::Scope t(timer, "checkpoint");
    if (mesh_refinement.is_enabled())
      {
        // The run's mesh is the checkpoint's; everything on it is rebuilt
        // before the state is read into it.
        discretization.load_mesh(checkpoint.folder() + "/" + mesh_file);
        state.reinit(discretization);
        rebuild_on_new_mesh();
      }
    checkpoint.read(mpi_communicator, [&](InputArchive &archive) {
      serialize(archive, Checkpoint::format);
    });
    // The dashpots' force of the saved state, for the next step's
    // dissipation.
    if (foundation.has_damping())
      compute_dashpot_force();
    AssertThrow(state.step == resume_step
                  && time_history.rows().size() == resume_step + 1,
                ExcMessage(
                  "The checkpoint of step " + std::to_string(resume_step)
                  + " holds step " + std::to_string(state.step) + " and "
                  + std::to_string(time_history.rows().size()) + " rows."));
    pcout << "resumed after step " << resume_step << std::endl;
  }


  void
  Simulator::assemble_right_hand_side(const unsigned int step)
  {
    assemble_loads(step, step * newmark.time_step, next_load);
    SectionTimer::Scope t(timer, "right hand side");
    newmark.right_hand_side(matrices.mass,
                            state.u,
                            state.v,
                            state.a,
                            next_load,
                            state.balance,
                            scratch,
                            rhs);
  }


  SpringPressure
  Simulator::pressure_at_state_velocity()
  {
    if (!foundation.has_damping())
      return foundation.law().pressure();
    // At a given state v is given: kappa = 0, o = -v.
    scratch.equ(-1.0, state.v);
    ghosted_scratch = scratch;
    return foundation.law().pressure(0.0, ghosted_scratch);
  }


  void
  Simulator::compute_dashpot_force()
  {
    ghosted_scratch = state.v;
    dashpot_force   = 0;
    foundation.add_dashpot_force(ghosted_scratch, dashpot_force);
  }


  ActiveSetIteration::Result
  Simulator::solve_contact_problem(const unsigned int step)
  {
    SpringPressure pressure = foundation.law().pressure();
    if (foundation.has_damping())
      {
        // In the step v_{n+1} = kappa u_{n+1} - o_n: the dashpots' pressure
        // is affine in the new displacement, like a spring on a gap.
        newmark.velocity_offset(state.u, state.v, state.a, scratch);
        ghosted_scratch = scratch;
        pressure =
          foundation.law().pressure(newmark.velocity_factor(), ghosted_scratch);
      }
    newmark.predict(state.u, state.v, state.a, u_next);
    // The first step starts from the bilateral set: the predictor has no
    // motion yet to extrapolate.
    const auto result =
      active_set.solve({rhs, pressure}, u_next, state.ghosted_u, step > 1);
    // Before the convergence test: a nan makes the contact set wander.
    const double tau = step * newmark.time_step;
    require_finite(step, tau, "the solution", {&u_next}, {}, [&]() {
      return cause_of_non_finite_state(next_load);
    });
    AssertThrow(result.converged,
                ExcMessage("The active set "
                           + unsettled(result, active_set.max_iterations)
                           + " at step " + std::to_string(step)
                           + " (tau = " + format_time(tau)
                           + (result.cycle_length > 0
                                ? "); Active set/Cycle rule = stop asks "
                                  "for this error; union resolves it."
                                : "); raise Active set/Maximum iterations "
                                  "or reduce Time integration/Time "
                                  "step.")));
    return result;
  }


  void
  Simulator::advance(const unsigned int step)
  {
    state.work += work_of_step(state.u,
                               u_next,
                               state.load,
                               next_load,
                               discretization.n_symmetry_copies(),
                               scratch,
                               scratch_2);
    copy_values(next_load, state.load);
    newmark.advance(u_next, state.u, state.v, state.a);
    state.step = step;
    state.tau  = step * newmark.time_step;
    if (foundation.has_damping())
      {
        // The dashpots' work over the step by the trapezoidal rule, as the
        // loads': 1/2 (u_{n+1} - u_n).(f_n + f_{n+1}); `scratch` still
        // holds u_{n+1} - u_n from work_of_step().
        LA::MPI::Vector &previous_force = scratch_2;
        previous_force                  = dashpot_force;
        compute_dashpot_force();
        previous_force += dashpot_force;
        state.dissipated +=
          0.5 * discretization.n_symmetry_copies() * (scratch * previous_force);
      }
    if (newmark.needs_force_balance())
      {
        SectionTimer::Scope t(timer, "right hand side");
        force_balance(state.load, pressure_at_state_velocity(), state.balance);
      }
    state.energies = energies();
    require_finite_state("the velocity, acceleration or an energy",
                         {&state.v, &state.a},
                         state.energies.values(),
                         state.load);
    check_energy_balance();
  }


  void
  Simulator::write_checkpoint_if_due(const bool is_stopping)
  {
    if (!writes_files()
        || !(is_stopping
             || checkpoint.is_due(state.step,
                                  state.step == newmark.n_steps(),
                                  mpi_communicator)))
      return;
    SectionTimer::Scope t(timer, "checkpoint");
    // An adaptive run's mesh cannot be rebuilt from the scene.
    Checkpoint::SharedFiles save_mesh;
    if (mesh_refinement.is_enabled())
      save_mesh = [&](const std::string &folder) {
        discretization.triangulation.save(folder + "/" + mesh_file);
        // deal.II writes "mesh", "mesh.info" and, with cell data, more.
        std::vector<std::string> names;
        for (const auto &entry : std::filesystem::directory_iterator(folder))
          if (entry.path().filename().string().rfind(mesh_file, 0) == 0)
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
      };
    checkpoint.write(
      output_directory,
      mpi_communicator,
      state.step,
      scene,
      [&](OutputArchive &archive) { serialize(archive, Checkpoint::format); },
      save_mesh);
  }


  void
  Simulator::stop_if_signalled(const int signal)
  {
    if (signal != 0)
      stop_for_signal(signal,
                      "after step " + std::to_string(state.step)
                        + " (tau = " + format_time(state.tau)
                        + "); the files written so far are complete"
                        + (writes_files() ? " and `liftoff --resume` continues "
                                            "from the checkpoint of this step."
                                          : "."));
  }


  template <class Archive>
  void
  Simulator::serialize(Archive &archive, const unsigned int version)
  {
    // The time loop's whole state, bit for bit: the next step's right-hand
    // side needs the state, its active-set iteration starts from the
    // contact status and the matrix and factor as they are; the outputs
    // keep what they have written.
    archive &state;
    archive &energy_check;
    archive &adaptation_pending;
    transfer(archive, foundation);
    if constexpr (Archive::is_loading::value)
      active_set.load(archive,
                      effective_base_matrix(),
                      newmark.velocity_factor());
    else
      active_set.save(archive);
    for (Output *output : outputs)
      transfer(archive, *output);
    (void)version;
  }


  void
  Simulator::assemble_loads(const unsigned int step,
                            const double       tau,
                            LA::MPI::Vector   &load)
  {
    loads.assemble(tau, load);
    require_finite(step, tau, "the load vector", {&load}, {}, [&]() {
      return loads.non_finite_load(tau);
    });
  }


  void
  Simulator::force_balance(const LA::MPI::Vector &load,
                           const SpringPressure  &pressure,
                           LA::MPI::Vector       &balance) const
  {
    matrices.stiffness.vmult(balance, state.u);
    foundation.add_reaction(state.ghosted_u, balance);
    balance.sadd(-1.0, 1.0, load);
    if (foundation.has_gap())
      foundation.add_gap_load(pressure, balance);
  }


  void
  Simulator::write_summary(const std::string &status) const
  {
    const auto         &rows       = time_history.rows();
    const auto          iterations = time_history.iteration_statistics();
    const LinearSolver &solver     = active_set.linear_solver();
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const double peak_memory_mb =
      Utilities::MPI::max(memory.VmHWM / 1024.0, mpi_communicator);

    RunSummary summary;
    summary.add("status", status);
    if (!energy_warning.empty())
      summary.add("warning", energy_warning);
    summary.add("liftoff",
                std::string(LIFTOFF_VERSION) + " (git " + LIFTOFF_GIT_COMMIT
                  + ")");
    if (resume_step > 0)
      summary.add("resumed after step", double(resume_step));
    summary.add("analysis",
                analysis == Analysis::static_analysis ? "static" : "dynamic");
    summary.add("ranks",
                double(Utilities::MPI::n_mpi_processes(mpi_communicator)));
    summary.add("cells",
                double(discretization.triangulation.n_global_active_cells()));
    summary.add("degree", double(discretization.degree()));
    summary.add("element", discretization.element_name());
    summary.add("dofs", double(discretization.dof_handler.n_dofs()));
    if (mesh_refinement.is_enabled())
      {
        summary.add("mesh adaptations", double(n_adaptations));
        summary.add("largest relative energy change of a transfer",
                    largest_energy_jump);
      }
    summary.add("steps", double(rows.empty() ? 0 : rows.size() - 1));
    if (analysis == Analysis::dynamic_analysis && energy_check.is_enabled()
        && !checks_energy())
      summary.add("energy balance",
                  "not checked: Time integration/Beta = "
                    + format_time(newmark.beta)
                    + " with Gamma = 1/2 conserves a modified energy");
    if (checks_energy())
      {
        summary.add("energy balance error, largest share of the energy scale",
                    energy_check.largest_relative_error());
        summary.add("energy balance error, its step",
                    double(energy_check.step_of_largest_error()));
      }
    summary.add("active-set iterations per step, mean", iterations.mean);
    summary.add("active-set iterations per step, max", double(iterations.max));
    summary.add("steps whose active set cycled", double(iterations.n_cycled));
    summary.add("factorisations", double(solver.n_preparations));
    summary.add("factor", solver.factor_name());
    summary.add("substitutions", double(solver.n_substitutions));
    summary.add("time per substitution [s]",
                solver.n_substitutions > 0
                  ? solver.substitution_timer.wall_time()
                      / solver.n_substitutions
                  : 0.0);
    summary.add("CG iterations", double(solver.n_cg_iterations));
    summary.add("CG products with the whole matrix", double(solver.n_products));
    summary.add("CG solutions that failed the residual check",
                double(solver.n_failed_checks));
    summary.add("peak memory per rank, max [MB]", peak_memory_mb);
    summary.add("wall time [s]", wall_clock.wall_time());
    RunSummary::Section sections;
    for (const auto &[section, seconds] : timer.wall_times())
      sections.emplace_back(section, seconds);
    summary.add("wall time by section [s]", sections);

    if (is_quiet)
      pcout << "status: " << status
            << (writes_files()
                  ? "; summary in " + output_directory + "/summary.txt"
                  : std::string())
            << std::endl;
    else
      pcout << summary.text();
    if (writes_files())
      {
        if (output_folder)
          output_folder->release_space_for_summary();
        summary.write(output_directory, mpi_communicator);
      }
  }


  void
  Simulator::set_body_force(Function<2> *force)
  {
    loads.set_body_force(force);
  }


  double
  Simulator::deflection_at(const Point<2> &p) const
  {
    const PointFunctional probe(discretization,
                                discretization.to_modelled_part(p));
    return Utilities::MPI::sum(probe.local_value(state.ghosted_u),
                               mpi_communicator);
  }


  const std::vector<TimeHistory::Row> &
  Simulator::history() const
  {
    return time_history.rows();
  }


  const LA::MPI::Vector &
  Simulator::solution() const
  {
    return state.ghosted_u;
  }


  FoundationDiagnostics::PressureRange
  Simulator::contact_pressure_range() const
  {
    LA::MPI::Vector v;
    discretization.reinit_ghosted_vector(v);
    v = state.v;
    return foundation.diagnostics().pressure_range(state.ghosted_u, v);
  }


  int
  Simulator::stopping_signal() const
  {
    return stopped_by_signal;
  }


  unsigned int
  Simulator::n_factorizations() const
  {
    return active_set.linear_solver().n_preparations;
  }


  const LinearSolver &
  Simulator::linear_solver() const
  {
    return active_set.linear_solver();
  }


  const Discretization &
  Simulator::get_discretization() const
  {
    return discretization;
  }
} // namespace liftoff
