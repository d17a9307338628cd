#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/output_files.h>
#include <liftoff/scene_input.h>
#include <liftoff/simulator.h>
#include <liftoff/stop_signal.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <tuple>

namespace liftoff
{
  namespace
  {
    std::string
    format_time(const double tau)
    {
      std::ostringstream text;
      text << std::setprecision(8) << tau;
      return text.str();
    }

    // Whether initial fields vanish at every node: a plate at rest.
    bool
    is_at_rest(const Discretization                                  &disc,
               const std::vector<std::unique_ptr<FunctionParser<2>>> &fields)
    {
      LA::MPI::Vector state;
      disc.reinit_vector(state);
      for (const auto &field : fields)
        {
          VectorTools::interpolate(disc.mapping,
                                   disc.dof_handler,
                                   *field,
                                   state);
          if (state.linfty_norm() != 0.0)
            return false;
        }
      return true;
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
  } // namespace

  Simulator::Simulator(const MPI_Comm comm, const bool verbose)
      : mpi_communicator(comm)
      , pcout(std::cout, verbose && Utilities::MPI::this_mpi_process(comm) == 0)
      , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
      , discretization(comm)
      , active_set(discretization, foundation, timer)
  {}


  void
  Simulator::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Analysis");
    prm.declare_entry("Type",
                      "dynamic",
                      Patterns::Selection("dynamic|static"),
                      "dynamic: Newmark time integration to the end time; "
                      "static: equilibrium under the loads at tau = 0.");
    prm.leave_subsection();

    prm.enter_subsection("Initial conditions");
    prm.declare_entry("Displacement",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "w; psi_x; psi_y at tau = 0 as muParser expressions "
                      "in x, y.");
    prm.declare_entry("Velocity",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "Velocities of w; psi_x; psi_y at tau = 0, in x, y.");
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
                      "the files liftoff writes are ever touched.");
    prm.leave_subsection();

    MindlinPlate::declare_parameters(prm);
    Discretization::declare_parameters(prm);
    TensionlessWinklerFoundation::declare_parameters(prm);
    LoadSet::declare_parameters(prm);
    NewmarkIntegrator::declare_parameters(prm);
    ActiveSetIteration::declare_parameters(prm);
    LinearSolver::declare_parameters(prm);
    FieldOutput::declare_parameters(prm);
    TimeHistory::declare_parameters(prm);
    ProfileOutput::declare_parameters(prm);
    Checkpoint::declare_parameters(prm);
  }


  void
  Simulator::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Analysis");
    analysis = (prm.get("Type") == "static" ? Analysis::static_analysis
                                            : Analysis::dynamic_analysis);
    prm.leave_subsection();
    prm.enter_subsection("Initial conditions");
    initial_displacement = prm.get("Displacement");
    initial_velocity     = prm.get("Velocity");
    prm.leave_subsection();
    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    prm.leave_subsection();

    plate.parse_parameters(prm);
    discretization.parse_parameters(prm);
    foundation.parse_parameters(prm);
    loads.parse_parameters(prm);
    newmark.parse_parameters(prm);
    active_set.parse_parameters(prm);
    active_set.linear_solver().parse_parameters(prm);
    field_output.parse_parameters(prm);
    time_history.parse_parameters(prm);
    profile_output.parse_parameters(prm);
    checkpoint.parse_parameters(prm);

    // Initial conditions must parse before anything runs.
    initial_fields.clear();
    for (const auto &[name, text] :
         {std::make_pair("Displacement", initial_displacement),
          std::make_pair("Velocity", initial_velocity)})
      {
        initial_fields.push_back(parse_expression<2>(
          std::string("Initial conditions/") + name, text, 3, "x,y", false));
      }

    if (analysis == Analysis::static_analysis)
      AssertThrow(discretization.has_kinematic_support()
                    || foundation.model
                         != TensionlessWinklerFoundation::Model::none,
                  ExcMessage("Analysis/Type = static: a plate with all edges "
                             "free and Foundation/Model = none has no static "
                             "equilibrium."));

    // Geometry-dependent checks need the mesh; building it writes nothing,
    // but what it and the solver would allocate is estimated first (the
    // direct solver's factor dominates a large scene).
    discretization.check_memory(active_set.linear_solver().factor_placement());
    discretization.setup(plate);
    if (analysis == Analysis::static_analysis)
      loads.check_against(discretization, 0.0, 0);
    else
      {
        newmark.check_end_time();
        loads.check_against(discretization,
                            newmark.time_step,
                            newmark.n_steps());
      }
    time_history.check_against(discretization);
    profile_output.check_against(discretization);

    // Nothing to compute: most likely a load whose Magnitude was left at its
    // default 0.
    if (loads.is_empty())
      AssertThrow(analysis == Analysis::dynamic_analysis
                    && !is_at_rest(discretization, initial_fields),
                  ExcMessage(
                    "The scene has no load (every Loads/.../Magnitude is 0)"
                    + std::string(analysis == Analysis::dynamic_analysis
                                    ? " and starts at rest (Initial "
                                      "conditions are 0)"
                                    : "")
                    + ", so its solution is u = 0. Give a load a "
                      "Magnitude"
                    + (analysis == Analysis::dynamic_analysis
                         ? ", or the plate an initial displacement or "
                           "velocity."
                         : ".")));

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
    time_history.flush();
    profile_output.flush();
    field_output.write_record(output_directory, mpi_communicator);
    output_folder->remove_fields_after(step);
  }


  void
  Simulator::setup()
  {
    {
      TimerOutput::Scope t(timer, "assembly");
      matrices.assemble(discretization, plate);
    }
    TimerOutput::Scope t(timer, "setup");
    foundation.setup(discretization);
    loads.setup(discretization);
    for (auto *vector : {&u, &v, &a})
      discretization.reinit_vector(*vector);
    discretization.reinit_ghosted_vector(ghosted_u);
    discretization.reinit_ghosted_vector(ghosted_v);
  }


  void
  Simulator::check_before_run()
  {
    if (analysis == Analysis::static_analysis)
      return;
    // The initial fields are evaluated at the nodes only now; a nan there
    // (sqrt(x) on x < 0) would otherwise surface as a nan history.
    set_initial_state();
    for (const auto &[name, text, state] :
         {std::make_tuple("Displacement", &initial_displacement, &u),
          std::make_tuple("Velocity", &initial_velocity, &v)})
      AssertThrow(is_finite(*state),
                  ExcMessage(std::string("Initial conditions/") + name + " = <"
                             + *text
                             + "> is not a finite number at every node of "
                               "the plate."));

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
        + "): the run would blow up. Use a smaller Time "
          "step or Beta >= Gamma/2 (e.g. 0.25 and 0.5)."));
  }


  double
  Simulator::stable_time_step()
  {
    if (largest_eigenvalue == 0)
      {
        TimerOutput::Scope t(timer, "stability limit");
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
    pcout << "liftoff: " << discretization.triangulation.n_global_active_cells()
          << " cells, " << discretization.dof_handler.n_dofs() << " dofs (Q"
          << discretization.degree() << "), "
          << Utilities::MPI::n_mpi_processes(mpi_communicator) << " rank(s)"
          << std::endl;
    // Checks that need the matrices come before the folder is touched.
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
      {
        // Everything is checked before a file is touched: a refused resume
        // leaves the output of the earlier run as it was.
        resume_step =
          checkpoint.open(output_directory, mpi_communicator, scene);
        AssertThrow(resume_step <= newmark.n_steps(),
                    ExcMessage("Cannot resume: the checkpoint is of step "
                               + std::to_string(resume_step)
                               + ", beyond Time integration/End time = "
                               + format_time(newmark.end_time) + " ("
                               + std::to_string(newmark.n_steps())
                               + " steps)."));
        // A killed run may have left temporary files (and checkpoint.new,
        // which the next checkpoint replaces).
        output_folder->remove_temporary_files();
      }
    has_taken_over_output = (start != Start::resume);
    time_history.setup(discretization, output_directory);
    profile_output.setup(discretization, output_directory);
    try
      {
        if (analysis == Analysis::static_analysis)
          run_static();
        else
          run_dynamic();
        if (!has_taken_over_output)
          take_over_output(resume_step);
        time_history.flush();
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
            attempt([&]() { time_history.flush(); });
            attempt([&]() {
              write_summary(stopped_by_signal != 0 ? "interrupted" : "failed");
            });
          }
        throw;
      }
    write_summary("completed");
  }


  void
  Simulator::set_initial_state()
  {
    LA::MPI::Vector *state[2] = {&u, &v};
    for (unsigned int k = 0; k < 2; ++k)
      {
        VectorTools::interpolate(discretization.mapping,
                                 discretization.dof_handler,
                                 *initial_fields[k],
                                 *state[k]);
        discretization.constraints.distribute(*state[k]);
      }
    ghosted_u = u;
    ghosted_v = v;
  }


  EnergyBalance
  Simulator::energies(const double work) const
  {
    EnergyBalance e;
    const double  copies = discretization.n_symmetry_copies();
    if (time_history.wants_energies())
      {
        LA::MPI::Vector product(u);
        matrices.mass.vmult(product, v);
        e.kinetic = 0.5 * copies * (v * product);
        matrices.stiffness.vmult(product, u);
        e.strain     = 0.5 * copies * (u * product);
        e.foundation = copies * foundation.energy(ghosted_u);
      }
    e.work = work;
    return e;
  }


  void
  Simulator::record_step(const unsigned int                step,
                         const double                      tau,
                         const bool                        is_last_step,
                         const ActiveSetIteration::Result &iteration,
                         const EnergyBalance              &energy,
                         const EnergyBalance              &initial)
  {
    TimerOutput::Scope t(timer, "output");
    const double       contact = foundation.contact_area_fraction();
    records.push_back({tau,
                       iteration.iterations,
                       iteration.cycle_length,
                       contact,
                       time_history.probe_values(ghosted_u),
                       energy});
    time_history.record(tau,
                        records.back().probe_w,
                        contact,
                        iteration.iterations,
                        iteration.cycle_length,
                        energy,
                        initial);
    // A static analysis (no time step) writes its one profile.
    profile_output.write_if_due(tau,
                                analysis == Analysis::static_analysis
                                  ? 0.0
                                  : newmark.time_step,
                                ghosted_u);
    if (writes_files() && field_output.is_due(step, is_last_step))
      {
        // The velocity with ghosts only for the files that show it.
        ghosted_v = v;
        field_output.write(output_directory,
                           discretization,
                           foundation,
                           ghosted_u,
                           ghosted_v,
                           tau,
                           step);
      }
    if (!has_taken_over_output)
      take_over_output(step);
  }


  void
  Simulator::run_static()
  {
    const bool needs_contact    = !discretization.has_kinematic_support();
    active_set.requires_contact = needs_contact;
    foundation.activate_all();
    active_set.set_base_matrix(matrices.stiffness);

    LA::MPI::Vector load;
    discretization.reinit_vector(load);
    assemble_loads(0, 0.0, load);

    const auto result = active_set.solve(load, u, ghosted_u);
    require_finite(0, 0.0, "the static solution", {&u}, {}, [&]() {
      return cause_of_non_finite_state(load);
    });
    // The one "step" of a static analysis is done: a stop request ends the
    // run here, like a dynamic run after a step, with no result written.
    if (const int signal = StopSignal::received(mpi_communicator))
      stop_for_signal(signal,
                      "during the static analysis; no result was written.");
    AssertThrow(!result.lost_contact,
                ExcMessage("Static analysis: the plate lifts off the "
                           "foundation everywhere (or keeps too little "
                           "contact to be held) and has no support, so it "
                           "has no static equilibrium under these loads. "
                           "Use a dynamic analysis or support an edge."));
    AssertThrow(result.converged,
                ExcMessage("Static analysis: the active set "
                           + unsettled(result, active_set.max_iterations)
                           + (result.cycle_length > 0
                                ? " (Active set/Cycle rule = stop)."
                                : " (Active set/Maximum iterations).")));
    // A very soft foundation under a plate with free edges leaves the
    // rigid-body motion held by Gamma alone: the system is regular, its
    // residual small, and its answer still round-off. Measure, don't trust.
    const double change = active_set.refinement_change(u, load);
    AssertThrow(change <= 1e-3,
                ExcMessage("Static analysis: the solution is not accurate to "
                           "0.1 %: one step of iterative refinement changes "
                           "it by "
                           + format_time(change)
                           + " (relative). The system is too ill-conditioned "
                             "for double precision, typically a very small "
                             "Foundation/Stiffness under a thin plate "
                             "(Plate/Thickness ratio) with free edges; use "
                             "a stiffer foundation, support an edge or run a "
                             "dynamic analysis."));
    const EnergyBalance none;
    EnergyBalance       e = energies(0.0);
    // Loads applied proportionally: the response is positively homogeneous
    // (max(w, 0) is), so their work is 1/2 F.u (Clapeyron) even with
    // lift-off, and the balance column checks it.
    e.work = 0.5 * discretization.n_symmetry_copies() * (load * u);
    require_finite(0, 0.0, "an energy", {}, e.values(), [&]() {
      return cause_of_non_finite_state(load);
    });
    record_step(0, 0.0, true, result, e, none);
    pcout << "static: " << result.iterations << " active-set iterations, "
          << "contact fraction " << foundation.contact_area_fraction()
          << std::endl;
  }


  void
  Simulator::run_dynamic()
  {
    const double       dt      = newmark.time_step;
    const unsigned int n_steps = newmark.n_steps();
    const double       copies  = discretization.n_symmetry_copies();

    LA::MPI::Vector load, next_load, rhs, history_term, u_new, balance,
      increment;
    for (auto *vector :
         {&load, &next_load, &rhs, &history_term, &u_new, &balance, &increment})
      discretization.reinit_vector(*vector);
    // Generalized-alpha weighs in the previous state's force balance.
    const double previous_weight = newmark.previous_state_weight();

    double work = 0;
    if (writes_files())
      active_set.prepare_for_checkpoints();

    if (resume_step == 0)
      {
        // Initial acceleration from M a0 = F(0) - (K + K_f(u0)) u0, with
        // the contact set of u0.
        // check_before_run() set the initial state.
        assemble_loads(0, 0.0, load);
        TimerOutput::Scope t(timer, "initial acceleration");
        foundation.update_contact_status(ghosted_u);
        force_balance(load, balance);
        matrices.solve_with_mass(a, balance);
        discretization.constraints.distribute(a);
        require_finite(0, 0.0, "the initial acceleration", {&a}, {}, [&]() {
          return cause_of_non_finite_state(load);
        });
        // The first iterate is the bilateral problem.
        foundation.activate_all();
      }
    {
      // The effective matrix without the foundation is needed only to
      // build the system matrix.
      LA::MPI::SparseMatrix base;
      discretization.reinit_matrix(base);
      base.copy_from(matrices.stiffness);
      base.add(newmark.mass_factor(), matrices.mass);
      if (resume_step == 0)
        active_set.set_base_matrix(base);
      else
        read_checkpoint(base, load, balance, work);
    }
    if (resume_step == 0)
      {
        const EnergyBalance e = energies(0.0);
        require_finite(0, 0.0, "an energy", {}, e.values(), [&]() {
          return cause_of_non_finite_state(load);
        });
        record_step(0, 0.0, n_steps == 0, {}, e, e);
      }
    const EnergyBalance initial = records.front().energies;

    for (unsigned int step = resume_step + 1; step <= n_steps; ++step)
      {
        const double tau = step * dt;
        {
          TimerOutput::Scope t(timer, "right hand side");
          assemble_loads(step, tau, next_load);
          newmark.history_term(u, v, a, history_term);
          matrices.mass.vmult(rhs, history_term);
          rhs += next_load;
          if (previous_weight != 0)
            rhs.add(previous_weight, balance);
        }
        newmark.predict(u, v, a, u_new);
        // The first step starts from the bilateral set: the predictor has
        // no motion yet to extrapolate.
        const auto result = active_set.solve(rhs, u_new, ghosted_u, step > 1);
        // Before the convergence test: a nan makes the contact set wander.
        require_finite(step, tau, "the solution", {&u_new}, {}, [&]() {
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

        // Trapezoidal work of the loads, exact for Newmark's average
        // acceleration rule on linear problems.
        increment = u_new;
        increment -= u;
        load += next_load;
        work += 0.5 * copies * (increment * load);
        load = next_load;

        newmark.advance(u_new, u, v, a);
        if (previous_weight != 0)
          {
            TimerOutput::Scope t(timer, "right hand side");
            force_balance(load, balance);
          }

        const EnergyBalance e = energies(work);
        require_finite(step,
                       tau,
                       "the velocity, acceleration or an energy",
                       {&v, &a},
                       e.values(),
                       [&]() { return cause_of_non_finite_state(load); });
        record_step(step, tau, step == n_steps, result, e, initial);

        const int signal = StopSignal::received(mpi_communicator);
        if (writes_files()
            && (signal != 0
                || checkpoint.is_due(step, step == n_steps, mpi_communicator)))
          write_checkpoint(step, load, balance, work);
        if (signal != 0)
          stop_for_signal(signal,
                          "after step " + std::to_string(step)
                            + " (tau = " + format_time(tau)
                            + "); the files written so far are complete"
                            + (writes_files()
                                 ? " and `liftoff --resume` continues from "
                                   "the checkpoint of this step."
                                 : "."));
      }
  }


  void
  Simulator::write_checkpoint(const unsigned int     step,
                              const LA::MPI::Vector &load,
                              const LA::MPI::Vector &balance,
                              const double           work)
  {
    TimerOutput::Scope t(timer, "checkpoint");
    // The time loop's whole state, bit for bit: the next step's right-hand
    // side needs u, v, a (and the load and force balance of this step), its
    // active-set iteration starts from the contact status and the matrix
    // and factor as they are. The rows written so far go with them.
    checkpoint.write(output_directory,
                     mpi_communicator,
                     step,
                     scene,
                     [&](OutputArchive &archive) {
                       archive << work << records;
                       for (const LA::MPI::Vector *vector :
                            std::initializer_list<const LA::MPI::Vector *>{
                              &u, &v, &a, &load, &balance})
                         save_vector(archive, *vector);
                       foundation.save(archive);
                       active_set.save(archive);
                       field_output.save(archive);
                       profile_output.save(archive);
                     });
  }


  void
  Simulator::read_checkpoint(const LA::MPI::SparseMatrix &base,
                             LA::MPI::Vector             &load,
                             LA::MPI::Vector             &balance,
                             double                      &work)
  {
    TimerOutput::Scope t(timer, "checkpoint");
    checkpoint.read(mpi_communicator, [&](InputArchive &archive) {
      archive >> work >> records;
      for (auto *vector : {&u, &v, &a, &load, &balance})
        load_vector(archive, *vector);
      foundation.load(archive);
      active_set.load(archive, base);
      field_output.load(archive);
      profile_output.load(archive);
    });
    AssertThrow(records.size() == resume_step + 1,
                ExcMessage("The checkpoint of step "
                           + std::to_string(resume_step) + " holds "
                           + std::to_string(records.size()) + " steps."));
    ghosted_u = u;
    ghosted_v = v;
    // history.csv is a function of the records: its rows are recorded again
    // as they were, and those of steps after the checkpoint are gone once
    // the file is rewritten (take_over_output()).
    time_history.hold();
    for (const auto &r : records)
      time_history.record(r.tau,
                          r.probe_w,
                          r.contact_fraction,
                          r.iterations,
                          r.cycle_length,
                          r.energies,
                          records.front().energies);
    pcout << "resumed after step " << resume_step << std::endl;
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
                           LA::MPI::Vector       &balance) const
  {
    matrices.stiffness.vmult(balance, u);
    foundation.add_reaction(ghosted_u, balance);
    balance.sadd(-1.0, 1.0, load);
  }


  void
  Simulator::write_summary(const std::string &status) const
  {
    unsigned int total = 0, largest = 0, n = 0, cycles = 0;
    for (const auto &r : records)
      if (r.iterations > 0)
        {
          total += r.iterations;
          largest = std::max(largest, r.iterations);
          ++n;
          cycles += (r.cycle_length > 0);
        }
    const LinearSolver            &solver = active_set.linear_solver();
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const double peak_memory_mb =
      Utilities::MPI::max(memory.VmHWM / 1024.0, mpi_communicator);

    std::ostringstream text;
    text << "status: " << status << '\n';
    if (resume_step > 0)
      text << "resumed after step: " << resume_step
           << " (solver counts and times below are since then)\n";
    text << "analysis: "
         << (analysis == Analysis::static_analysis ? "static" : "dynamic")
         << '\n'
         << "ranks: " << Utilities::MPI::n_mpi_processes(mpi_communicator)
         << '\n'
         << "cells: " << discretization.triangulation.n_global_active_cells()
         << '\n'
         << "degree: " << discretization.degree() << '\n'
         << "dofs: " << discretization.dof_handler.n_dofs() << '\n'
         << "steps: " << (records.empty() ? 0 : records.size() - 1) << '\n'
         << "active-set iterations per step, mean: "
         << (n > 0 ? double(total) / n : 0.0) << '\n'
         << "active-set iterations per step, max: " << largest << '\n'
         << "steps whose active set cycled: " << cycles << '\n'
         << "factorisations: " << solver.n_preparations << '\n'
         << "factor: " << solver.factor_name() << '\n'
         << "substitutions: " << solver.n_substitutions << '\n'
         << "time per substitution [s]: "
         << (solver.n_substitutions > 0
               ? solver.substitution_timer.wall_time() / solver.n_substitutions
               : 0.0)
         << '\n'
         << "CG iterations: " << solver.n_cg_iterations << '\n'
         << "peak memory per rank, max [MB]: " << peak_memory_mb << '\n';

    const auto timings =
      timer.get_summary_data(TimerOutput::OutputData::total_wall_time);
    text << "wall time [s]: " << wall_clock.wall_time() << '\n'
         << "wall time by section [s]:\n";
    for (const auto &[section, seconds] : timings)
      text << "  " << section << ": " << seconds << '\n';

    pcout << text.str();
    if (writes_files())
      collective_attempt(mpi_communicator, "", [&]() {
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          write_file_atomically(output_directory + "/summary.txt",
                                [&](std::ostream &out) { out << text.str(); });
      });
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
    return Utilities::MPI::sum(probe.local_value(ghosted_u), mpi_communicator);
  }


  const std::vector<Simulator::StepRecord> &
  Simulator::history() const
  {
    return records;
  }


  const LA::MPI::Vector &
  Simulator::solution() const
  {
    return ghosted_u;
  }


  int
  Simulator::stopping_signal() const
  {
    return stopped_by_signal;
  }


  unsigned int
  Simulator::n_factorisations() const
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
