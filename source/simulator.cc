#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/output_files.h>
#include <liftoff/simulator.h>
#include <liftoff/stop_signal.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <numeric>
#include <sstream>

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
                      "write no files.");
    prm.leave_subsection();

    MindlinPlate::declare_parameters(prm);
    Discretization::declare_parameters(prm);
    PlateMatrices::declare_parameters(prm);
    TensionlessWinklerFoundation::declare_parameters(prm);
    LoadSet::declare_parameters(prm);
    NewmarkIntegrator::declare_parameters(prm);
    ActiveSetIteration::declare_parameters(prm);
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
    matrices.parse_parameters(prm);
    foundation.parse_parameters(prm);
    loads.parse_parameters(prm);
    newmark.parse_parameters(prm);
    active_set.parse_parameters(prm);
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
        auto f = std::make_unique<FunctionParser<2>>(3);
        try
          {
            f->initialize("x,y", text, {{"pi", M_PI}});
            Vector<double> values(3);
            f->vector_value(Point<2>(), values);
          }
        catch (const std::exception &e)
          {
            AssertThrow(false,
                        ExcMessage(std::string("Initial conditions/") + name
                                   + " = <" + text
                                   + "> must be three muParser expressions in "
                                     "x, y separated by ';': "
                                   + e.what()));
          }
        initial_fields.push_back(std::move(f));
      }

    if (analysis == Analysis::static_analysis)
      AssertThrow(discretization.has_kinematic_support()
                    || foundation.model
                         != TensionlessWinklerFoundation::Model::none,
                  ExcMessage("Analysis/Type = static: a plate with all edges "
                             "free and Foundation/Model = none has no static "
                             "equilibrium."));

    // Geometry-dependent checks need the mesh; building it writes nothing.
    discretization.setup(plate);
    loads.check_against(discretization);
    time_history.check_against(discretization);
    profile_output.check_against(discretization);
  }


  bool
  Simulator::writes_files() const
  {
    return !output_directory.empty();
  }


  void
  Simulator::prepare_output_directory(const ParameterHandler &prm) const
  {
    if (!writes_files())
      return;
    // Rank 0 creates the folder; every rank learns whether it could, so all
    // stop together.
    std::string error;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      try
        {
          std::filesystem::create_directories(output_directory);
          write_file_atomically(
            output_directory + "/used_parameters.prm", [&](std::ostream &out) {
              prm.print_parameters(out, ParameterHandler::ShortPRM);
            });
        }
      catch (const std::exception &e)
        {
          error = message_of(e);
        }
    error = Utilities::MPI::broadcast(mpi_communicator, error, 0);
    AssertThrow(error.empty(),
                ExcMessage("Output/Directory = " + output_directory
                           + " cannot be written: " + error));
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
    time_history.setup(discretization, output_directory);
    profile_output.setup(discretization, output_directory);
  }


  void
  Simulator::run(const ParameterHandler &prm, const bool resume)
  {
    wall_clock.restart();
    scene       = Checkpoint::comparable_scene(prm);
    resume_step = 0;
    if (resume)
      {
        // Everything is checked before a file is touched: a refused resume
        // leaves the output of the earlier run as it was.
        AssertThrow(analysis == Analysis::dynamic_analysis,
                    ExcMessage("--resume continues a time integration; "
                               "Analysis/Type = static has none."));
        AssertThrow(writes_files(),
                    ExcMessage("--resume reads the checkpoint in "
                               "Output/Directory, which is empty."));
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
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          remove_temporary_files(output_directory);
      }
    prepare_output_directory(prm);
    pcout << "liftoff: " << discretization.triangulation.n_global_active_cells()
          << " cells, " << discretization.dof_handler.n_dofs() << " dofs (Q"
          << discretization.degree() << "), "
          << Utilities::MPI::n_mpi_processes(mpi_communicator) << " rank(s)"
          << std::endl;
    setup();
    try
      {
        if (analysis == Analysis::static_analysis)
          run_static();
        else
          run_dynamic();
      }
    catch (...)
      {
        // Keep the rows computed so far and say how the run ended. The
        // original error is the one to report: a second one while writing
        // (a full disk) is dropped.
        const auto attempt = [](const std::function<void()> &write) {
          try
            {
              write();
            }
          catch (...)
            {}
        };
        attempt([&]() { time_history.flush(); });
        attempt([&]() {
          write_summary(stopped_by_signal != 0 ? "interrupted" : "failed");
        });
        throw;
      }
    time_history.flush();
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
    loads.assemble(0.0, load);

    const auto result = active_set.solve(load, u, ghosted_u);
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
    const EnergyBalance none;
    EnergyBalance       e = energies(0.0);
    // Loads applied proportionally: the response is positively homogeneous
    // (max(w, 0) is), so their work is 1/2 F.u (Clapeyron) even with
    // lift-off, and the balance column checks it.
    e.work = 0.5 * discretization.n_symmetry_copies() * (load * u);
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
        set_initial_state();
        loads.assemble(0.0, load);
        TimerOutput::Scope t(timer, "initial acceleration");
        foundation.update_contact_status(ghosted_u);
        force_balance(load, balance);
        matrices.solve_with_mass(a, balance);
        discretization.constraints.distribute(a);
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
        record_step(0, 0.0, n_steps == 0, {}, e, e);
      }
    const EnergyBalance initial = records.front().energies;

    for (unsigned int step = resume_step + 1; step <= n_steps; ++step)
      {
        const double tau = step * dt;
        {
          TimerOutput::Scope t(timer, "right hand side");
          loads.assemble(tau, next_load);
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

        record_step(
          step, tau, step == n_steps, result, energies(work), initial);

        const int signal = StopSignal::received(mpi_communicator);
        if (writes_files()
            && (signal != 0
                || checkpoint.is_due(step, step == n_steps, mpi_communicator)))
          write_checkpoint(step, load, balance, work);
        if (signal != 0)
          {
            stopped_by_signal = signal;
            AssertThrow(false,
                        ExcMessage("Interrupted by signal "
                                   + std::to_string(signal) + " after step "
                                   + std::to_string(step)
                                   + " (tau = " + format_time(tau)
                                   + "); the files written so far are "
                                     "complete"
                                   + (writes_files()
                                        ? " and `liftoff --resume` continues "
                                          "from the checkpoint of this step."
                                        : ".")));
          }
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
      field_output.load(archive, output_directory, mpi_communicator);
      profile_output.load(archive);
    });
    AssertThrow(records.size() == resume_step + 1,
                ExcMessage("The checkpoint of step "
                           + std::to_string(resume_step) + " holds "
                           + std::to_string(records.size()) + " steps."));
    ghosted_u = u;
    ghosted_v = v;
    // history.csv is a function of the records: its rows are written again
    // as they were, and those of steps after the checkpoint are gone.
    for (const auto &r : records)
      time_history.record(r.tau,
                          r.probe_w,
                          r.contact_fraction,
                          r.iterations,
                          r.cycle_length,
                          r.energies,
                          records.front().energies);
    time_history.flush();
    pcout << "resumed after step " << resume_step << std::endl;
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
    if (writes_files()
        && Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      write_file_atomically(output_directory + "/summary.txt",
                            [&](std::ostream &out) { out << text.str(); });
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
