#include <deal.II/base/mpi.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/output/profile_output.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/time/plate_state.h>

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace liftoff
{
  void
  ProfileOutput::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Profile start",
                      "0, 0",
                      Patterns::List(Patterns::Double(), 2, 2, ","),
                      "x, y where the profile line starts (full plate; "
                      "from the load with Profile follows)."
                        + quantity("length"));
    prm.declare_entry("Profile end",
                      "0.5, 0",
                      Patterns::List(Patterns::Double(), 2, 2, ","),
                      "x, y where the profile line ends (full plate; from "
                      "the load with Profile follows)."
                        + quantity("length"));
    prm.declare_entry("Profile follows",
                      "",
                      Patterns::Anything(),
                      "Empty: the line stands. The name of a moving load as "
                      "history.csv names it (point_load_2, patch_load_1, "
                      "vehicle_1): Profile start and Profile end are then "
                      "offsets from the load's point (a vehicle's: its "
                      "Path), and each profile is written along that line "
                      "where the load is at its time, the basin around the "
                      "load; points off the plate then are left out."
                        + quantity("text"));
    prm.declare_entry("Profile points",
                      "0",
                      Patterns::Integer(0, 100000),
                      "Points along the line (including its ends); 0 "
                      "writes no profiles.");
    prm.declare_entry("Profile times",
                      "",
                      Patterns::List(Patterns::Double(0.0)),
                      "Times tau at which profiles.csv gets a profile, "
                      "each at the step nearest to it (times nearer to "
                      "each other than half a Time step share one "
                      "profile; a time given twice is refused). Times beyond "
                      "Time integration/End time are not reached: the run "
                      "warns about them and goes on (a scene may be run "
                      "shorter for a try or resumed further)."
                        + quantity("time"));
  }


  void
  ProfileOutput::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    const auto a = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Profile start")));
    const auto b = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Profile end")));
    start    = Point<2>(a[0], a[1]);
    end      = Point<2>(b[0], b[1]);
    n_points = prm.get_integer("Profile points");
    rider    = prm.get("Profile follows");
    times.parse(prm.get("Profile times"));
    AssertThrow(n_points != 1,
                ExcMessage("Output/Profile points must be 0 (no profile) or "
                           "at least 2."));
    const LoadSet &loads = scene.loads;
    follow(loads.moving_load_names(), [&loads](const double tau) {
      return loads.moving_load_positions(tau);
    });
  }


  void
  ProfileOutput::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  Point<2>
  ProfileOutput::point(const unsigned int i) const
  {
    return start + (end - start) * (double(i) / (n_points - 1));
  }


  std::vector<Point<2>>
  ProfileOutput::line_at(const double tau) const
  {
    std::vector<Point<2>> at(n_points);
    for (unsigned int i = 0; i < n_points; ++i)
      at[i] = point(i);
    if (rider.empty())
      return at;
    // The followed load's centre, asked of the loads once for the line.
    const std::vector<double> xy = load_positions(tau);
    const Tensor<1, 2> centre({xy[3 * rider_index], xy[3 * rider_index + 1]});
    for (Point<2> &p : at)
      p = p + centre;
    return at;
  }


  void
  ProfileOutput::follow(
    const std::vector<std::string>                         &names,
    const std::function<std::vector<double>(const double)> &positions)
  {
    load_positions = positions;
    if (rider.empty())
      return;
    const auto found = std::find(names.begin(), names.end(), rider);
    AssertThrow(found != names.end(),
                ExcMessage("Output/Profile follows = <" + rider
                           + "> names no moving load; "
                           + (names.empty() ? "the scene has none."
                                            : "the scene's are <"
                                                + joined(names, ", ") + ">.")));
    rider_index = found - names.begin();
  }


  void
  ProfileOutput::check(const SceneView &scene) const
  {
    if (scene.dynamic)
      warn_of_times_not_reached(scene.clock.end_time(),
                                scene.clock.time_step(),
                                scene.discretization.mpi_communicator);
    // A riding line is placed anew at each profile time and keeps the
    // points on the plate at that time.
    const Discretization &disc = scene.discretization;
    if (n_points == 0 || !rider.empty())
      return;
    for (const auto &p : {start, end})
      AssertThrow(disc.geometry().is_on_plate(p),
                  ExcMessage("Output/Profile start and Profile end must lie "
                             "on "
                             + disc.geometry().plate_description() + "; "
                             + format_point(p[0], p[1]) + " does not."));
    // Between its ends a line may cross a hole (an annulus).
    for (unsigned int i = 0; i < n_points; ++i)
      AssertThrow(disc.geometry().is_on_plate(point(i)),
                  // A point between the ends is computed: its last digits
                  // are round-off, not what the user wrote.
                  ExcMessage("Output/Profile points: the profile's point "
                             + format_number(point(i)[0]) + ", "
                             + format_number(point(i)[1]) + " lies outside "
                             + disc.geometry().plate_description()
                             + "; keep the line on the plate."));
  }


  std::vector<double>
  ProfileOutput::times_not_reached(const double end_time, const double dt) const
  {
    return n_points > 0 ? times.not_reached(end_time, dt)
                        : std::vector<double>();
  }


  void
  ProfileOutput::warn_of_times_not_reached(const double   end_time,
                                           const double   dt,
                                           const MPI_Comm comm) const
  {
    const auto late = times_not_reached(end_time, dt);
    if (late.empty() || Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    // In the unit the scene gives the times in.
    const double      t0   = units.scale(PhysicalUnits::Quantity::time);
    const std::string unit = units.is_physical() ? " s" : "";
    std::cerr << "liftoff: warning: Output/Profile times";
    for (const double tau : late)
      std::cerr << ' ' << format_number(t0 * tau);
    std::cerr << unit << " lie beyond Time integration/End time = "
              << format_number(t0 * end_time) << unit
              << "; no profile is written for them." << std::endl;
  }


  void
  ProfileOutput::setup(const SceneView &scene, const std::string &directory)
  {
    const Discretization &disc = scene.discretization;
    times.reset();
    mesh_changed(scene);
    if (n_points == 0)
      return;

    // The file appears with the first profile.
    file.open(directory.empty() ? "" : directory + "/profiles.csv",
              rewrite_interval,
              disc.mpi_communicator);
    using Quantity = PhysicalUnits::Quantity;
    file.stream() << (units.is_physical() ? "t" : "tau")
                  << units.unit(Quantity::time) << ",s"
                  << units.unit(Quantity::length) << ",x"
                  << units.unit(Quantity::length) << ",y"
                  << units.unit(Quantity::length) << ",w"
                  << units.unit(Quantity::deflection) << '\n';
  }


  void
  ProfileOutput::mesh_changed(const SceneView &scene)
  {
    const Discretization &disc = scene.discretization;
    discretization             = &disc;
    points.clear();
    located.clear();
    if (rider.empty())
      locate_points(0);
  }


  void
  ProfileOutput::locate_points(const double tau)
  {
    const PlateGeometry &geometry = discretization->geometry();
    points.clear();
    located.clear();
    line = line_at(tau);
    for (unsigned int i = 0; i < n_points; ++i)
      if (geometry.is_on_plate(line[i]))
        {
          points.emplace_back(*discretization,
                              geometry.to_modelled_part(line[i]));
          located.push_back(i);
        }
  }


  void
  ProfileOutput::execute(const StepData &step)
  {
    const double           tau = step.state.clock.tau();
    const double           dt  = step.state.clock.time_step();
    const LA::MPI::Vector &u   = step.state.ghosted_u;
    if (n_points == 0)
      return;
    if (!times.is_due(tau, dt))
      return;

    if (!rider.empty())
      locate_points(tau);
    std::vector<double> w;
    for (const auto &p : points)
      w.push_back(p.local_value(u));
    Utilities::MPI::sum(w, discretization->mpi_communicator, w);
    using Quantity       = PhysicalUnits::Quantity;
    const double  length = units.scale(Quantity::length);
    std::ostream &out    = file.stream();
    out << std::setprecision(12);
    for (unsigned int k = 0; k < located.size(); ++k)
      {
        const unsigned int i = located[k];
        const Point<2>    &p = line[i];
        out << units.scale(Quantity::time) * tau << ','
            << length * point(i).distance(start) << ',' << length * p[0] << ','
            << length * p[1] << ',' << units.scale(Quantity::deflection) * w[k]
            << '\n';
      }
    file.flush();
  }


  void
  ProfileOutput::save(OutputArchive &archive) const
  {
    times.save(archive);
    archive << file.text();
  }


  void
  ProfileOutput::load(InputArchive &archive)
  {
    std::string text;
    times.load(archive);
    archive >> text;
    file.replace(text);
    file.hold();
  }


  void
  ProfileOutput::flush()
  {
    if (n_points > 0)
      file.flush();
  }
} // namespace liftoff
