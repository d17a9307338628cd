#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/number_text.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/run/simulator.h>
#include <liftoff/run/stop_signal.h>
#include <liftoff/version.h>

#include <cmath>
#include <functional>
#include <sstream>

namespace liftoff
{
  Simulator::Simulator(const MPI_Comm comm,
                       const bool     verbose,
                       const bool     show_progress)
      : mpi_communicator(comm)
      , pcout(std::cout,
              verbose && show_progress
                && Utilities::MPI::this_mpi_process(comm) == 0)
      , status_out(std::cout,
                   verbose && !show_progress
                     && Utilities::MPI::this_mpi_process(comm) == 0)
      , parts(comm, timer)
      , progress_line(comm, std::cout)
  {
    if (verbose && show_progress)
      outputs.push_back(&progress_line);
  }


  void
  Simulator::declare_parameters(ParameterHandler &prm)
  {
    SceneParts::declare_parameters(prm);
    prm.enter_subsection("Output");
    OutputDirectory::declare_parameters(prm);
    TimeHistory::declare_parameters(prm);
    ProfileOutput::declare_parameters(prm);
    JointProfiles::declare_parameters(prm);
    JointProbes::declare_parameters(prm);
    FieldOutput::declare_parameters(prm);
    Envelopes::declare_parameters(prm);
    prm.leave_subsection();
    Checkpoint::declare_parameters(prm);
    PhysicalUnits::declare_parameters(prm);
  }


  void
  Simulator::parse_parameters(ParameterHandler &prm)
  {
    units.parse_parameters(prm, SceneParts::outline_for_units(prm));
    ParameterHandler &scene = units.solver_scene(prm, declare_parameters);
    units.explain_errors_of([&]() {
      parts.parse_parameters(scene, units);
      scene.enter_subsection("Output");
      output_directory = scene.get("Directory");
      time_history.parse_parameters(scene, parts.plate);
      profile_output.parse_parameters(scene);
      const PlateGeometry &geometry = parts.discretization.geometry();
      joint_probes.parse_parameters(scene, geometry, parts.plate);
      joint_profiles.parse_parameters(scene, geometry);
      field_output.parse_parameters(scene, parts.plate, parts.joint_dowels);
      envelopes.parse_parameters(scene);
      scene.leave_subsection();
      deflectometer_sensors.parse_parameters(scene);
      if (time_history.drop_default_probe_off(geometry))
        pcout << "liftoff: no probe: 0, 0 lies in the annulus's hole.\n";
      time_history.show_dissipated_energy(parts.foundation.law().has_damping());
      const auto load_positions = [this](const double tau) {
        return parts.loads.moving_load_positions(tau);
      };
      time_history.follow(parts.loads.moving_load_names(), load_positions);
      profile_output.follow(parts.loads.moving_load_names(), load_positions);
      for (Output *output : outputs)
        output->write_in_units_of(units);
      for (const Output *output : outputs)
        output->add_columns_to(time_history);
      if (parts.newmark.step_control.is_enabled())
        time_history.add_step_sizes(
          [this]() { return stepper->step_control().interval_columns(); });
      checkpoint.parse_parameters(scene);
      check_scene();
    });
  }


  void
  Simulator::check_scene() const
  {
    parts.check();
    time_history.check_against(parts.discretization);
    profile_output.check_against(parts.discretization);
    envelopes.check_against(parts.mesh_refinement);
    deflectometer_sensors.check_against(parts.discretization);
    if (parts.is_dynamic())
      profile_output.warn_of_times_not_reached(parts.clock().end_time(),
                                               parts.clock().time_step(),
                                               mpi_communicator);
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
      folder->write_used_parameters(used_parameters);
    return folder;
  }


  void
  Simulator::take_over_output(const unsigned int step)
  {
    has_taken_over_output = true;
    // The old summary goes first: a run killed in between leaves none,
    // as any run that has not ended does. The field files of later steps
    // go last, once the PVD no longer lists them.
    output_folder->remove_summary();
    output_folder->write_used_parameters(used_parameters);
    for (Output *output : outputs)
      output->flush();
    output_folder->remove_fields_after(step);
  }


  void
  Simulator::setup()
  {
    parts.setup_mesh();
    stepper = std::make_unique<TimeStepper>(
      parts.for_stepper(),
      TimeStepper::Options{parts.is_dynamic(),
                           time_history.wants_energies(),
                           parts.clock()},
      timer);
    stepper->setup();
    parts.check_not_trivial();

    const Discretization &discretization = parts.discretization;
    pcout << "liftoff: " << discretization.triangulation.n_global_active_cells()
          << " cells, " << discretization.dof_handler.n_dofs() << " dofs ("
          << discretization.element().name() << "), "
          << Utilities::MPI::n_mpi_processes(mpi_communicator) << " rank(s)"
          << units.groups_line() << std::endl;
  }


  void
  Simulator::check_before_run()
  {
    if (!parts.is_dynamic())
      return;
    // The initial fields are evaluated at the nodes only now; a nan there
    // (sqrt(x) on x < 0) would otherwise surface as a nan history.
    stepper->set_initial_state(parts.initial_conditions);
    stepper->check_time_step();
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
    used_parameters = units.record_of(parameters.str());
    resume_step     = 0;
    if (start == Start::resume)
      {
        AssertThrow(parts.is_dynamic(),
                    ExcMessage("--resume continues a time integration; "
                               "Analysis/Type = static has none."));
        AssertThrow(writes_files(),
                    ExcMessage("--resume reads the checkpoint in "
                               "Output/Directory, which is empty."));
      }
    // Checks that need the mesh and matrices precede touching the folder.
    units.explain_run_errors_of([this]() { setup(), check_before_run(); });

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
      output->setup(parts.discretization, output_directory);
    // Every point of the scene has found its cell.
    parts.discretization.release_grid_cache();
    units.explain_run_errors_of([this]() { run_analysis(); });
  }


  unsigned int
  Simulator::open_checkpoint()
  {
    // Everything is checked before a file is touched: a refused resume
    // leaves the output of the earlier run as it was.
    const unsigned int step =
      checkpoint.open(output_directory, mpi_communicator, scene);
    const Clock &clock = stepper->state().clock;
    AssertThrow(step <= clock.n_steps(),
                ExcMessage("Cannot resume: the checkpoint is of step "
                           + std::to_string(step)
                           + ", beyond Time integration/End time = "
                           + format_number(clock.end_time()) + " ("
                           + std::to_string(clock.n_steps()) + " steps)."));
    // A killed run may leave temporary files (and checkpoint.new).
    output_folder->remove_temporary_files();
    return step;
  }


  void
  Simulator::run_analysis()
  {
    try
      {
        if (!parts.is_dynamic())
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
    write_summary(warnings().empty() ? "completed" : "completed with warnings");
  }


  void
  Simulator::record(const ActiveSetIteration::Result &iteration)
  {
    SectionTimer::Scope  t(timer, "output");
    const PlateState    &state = stepper->state();
    const ResultantSweep resultants(parts.plate,
                                    parts.discretization,
                                    parts.foundation.law(),
                                    state.ghosted_u,
                                    parts.loads.free_bending(
                                      state.clock.tau()));
    const StepData       step{state,
                        parts.discretization,
                        parts.foundation,
                        parts.joint_springs,
                        parts.joint_dowels,
                        iteration,
                        resultants,
                        parts.foundation.diagnostics().contact_area_fraction()};
    for (Output *output : outputs)
      output->execute(step);
    if (!has_taken_over_output)
      take_over_output(state.clock.step());
  }


  TimeStepper::StopCheck
  Simulator::stop_check()
  {
    return [this](const std::string &when) {
      if (const int signal = StopSignal::received(mpi_communicator))
        stop_for_signal(signal, when);
    };
  }


  void
  Simulator::run_static()
  {
    auto result = stepper->solve_static_analysis(stop_check());
    for (unsigned int cycle = 1;
         cycle <= parts.mesh_refinement.n_static_cycles();
         ++cycle)
      {
        if (!adapt_mesh())
          break;
        result = stepper->solve_static_analysis(stop_check());
        pcout << "static cycle " << cycle << ": "
              << parts.discretization.triangulation.n_global_active_cells()
              << " cells, " << parts.discretization.dof_handler.n_dofs()
              << " dofs, " << result.iterations << " active-set iterations"
              << std::endl;
      }
    record(result);
    pcout << "static: " << result.iterations << " active-set iterations, "
          << "contact fraction "
          << parts.foundation.diagnostics().contact_area_fraction()
          << std::endl;
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

    const Clock &clock = stepper->state().clock;
    for (unsigned int step = clock.step() + 1; step <= clock.n_steps(); ++step)
      {
        record(stepper->do_step(step));
        adapt_mesh_if_due();
        const int signal = StopSignal::received(mpi_communicator);
        write_checkpoint_if_due(signal != 0);
        stop_if_signalled(signal);
      }
  }


  bool
  Simulator::adapt_mesh()
  {
    if (!stepper->adapt_mesh())
      return false;
    find_points_on_new_mesh();
    return true;
  }


  void
  Simulator::find_points_on_new_mesh()
  {
    // Timed with the rest of a new mesh's set-up.
    SectionTimer::Scope t(timer, "setup");
    for (Output *output : outputs)
      output->mesh_changed(parts.discretization);
    parts.discretization.release_grid_cache();
  }


  void
  Simulator::adapt_mesh_if_due()
  {
    const Clock &clock = stepper->state().clock;
    if (!parts.mesh_refinement.is_due(clock.step()))
      return;
    adaptation_pending = clock.is_at_end();
    if (adaptation_pending)
      return;
    const std::optional<double> jump = stepper->adapt_mesh_in_time_loop();
    if (!jump)
      return;
    find_points_on_new_mesh();
    largest_energy_jump = std::abs(*jump) > std::abs(largest_energy_jump)
                            ? *jump
                            : largest_energy_jump;
  }


  void
  Simulator::adapt_to_initial_state()
  {
    if (parts.initial_conditions.is_at_rest(parts.discretization))
      return;
    unsigned int r = 0;
    for (; r < parts.mesh_refinement.n_initial_refinements(); ++r)
      {
        parts.active_set.update_status(stepper->state().ghosted_u,
                                       parts.foundation.law().pressure());
        if (!adapt_mesh())
          break;
        // The fields themselves, not their interpolant on the old mesh.
        stepper->set_initial_state(parts.initial_conditions);
      }
    // The stability limit of the final mesh only.
    if (r > 0)
      stepper->check_time_step();
  }


  void
  Simulator::start_from_initial_state()
  {
    // check_before_run() set the initial state.
    adapt_to_initial_state();
    stepper->start_time_integration(stop_check());
    record({});
  }


  void
  Simulator::resume_from_checkpoint()
  {
    SectionTimer::Scope t(timer, "checkpoint");
    if (parts.mesh_refinement.is_enabled())
      {
        // The run's mesh is the checkpoint's; everything on it is rebuilt
        // before the state is read into it.
        parts.discretization.load_mesh(checkpoint.mesh_file());
        stepper->setup();
        find_points_on_new_mesh();
      }
    checkpoint.read(mpi_communicator, [&](InputArchive &archive) {
      serialize(archive, Checkpoint::format);
    });
    const unsigned int step = stepper->state().clock.step();
    AssertThrow(
      step == resume_step && time_history.rows().size() == resume_step + 1,
      ExcMessage("The checkpoint of step " + std::to_string(resume_step)
                 + " holds step " + std::to_string(step) + " and "
                 + std::to_string(time_history.rows().size()) + " rows."));
    pcout << "resumed after step " << resume_step << std::endl;
  }


  void
  Simulator::write_checkpoint_if_due(const bool is_stopping)
  {
    const Clock &clock = stepper->state().clock;
    if (!writes_files()
        || !(is_stopping
             || checkpoint.is_due(clock.step(),
                                  clock.is_at_end(),
                                  mpi_communicator)))
      return;
    SectionTimer::Scope t(timer, "checkpoint");
    // An adaptive run's mesh cannot be rebuilt from the scene.
    const Checkpoint::SharedFiles save_mesh =
      parts.mesh_refinement.is_enabled()
        ? Checkpoint::mesh_writer(parts.discretization.triangulation)
        : Checkpoint::SharedFiles();
    checkpoint.write(
      output_directory,
      mpi_communicator,
      clock.step(),
      scene,
      [&](OutputArchive &archive) { serialize(archive, Checkpoint::format); },
      save_mesh);
  }


  void
  Simulator::stop_if_signalled(const int signal)
  {
    if (signal != 0)
      stop_for_signal(signal,
                      "after step "
                        + std::to_string(stepper->state().clock.step())
                        + " (tau = "
                        + format_number(stepper->state().clock.tau())
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
    stepper->serialize_state(archive);
    archive &adaptation_pending;
    stepper->serialize_contact(archive);
    for (Output *output : outputs)
      transfer(archive, *output);
    (void)version;
  }


  std::string
  Simulator::warnings() const
  {
    const std::string a = stepper->warnings(), b = small_deflection.warning();
    return a.empty() || b.empty() ? a + b : a + " " + b;
  }


  RunSummary
  Simulator::summary_of_run(const std::string &status) const
  {
    const auto &rows = time_history.rows();
    RunSummary  summary;
    summary.add("status", status);
    if (!warnings().empty())
      summary.add("warning", warnings());
    summary.add("liftoff",
                std::string(LIFTOFF_VERSION) + " (git " + LIFTOFF_GIT_COMMIT
                  + ")");
    if (resume_step > 0)
      summary.add("resumed after step", double(resume_step));
    summary.add("analysis", parts.is_dynamic() ? "dynamic" : "static");
    summary.add_units(units);
    summary.add_mesh(parts.discretization);
    if (parts.mesh_refinement.is_enabled())
      {
        summary.add("mesh adaptations", double(stepper->n_adaptations()));
        summary.add("largest relative energy change of a transfer",
                    largest_energy_jump);
      }
    summary.add("steps", double(rows.empty() ? 0 : rows.size() - 1));
    summary.add_checks(*stepper,
                       parts.energy_check,
                       parts.is_dynamic(),
                       parts.newmark.beta);
    for (const Output *output : outputs)
      output->add_to(summary);
    summary.add_linear_solver(parts.active_set.linear_solver());
    summary.add_resources(timer, wall_clock.wall_time(), mpi_communicator);
    return summary;
  }


  void
  Simulator::write_summary(const std::string &status) const
  {
    const RunSummary summary = summary_of_run(status);
    status_out << "status: " << status
               << (writes_files()
                     ? "; summary in " + output_directory + "/summary.txt"
                     : std::string())
               << std::endl;
    pcout << summary.text();
    if (writes_files())
      {
        if (output_folder)
          output_folder->release_space_for_summary();
        summary.write(output_directory, mpi_communicator);
      }
  }
} // namespace liftoff
