#include <deal.II/base/mpi.h>

#include <liftoff/time_history.h>

#include <iomanip>

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
    prm.enter_subsection("Output");
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
    prm.leave_subsection();
  }


  void
  TimeHistory::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    probe_points   = parse_points(prm.get("Probe points"));
    write_energies = prm.get_bool("Write energies");
    prm.leave_subsection();
  }


  void
  TimeHistory::check_against(const Discretization &disc) const
  {
    for (const auto &p : probe_points)
      AssertThrow(disc.plate_box().point_inside(p, 1e-12),
                  ExcMessage("Output/Probe points: the point "
                             + std::to_string(p[0]) + ", "
                             + std::to_string(p[1])
                             + " lies outside the plate [-1/2, 1/2] x [-mu/2, "
                               "mu/2]."));
  }


  void
  TimeHistory::setup(const Discretization &disc, const std::string &directory)
  {
    discretization = &disc;
    probes.clear();
    for (const auto &p : probe_points)
      probes.emplace_back(disc, disc.to_modelled_part(p));

    // No directory: keep the values in memory only (tests). The file
    // appears with the first rows.
    file.open(directory.empty() ? "" : directory + "/history.csv",
              1.0,
              disc.mpi_communicator);
    std::ostream &out = file.stream();
    out << "tau";
    for (const auto &p : probe_points)
      out << ",w(" << p[0] << ";" << p[1] << ")";
    out << ",contact_fraction,active_set_iterations,active_set_cycle";
    if (write_energies)
      out << ",kinetic,strain,foundation,work,balance_error";
    out << '\n';
  }


  bool
  TimeHistory::wants_energies() const
  {
    return write_energies;
  }


  std::vector<double>
  TimeHistory::probe_values(const LA::MPI::Vector &u) const
  {
    std::vector<double> values;
    for (const auto &probe : probes)
      values.push_back(probe.local_value(u));
    Utilities::MPI::sum(values, discretization->mpi_communicator, values);
    return values;
  }


  void
  TimeHistory::record(const double               tau,
                      const std::vector<double> &w,
                      const double               contact_fraction,
                      const unsigned int         iterations,
                      const unsigned int         cycle_length,
                      const EnergyBalance       &energies,
                      const EnergyBalance       &initial)
  {
    std::ostream &out = file.stream();
    out << std::setprecision(12) << tau;
    for (const double value : w)
      out << ',' << value;
    out << ',' << contact_fraction << ',' << iterations << ',' << cycle_length;
    if (write_energies)
      out << ',' << energies.kinetic << ',' << energies.strain << ','
          << energies.foundation << ',' << energies.work << ','
          << energies.error(initial);
    out << '\n';
    file.write_if_due();
  }


  void
  TimeHistory::flush()
  {
    file.flush();
  }


  void
  TimeHistory::hold()
  {
    file.hold();
  }
} // namespace liftoff
