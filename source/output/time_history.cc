#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <liftoff/base/archives.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/time/plate_state.h>

#include <liftoff/output/time_history.h>

#include <algorithm>
#include <array>
#include <charconv>

#include <iomanip>
#include <limits>
#include <sstream>

namespace liftoff
{
  namespace
  {
    std::vector<Point<2>>
    parse_points(const std::string &text)
    {
      std::vector<Point<2>> points;
      for (const auto &entry : Utilities::split_string_list(text, ';'))
        {
          const auto xy = Utilities::string_to_double(
            Utilities::split_string_list(entry, ','));
          points.emplace_back(xy[0], xy[1]);
        }
      return points;
    }
  } // namespace


  void
  TimeHistory::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Probe points",
      "0, 0",
      Patterns::List(Patterns::List(Patterns::Double(), 2, 2, ","),
                     0,
                     Patterns::List::max_int_value,
                     ";"),
      "Points x, y of the full plate, separated by ';', whose "
      "deflection w is written to history.csv at every step.");
    prm.declare_entry("Write energies",
                      "true",
                      Patterns::Bool(),
                      "Write kinetic, strain and foundation energy, the work "
                      "of the loads and the balance error to history.csv "
                      "(costs two matrix-vector products per step).");
    prm.declare_entry(
      "Write foundation resultant",
      "false",
      Patterns::Bool(),
      "Write the bed's normal reaction on the full plate to history.csv: "
      "`resultant`, the force of the springs and dashpots int_S (Gamma "
      "(w - g) + c w_dot) over the contact region S (the shear layer adds "
      "no force), its centre `resultant_x`, `resultant_y` (the point about "
      "which it has no moment; 0, 0 without a force) and `contact_area`, "
      "in full plate units also on a half or quarter model; and the largest "
      "bearing pressure at a Gauss point in contact, `max_pressure` (0 "
      "without contact), at `max_pressure_x`, `max_pressure_y` (a point of "
      "the meshed part) (costs a pass over the Gauss points per step).");
  }


  void
  TimeHistory::parse_parameters(ParameterHandler &prm)
  {
    probe_points = parse_points(prm.get("Probe points"));
    for (unsigned int i = 0; i < probe_points.size(); ++i)
      for (unsigned int j = 0; j < i; ++j)
        AssertThrow(probe_points[i] != probe_points[j],
                    ExcMessage("Output/Probe points: the point "
                               + std::to_string(probe_points[i][0]) + ", "
                               + std::to_string(probe_points[i][1])
                               + " is given twice."));
    write_energies  = prm.get_bool("Write energies");
    write_resultant = prm.get_bool("Write foundation resultant");
    make_columns();
  }


  void
  TimeHistory::check_against(const Discretization &disc) const
  {
    for (const auto &p : probe_points)
      AssertThrow(disc.geometry().is_on_plate(p),
                  ExcMessage("Output/Probe points: the point "
                             + std::to_string(p[0]) + ", "
                             + std::to_string(p[1]) + " lies outside "
                             + disc.geometry().plate_description() + "."));
  }


  std::vector<std::string>
  TimeHistory::probe_column_names() const
  {
    // Six digits name most points briefly; points that six digits do not
    // tell apart (0.333333 and 0.3333334) get as many as they need.
    for (int digits = 6;; ++digits)
      {
        std::vector<std::string> names;
        for (const auto &p : probe_points)
          {
            std::ostringstream name;
            name << std::setprecision(digits) << "w(" << p[0] << ";" << p[1]
                 << ")";
            names.push_back(name.str());
          }
        std::vector<std::string> sorted = names;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()
            || digits == std::numeric_limits<double>::max_digits10)
          return names;
      }
  }


  bool
  TimeHistory::wants_energies() const
  {
    return write_energies;
  }


  void
  TimeHistory::follow(
    const std::vector<std::string>                         &names,
    const std::function<std::vector<double>(const double)> &positions)
  {
    moving_load_names     = names;
    moving_load_positions = positions;
    make_columns();
  }


  void
  TimeHistory::show_dissipated_energy(const bool show)
  {
    write_dissipated = show;
    make_columns();
  }


  void
  TimeHistory::make_columns()
  {
    columns.clear();
    const auto add = [this](const std::string                 &name,
                            std::function<double(const Row &)> value) {
      columns.push_back({name, std::move(value)});
    };
    add("tau", [](const Row &r) { return r.tau; });
    const std::vector<std::string> probe_names = probe_column_names();
    for (unsigned int k = 0; k < probe_names.size(); ++k)
      add(probe_names[k], [k](const Row &r) { return r.probe_w[k]; });
    add("contact_fraction", [](const Row &r) { return r.contact_fraction; });
    add("max_uplift", [](const Row &r) { return r.max_uplift; });
    add("active_set_iterations", [](const Row &r) { return r.iterations; });
    add("active_set_cycle", [](const Row &r) { return r.cycle_length; });
    add("cells", [](const Row &r) { return r.n_cells; });
    add("dofs", [](const Row &r) { return r.n_dofs; });
    if (write_energies)
      {
        add("kinetic", [](const Row &r) { return r.energies.kinetic; });
        add("strain", [](const Row &r) { return r.energies.strain; });
        add("foundation", [](const Row &r) { return r.energies.foundation; });
        add("work", [](const Row &r) { return r.energies.work; });
        if (write_dissipated)
          add("dissipated_energy",
              [](const Row &r) { return r.energies.dissipated; });
        add("balance_error", [](const Row &r) { return r.balance_error; });
      }
    if (write_resultant)
      {
        add("resultant", [](const Row &r) { return r.resultant; });
        add("resultant_x", [](const Row &r) { return r.resultant_x; });
        add("resultant_y", [](const Row &r) { return r.resultant_y; });
        add("contact_area", [](const Row &r) { return r.contact_area; });
        add("max_pressure", [](const Row &r) { return r.max_pressure; });
        add("max_pressure_x", [](const Row &r) { return r.max_pressure_x; });
        add("max_pressure_y", [](const Row &r) { return r.max_pressure_y; });
      }
    for (unsigned int k = 0; k < 3 * moving_load_names.size(); ++k)
      add(moving_load_names[k / 3] + std::array{"_x", "_y", "_on"}[k % 3],
          [k](const Row &r) { return r.moving_loads[k]; });
  }


  void
  TimeHistory::setup(const Discretization &disc, const std::string &directory)
  {
    mesh_changed(disc);
    history.clear();

    // No directory: keep the rows in memory only (tests). The file
    // appears with the first rows.
    file.open(directory.empty() ? "" : directory + "/history.csv",
              rewrite_interval,
              disc.mpi_communicator);
    write_header();
  }


  void
  TimeHistory::mesh_changed(const Discretization &disc)
  {
    discretization = &disc;
    probes.clear();
    for (const auto &p : probe_points)
      probes.emplace_back(disc, disc.geometry().to_modelled_part(p));
    w_dofs = DoFTools::extract_dofs(disc.dof_handler,
                                    disc.dof_handler.get_fe().component_mask(
                                      FEValuesExtractors::Scalar(0)));
    gap_at_w_dofs.clear();
    if (write_resultant)
      disc.reinit_ghosted_vector(ghosted_velocity);
  }


  void
  TimeHistory::find_gap_at_w_dofs(const StepData &step)
  {
    if (!step.foundation.law().has_initial_gap() || !gap_at_w_dofs.empty())
      return;
    const Discretization                       &disc = step.discretization;
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(
      disc.mapping,
      disc.dof_handler,
      points,
      disc.dof_handler.get_fe().component_mask(FEValuesExtractors::Scalar(0)));
    for (const auto i : w_dofs)
      gap_at_w_dofs.push_back(step.foundation.law().gap_at(points.at(i)));
  }


  void
  TimeHistory::write_header()
  {
    std::ostream &out = file.stream();
    for (unsigned int c = 0; c < columns.size(); ++c)
      out << (c > 0 ? "," : "") << columns[c].name;
    out << '\n';
  }


  TimeHistory::Row
  TimeHistory::row_of(const StepData &step) const
  {
    const MPI_Comm         comm = discretization->mpi_communicator;
    const LA::MPI::Vector &u    = step.state.ghosted_u;
    Row                    row;
    row.tau              = step.state.tau;
    row.iterations       = step.iteration.iterations;
    row.cycle_length     = step.iteration.cycle_length;
    row.contact_fraction = step.contact_fraction;
    for (const auto &probe : probes)
      row.probe_w.push_back(probe.local_value(u));
    Utilities::MPI::sum(row.probe_w, comm, row.probe_w);
    // (g - w)^+ as the uplift field; g = 0 takes the plain path.
    double uplift = 0;
    if (gap_at_w_dofs.empty())
      for (const auto i : w_dofs)
        uplift = std::max(uplift, -u(i));
    else
      {
        unsigned int k = 0;
        for (const auto i : w_dofs)
          uplift = std::max(uplift, gap_at_w_dofs[k++] - u(i));
      }
    row.max_uplift = Utilities::MPI::max(uplift, comm);
    row.n_cells    = step.discretization.triangulation.n_global_active_cells();
    row.n_dofs     = step.discretization.dof_handler.n_dofs();
    row.energies   = step.state.energies;
    row.balance_error = row.energies.error(step.state.initial_energies);
    if (moving_load_positions)
      row.moving_loads = moving_load_positions(row.tau);
    if (write_resultant)
      {
        const auto r =
          step.foundation.diagnostics().resultant(u, ghosted_velocity);
        row.resultant      = r.force;
        row.resultant_x    = r.centre[0];
        row.resultant_y    = r.centre[1];
        row.contact_area   = r.contact_area;
        row.max_pressure   = r.largest_pressure;
        row.max_pressure_x = r.largest_pressure_at[0];
        row.max_pressure_y = r.largest_pressure_at[1];
      }
    return row;
  }


  void
  TimeHistory::execute(const StepData &step)
  {
    find_gap_at_w_dofs(step);
    if (write_resultant && step.foundation.has_damping())
      ghosted_velocity = step.state.v;
    history.push_back(row_of(step));
    write_row(history.back());
    file.write_if_due();
  }


  namespace
  {
    /// `value` as a stream of precision 12 writes it (printf's %.12g), by
    /// std::to_chars: the stream's formatting took 7 % of the Example 2
    /// pulse's run (20 000 rows).
    void
    put(std::ostream &out, const double value)
    {
      char       text[32];
      const auto end = std::to_chars(std::begin(text),
                                     std::end(text),
                                     value,
                                     std::chars_format::general,
                                     12)
                         .ptr;
      out.write(text, end - text);
    }

  } // namespace


  void
  TimeHistory::write_row(const Row &row)
  {
    // Integer columns are exact in a double and written alike below 1e12.
    std::ostream &out = file.stream();
    for (unsigned int c = 0; c < columns.size(); ++c)
      {
        if (c > 0)
          out << ',';
        put(out, columns[c].value(row));
      }
    out << '\n';
  }


  void
  TimeHistory::flush()
  {
    file.flush();
  }


  void
  TimeHistory::save(OutputArchive &archive) const
  {
    archive << column_names() << Row::layout() << history;
  }


  void
  TimeHistory::load(InputArchive &archive)
  {
    // history.csv is a function of the rows: they are written again as
    // they were, and those of steps after the checkpoint are gone once the
    // file is rewritten.
    // A checkpoint of other columns, or of rows of another layout (another
    // version of liftoff: an optional column adds a member to every row),
    // is refused before its rows are read.
    std::vector<std::string> saved, saved_layout;
    archive >> saved >> saved_layout;
    const auto joined = [](const std::vector<std::string> &names) {
      std::string text;
      for (const auto &name : names)
        text += (text.empty() ? "" : ",") + name;
      return text;
    };
    AssertThrow(saved == column_names() && saved_layout == Row::layout(),
                ExcMessage("The checkpoint's time history has the columns "
                           + joined(saved) + " and rows of "
                           + joined(saved_layout) + ", this liftoff writes "
                           + joined(column_names()) + " and rows of "
                           + joined(Row::layout())
                           + ": it was written by another version of liftoff; "
                             "resume with that version, or start the scene "
                             "anew."));
    archive >> history;
    file.hold();
    for (const Row &row : history)
      write_row(row);
  }


  TimeHistory::IterationStatistics
  TimeHistory::iteration_statistics() const
  {
    IterationStatistics statistics;
    unsigned int        total = 0, n = 0;
    for (const Row &row : history)
      if (row.iterations > 0)
        {
          total += row.iterations;
          statistics.max = std::max(statistics.max, row.iterations);
          ++n;
          statistics.n_cycled += (row.cycle_length > 0);
        }
    statistics.mean = (n > 0 ? double(total) / n : 0.0);
    return statistics;
  }


  std::vector<std::string>
  TimeHistory::column_names() const
  {
    std::vector<std::string> names;
    for (const Column &column : columns)
      names.push_back(column.name);
    return names;
  }


  const std::vector<TimeHistory::Row> &
  TimeHistory::rows() const
  {
    return history;
  }
} // namespace liftoff
