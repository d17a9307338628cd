#include <deal.II/base/mpi.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/output_files.h>
#include <liftoff/loads/load_set.h>
#include <liftoff/output/deflectometer_sensors.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/time_history.h>
#include <liftoff/time/clock.h>
#include <liftoff/time/plate_state.h>

#include <cmath>
#include <limits>

namespace liftoff
{
  namespace
  {
    /// The SHRP sensor offsets, in metres.
    const std::vector<double> shrp_offsets =
      {0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219, 1.524};
  } // namespace


  void
  DeflectometerSensors::parse_parameters(ParameterHandler &prm,
                                         const SceneView &)
  {
    // The sensors are the Loads' deflectometer test's: read outside
    // `Output`.
    prm.leave_subsection();
    test.reset();
    prm.enter_subsection("Loads");
    for (unsigned int i = 1; i <= LoadSet::max_loads_per_kind; ++i)
      {
        const std::string section = "Deflectometer " + std::to_string(i);
        prm.enter_subsection(section);
        const Deflectometer read = Deflectometer::parse(prm, section);
        prm.leave_subsection();
        if (!read.is_on())
          continue;
        AssertThrow(!test,
                    ExcMessage(read.name
                               + ": a scene holds one deflectometer "
                                 "test; "
                               + test->name + " is on already."));
        test = read;
      }
    prm.leave_subsection();
    prm.enter_subsection("Output");
  }


  void
  DeflectometerSensors::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
    offsets.clear();
    points.clear();
    if (!test)
      return;
    offsets = test->offsets;
    if (offsets.empty())
      {
        AssertThrow(units.is_physical(),
                    ExcMessage(test->name
                               + "/Sensor offsets must be given in a "
                                 "dimensionless scene (the SHRP set is the "
                                 "default of an SI scene only)."));
        for (const double d : shrp_offsets)
          offsets.push_back(d / units.scale(PhysicalUnits::Quantity::length));
      }
    points = test->sensor_points(offsets);
    peak.assign(points.size(), -std::numeric_limits<double>::infinity());
    rest.clear();
    peak_time.assign(points.size(), 0.0);
  }


  void
  DeflectometerSensors::check(const SceneView &scene) const
  {
    const Discretization &disc   = scene.discretization;
    const double          length = units.scale(PhysicalUnits::Quantity::length);
    // The loading plate rests on the slab: one that overhangs its edge
    // would press on air, and the patch would drop that part of the force
    // (a plate of radius 0.15 m centred 0.05 m from the edge: 29 % of it).
    if (test)
      for (unsigned int k = 0; k < 64; ++k)
        {
          const double   angle = 2 * numbers::PI * k / 64;
          const Point<2> rim   = test->centre
                               + (1 - 1e-9) * test->radius
                                   * Point<2>(std::cos(angle), std::sin(angle));
          AssertThrow(disc.geometry().is_on_plate(rim),
                      ExcMessage(
                        test->name + "/Position: the loading plate of "
                        + "radius " + format_number(test->radius * length)
                        + units.unit(PhysicalUnits::Quantity::length) + " at ("
                        + format_number(test->centre[0] * length) + ", "
                        + format_number(test->centre[1] * length)
                        + ") overhangs the plate's edge, at ("
                        + format_number(rim[0] * length) + ", "
                        + format_number(rim[1] * length)
                        + "): put its centre at least its radius inside."));
        }
    for (unsigned int k = 0; k < points.size(); ++k)
      AssertThrow(disc.geometry().is_on_plate(points[k]),
                  ExcMessage(test->name + "/Sensor offsets: the sensor at "
                             + format_number(offsets[k] * length)
                             + units.unit(PhysicalUnits::Quantity::length)
                             + " from the load, at ("
                             + format_number(points[k][0] * length) + ", "
                             + format_number(points[k][1] * length)
                             + "), lies off the plate."));
  }


  std::string
  DeflectometerSensors::column_name(const unsigned int k) const
  {
    return "d("
           + format_number(offsets[k]
                           * units.scale(PhysicalUnits::Quantity::length))
           + ")";
  }


  void
  DeflectometerSensors::add_columns_to(TimeHistory &history) const
  {
    std::vector<HistoryColumns::Column> group;
    for (unsigned int k = 0; k < points.size(); ++k)
      group.push_back({column_name(k), PhysicalUnits::Quantity::deflection});
    history.add_columns(group, [this](const StepData &step) {
      return deflections(step);
    });
  }


  void
  DeflectometerSensors::setup(const SceneView &scene, const std::string &folder)
  {
    directory = folder;
    mesh_changed(scene);
  }


  void
  DeflectometerSensors::mesh_changed(const SceneView &scene)
  {
    const Discretization &disc = scene.discretization;
    discretization             = &disc;
    probes.clear();
    for (const Point<2> &p : points)
      probes.emplace_back(disc, disc.geometry().to_modelled_part(p));
  }


  std::vector<double>
  DeflectometerSensors::deflections(const StepData &step) const
  {
    std::vector<double> w;
    for (const auto &probe : probes)
      w.push_back(probe.local_value(step.state.ghosted_u));
    Utilities::MPI::sum(w, discretization->mpi_communicator, w);
    // A time integration's sensors measure from the plate at rest at tau =
    // 0 (settled under its permanent loads), as geophones do; a static
    // analysis has no rest state apart from the flat plate.
    const Clock &clock = step.state.clock;
    if (clock.step() == 0 && clock.n_steps() > 0)
      rest = w;
    for (unsigned int k = 0; k < w.size() && k < rest.size(); ++k)
      w[k] -= rest[k];
    return w;
  }


  void
  DeflectometerSensors::execute(const StepData &step)
  {
    if (points.empty())
      return;
    const std::vector<double> w = deflections(step);
    for (unsigned int k = 0; k < w.size(); ++k)
      if (w[k] > peak[k])
        {
          peak[k]      = w[k];
          peak_time[k] = step.state.clock.tau();
        }
  }


  void
  DeflectometerSensors::flush()
  {
    if (points.empty() || directory.empty())
      return;
    using Quantity      = PhysicalUnits::Quantity;
    const MPI_Comm comm = discretization->mpi_communicator;
    collective_attempt(
      comm, "Cannot write " + directory + "/basin.csv: ", [&]() {
        if (Utilities::MPI::this_mpi_process(comm) != 0)
          return;
        write_file_atomically(directory + "/basin.csv", [&](std::ostream &out) {
          out.precision(10);
          out << "offset" << units.unit(Quantity::length) << ",x"
              << units.unit(Quantity::length) << ",y"
              << units.unit(Quantity::length) << ",peak_w"
              << units.unit(Quantity::deflection) << ","
              << (units.is_physical() ? "t_peak" : "tau_peak")
              << units.unit(Quantity::time) << "\n";
          const double length = units.scale(Quantity::length);
          for (unsigned int k = 0; k < points.size(); ++k)
            out << offsets[k] * length << "," << points[k][0] * length << ","
                << points[k][1] * length << ","
                << peak[k] * units.scale(Quantity::deflection) << ","
                << peak_time[k] * units.scale(Quantity::time) << "\n";
        });
      });
  }


  void
  DeflectometerSensors::save(OutputArchive &archive) const
  {
    const unsigned int n = peak.size();
    archive << n;
    for (unsigned int k = 0; k < n; ++k)
      archive << peak[k] << peak_time[k] << rest_at(k);
  }


  void
  DeflectometerSensors::load(InputArchive &archive)
  {
    unsigned int n = 0;
    archive >> n;
    AssertThrow(n == peak.size(),
                ExcMessage("The checkpoint holds " + std::to_string(n)
                           + " deflectometer sensors, the scene "
                           + std::to_string(peak.size()) + "."));
    rest.assign(n, 0.0);
    for (unsigned int k = 0; k < n; ++k)
      archive >> peak[k] >> peak_time[k] >> rest[k];
  }


  double
  DeflectometerSensors::rest_at(const unsigned int k) const
  {
    return k < rest.size() ? rest[k] : 0.0;
  }


  void
  DeflectometerSensors::add_to(RunSummary &summary) const
  {
    if (points.empty())
      return;
    using Quantity = PhysicalUnits::Quantity;
    RunSummary::Section section;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        section.emplace_back(column_name(k) + units.unit(Quantity::deflection),
                             peak[k] * units.scale(Quantity::deflection));
        section.emplace_back(column_name(k) + " time"
                               + units.unit(Quantity::time),
                             peak_time[k] * units.scale(Quantity::time));
      }
    summary.add("deflectometer basin (peak and its time)", section);
  }


  const std::vector<double> &
  DeflectometerSensors::peaks() const
  {
    return peak;
  }
} // namespace liftoff
