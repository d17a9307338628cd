#include <deal.II/base/utilities.h>

#include <liftoff/base/number_text.h>
#include <liftoff/base/output_files.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/base/section_timer.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/solver/linear_solver.h>
#include <liftoff/time/energy_check.h>
#include <liftoff/time/time_stepper.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace liftoff
{
  namespace
  {
    // Counts read as counts, in both files (a million dofs is not 1e+06).
    bool
    is_count(const double x)
    {
      return x == std::round(x) && std::abs(x) < 1e15;
    }


    std::string
    text_number(const double x)
    {
      std::ostringstream out;
      if (is_count(x))
        out << static_cast<long long>(x);
      else
        out << x;
      return out.str();
    }

    // A value that is not finite becomes null (JSON has no inf or nan),
    // rather than making the file unreadable.
    nlohmann::ordered_json
    json_number(const double x)
    {
      if (!std::isfinite(x))
        return nullptr;
      if (is_count(x))
        return static_cast<long long>(x);
      return x;
    }
  } // namespace


  void
  RunSummary::add(const std::string &key, const Value &value)
  {
    entries.emplace_back(key, value);
  }


  std::string
  RunSummary::text() const
  {
    std::ostringstream out;
    for (const auto &[key, value] : entries)
      {
        out << key << ':';
        if (const auto *section = std::get_if<Section>(&value))
          {
            out << '\n';
            for (const auto &[name, number] : *section)
              out << "  " << name << ": " << text_number(number) << '\n';
          }
        else if (const auto *number = std::get_if<double>(&value))
          out << ' ' << text_number(*number) << '\n';
        else
          out << ' ' << std::get<std::string>(value) << '\n';
      }
    return out.str();
  }


  std::string
  RunSummary::json() const
  {
    // ordered_json keeps the order of summary.txt; doubles are written in
    // their shortest form that reads back exactly.
    nlohmann::ordered_json document = nlohmann::ordered_json::object();
    for (const auto &[key, value] : entries)
      if (const auto *section = std::get_if<Section>(&value))
        {
          auto &object = document[key] = nlohmann::ordered_json::object();
          for (const auto &[name, number] : *section)
            object[name] = json_number(number);
        }
      else if (const auto *number = std::get_if<double>(&value))
        document[key] = json_number(*number);
      else
        document[key] = std::get<std::string>(value);
    // A scene's bytes that are not UTF-8 (a file name, say) are replaced,
    // not thrown on: the summary of a finished run is always written.
    return document.dump(2,
                         ' ',
                         false,
                         nlohmann::ordered_json::error_handler_t::replace)
           + "\n";
  }


  void
  RunSummary::write(const std::string &directory, const MPI_Comm comm) const
  {
    collective_attempt(comm, "", [&]() {
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      write_file_atomically(directory + "/summary.json",
                            [&](std::ostream &out) { out << json(); });
      write_file_atomically(directory + "/summary.txt",
                            [&](std::ostream &out) { out << text(); });
    });
  }


  void
  RunSummary::add_units(const PhysicalUnits &units)
  {
    if (!units.is_physical())
      return;
    add("units",
        "SI (history.csv and profiles.csv: t [s], w [m], energies [J], "
        "forces [N], pressures [Pa])");
    add("scene groups", units.groups());
  }


  void
  RunSummary::add_mesh(const Discretization &discretization)
  {
    add("ranks",
        double(
          Utilities::MPI::n_mpi_processes(discretization.mpi_communicator)));
    add("cells", double(discretization.triangulation.n_global_active_cells()));
    add("degree", double(discretization.element().degree()));
    add("element", discretization.element().name());
    add("dofs", double(discretization.dof_handler.n_dofs()));
  }


  void
  RunSummary::add_checks(const TimeStepper &stepper,
                         const EnergyCheck &energy_check,
                         const bool         is_dynamic,
                         const double       beta)
  {
    if (is_dynamic && energy_check.is_enabled() && !stepper.checks_energy())
      add("energy balance",
          "not checked: Time integration/Beta = " + format_number(beta)
            + " with Gamma = 1/2 conserves a modified energy");
    if (const auto &equilibrium = stepper.static_equilibrium();
        equilibrium.imbalance >= 0)
      {
        add("static equilibrium, bed against loads (relative)",
            equilibrium.imbalance);
        add("static equilibrium, accepted", equilibrium.accepted());
      }
    if (stepper.checks_energy())
      {
        add("energy balance error, largest share of the energy scale",
            energy_check.largest_relative_error());
        add("energy balance error, its step",
            double(energy_check.step_of_largest_error()));
      }
    add_step_control(stepper.step_control());
  }


  void
  RunSummary::add_step_control(const StepSizeController &control)
  {
    if (!control.is_enabled())
      return;
    add("time steps taken", double(control.n_accepted));
    add("time steps repeated", double(control.n_rejected));
    add("changes of time step", double(control.n_level_changes));
    add("time steps above Error tolerance at the finest level",
        double(control.n_at_finest_above_tolerance));
  }


  void
  RunSummary::add_linear_solver(const LinearSolver &solver)
  {
    add("factorisations", double(solver.n_preparations));
    add("factor", solver.factor_name());
    add("substitutions", double(solver.n_substitutions));
    add("time per substitution [s]",
        solver.n_substitutions > 0
          ? solver.substitution_timer.wall_time() / solver.n_substitutions
          : 0.0);
    add("CG iterations", double(solver.n_cg_iterations));
    add("CG products with the whole matrix", double(solver.n_products));
    add("CG solutions that failed the residual check",
        double(solver.n_failed_checks));
  }


  void
  RunSummary::add_resources(const SectionTimer &timer,
                            const double        wall_time,
                            const MPI_Comm      comm)
  {
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    add("peak memory per rank, max [MB]",
        Utilities::MPI::max(memory.VmHWM / 1024.0, comm));
    add("wall time [s]", wall_time);
    Section sections;
    for (const auto &[section, seconds] : timer.wall_times())
      sections.emplace_back(section, seconds);
    add("wall time by section [s]", sections);
  }
} // namespace liftoff
