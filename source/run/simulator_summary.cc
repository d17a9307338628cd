#include <liftoff/output/run_summary.h>
#include <liftoff/run/simulator.h>
#include <liftoff/version.h>

// How a run ended and what it cost: the Simulator's summary.
namespace liftoff
{
  std::string
  Simulator::warnings() const
  {
    const std::string a = stepper->warnings(), b = outputs.warnings();
    return a.empty() || b.empty() ? a + b : a + " " + b;
  }


  RunSummary
  Simulator::summary_of_run(const std::string &status) const
  {
    const auto &rows = history();
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
    outputs.add_to(summary);
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
