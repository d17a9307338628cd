#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <liftoff/base/number_text.h>
#include <liftoff/output/envelopes.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/run/simulator.h>
#include <liftoff/run/stop_signal.h>

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
      , outputs(comm, verbose && show_progress)
  {}


  void
  Simulator::declare_parameters(ParameterHandler &prm)
  {
    SceneParts::declare_parameters(prm);
    prm.enter_subsection("Output");
    OutputDirectory::declare_parameters(prm);
    OutputList::declare_parameters(prm);
    prm.leave_subsection();
    Checkpoint::declare_parameters(prm);
    PhysicalUnits::declare_parameters(prm);
  }


  void
  Simulator::declare_scene(ParameterHandler &prm)
  {
    declare_parameters(prm);
    units.watch(prm);
  }


  void
  Simulator::parse_parameters(ParameterHandler &prm)
  {
    units.take_si_defaults(prm);
    units.parse_parameters(prm, SceneParts::outline_for_units(prm));
    ParameterHandler &scene = units.solver_scene(prm, declare_parameters);
    units.explain_errors_of([&]() {
      parts.parse_parameters(scene, units);
      scene.enter_subsection("Output");
      output_directory = scene.get("Directory");
      scene.leave_subsection();
      outputs.parse_parameters(scene, scene_view());
      if (parts.newmark.step_control.is_enabled())
        outputs.history().add_step_sizes(
          [this]() { return stepper->step_control().interval_columns(); });
      checkpoint.parse_parameters(scene);
      check_scene();
    });
  }


  void
  Simulator::check_scene() const
  {
    parts.check();
    outputs.check(scene_view());
  }


  SceneView
  Simulator::scene_view() const
  {
    return parts.view(units, pcout);
  }


  const Envelopes &
  Simulator::get_envelopes() const
  {
    return outputs.get<Envelopes>();
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
    outputs.flush();
    output_folder->remove_fields_after(step);
  }


  void
  Simulator::setup()
  {
    parts.setup_mesh();
    stepper = std::make_unique<TimeStepper>(
      parts.for_stepper(),
      TimeStepper::Options{parts.is_dynamic(),
                           outputs.history().wants_energies(),
                           parts.clock(),
                           [this](const std::string &message) {
                             return units.in_scene_terms(message);
                           }},
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
    // Every error from here on, the checkpoint's and the outputs' set-up
    // included, quotes the solver's numbers: told in the scene's units.
    units.explain_run_errors_of([&]() { set_up_and_run(start); });
  }


  void
  Simulator::set_up_and_run(const Start start)
  {
    // Checks that need the mesh and matrices precede touching the folder.
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
    outputs.setup(scene_view(), output_directory);
    // Every point of the scene has found its cell.
    parts.discretization.release_grid_cache();
    run_analysis();
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
        outputs.flush();
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
            outputs.flush(true);
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
                                    parts.loads.free_bending(state.clock.tau()),
                                    outputs.needs_face_stresses());
    const SceneView      scene = scene_view();
    const StepData       step{state,
                        scene,
                        iteration,
                        resultants,
                        parts.foundation.diagnostics().contact_area_fraction()};
    outputs.execute(step);
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
    outputs.mesh_changed(scene_view());
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
        parts.foundation.use_pressure(parts.foundation.law().pressure());
        parts.active_set.update_status(stepper->state().ghosted_u);
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
} // namespace liftoff
