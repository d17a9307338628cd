#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/selection.h>
#include <liftoff/loads/deflectometer.h>
#include <liftoff/loads/patch_load.h>

#include <cmath>
#include <sstream>

namespace liftoff
{
  namespace
  {
    const Selection<Deflectometer::Pulse> pulse_shapes = {
      {"half-sine", Deflectometer::Pulse::half_sine},
      {"haversine", Deflectometer::Pulse::haversine},
      {"constant", Deflectometer::Pulse::constant}};


    Point<2>
    two_numbers(const std::string &text, const std::string &entry)
    {
      const std::string message =
        entry + " = <" + text + "> must be 'x, y', two finite numbers.";
      const std::vector<double> v = numbers_or_refuse(text, message);
      AssertThrow(v.size() == 2 && std::isfinite(v[0]) && std::isfinite(v[1]),
                  ExcMessage(message));
      return Point<2>(v[0], v[1]);
    }
  } // namespace


  void
  Deflectometer::declare_parameters(ParameterHandler  &prm,
                                    const std::string &section)
  {
    prm.enter_subsection(section);
    prm.declare_entry("Peak force",
                      "0",
                      Patterns::Double(),
                      "The pulse's peak force on the loading plate, in units "
                      "of F0; 0 switches the test off."
                        + quantity("force"));
    prm.declare_entry("Plate diameter",
                      "0.3",
                      Patterns::Double(),
                      "Diameter of the loading plate, > 0 (0.3 m: the usual "
                      "300 mm plate). Every size in liftoff is a width or a "
                      "diameter (a disc's Size, a Wheel size)."
                        + quantity("length"));
    prm.declare_entry("Plate radius",
                      "",
                      Patterns::Anything(),
                      "Not read: sizes are diameters, so a scene that sets "
                      "this is refused; give Plate diameter, twice the "
                      "radius."
                        + quantity("length"));
    prm.declare_entry("Position",
                      "0, 0",
                      Patterns::List(Patterns::Double(), 2, 2, ","),
                      "x, y of the loading plate's centre on the full plate."
                        + quantity("position"));
    prm.declare_entry("Pulse shape",
                      "half-sine",
                      pulse_shapes.pattern(),
                      "h(tau) for 0 <= tau <= Duration, 0 after: half-sine "
                      "sin(pi tau / T), haversine sin^2(pi tau / T); "
                      "constant: the peak force at all times (a static "
                      "analysis, which solves at tau = 0).");
    prm.declare_entry("Duration",
                      "1",
                      Patterns::Double(),
                      "T, the pulse's duration, > 0 (about 25 to 30 ms)."
                        + quantity("time"));
    prm.declare_entry("Sensor offsets",
                      "",
                      Patterns::List(Patterns::Double(), 0),
                      "Distances of the sensors from the plate's centre, "
                      ">= 0; empty: the SHRP set 0, 203, 305, 457, 610, 914, "
                      "1219, 1524 mm in an SI scene (a dimensionless scene "
                      "must give them)."
                        + quantity("length"));
    prm.declare_entry("Sensor direction",
                      "1, 0",
                      Patterns::List(Patterns::Double(), 2, 2, ","),
                      "The direction from the plate's centre along which the "
                      "sensors lie (not 0; its length does not matter)."
                        + quantity("number"));
    prm.leave_subsection();
  }


  Deflectometer
  Deflectometer::parse(ParameterHandler &prm, const std::string &section)
  {
    Deflectometer test;
    test.name       = "Loads/" + section;
    const auto in   = [&](const std::string &e) { return test.name + "/" + e; };
    test.peak_force = prm.get_double("Peak force");
    AssertThrow(prm.get("Plate radius").find_first_not_of(" \t")
                  == std::string::npos,
                ExcMessage(in("Plate radius")
                           + " is set, but every size in liftoff is a width "
                             "or a diameter (a disc's Size, a Wheel size): "
                             "give Plate diameter, twice the radius, "
                             "instead."));
    const double diameter = prm.get_double("Plate diameter");
    AssertThrow(diameter > 0 && std::isfinite(diameter),
                ExcMessage(in("Plate diameter") + " = "
                           + format_number(diameter)
                           + " must be a finite number > 0."));
    test.radius   = diameter / 2;
    test.duration = prm.get_double("Duration");
    AssertThrow(test.duration > 0 && std::isfinite(test.duration),
                ExcMessage(in("Duration") + " = " + format_number(test.duration)
                           + " must be a finite number > 0."));
    test.pulse  = pulse_shapes.parse(prm.get("Pulse shape"), in("Pulse shape"));
    test.centre = two_numbers(prm.get("Position"), in("Position"));
    const std::string offsets = prm.get("Sensor offsets");
    if (offsets.find_first_not_of(" \t") != std::string::npos)
      test.offsets = numbers_or_refuse(offsets,
                                       in("Sensor offsets") + " = <" + offsets
                                         + "> must be numbers.");
    for (const double d : test.offsets)
      AssertThrow(d >= 0 && std::isfinite(d),
                  ExcMessage(in("Sensor offsets") + " = <" + offsets
                             + "> must be finite numbers >= 0."));
    const Point<2> d =
      two_numbers(prm.get("Sensor direction"), in("Sensor direction"));
    AssertThrow(d.norm() > 0,
                ExcMessage(in("Sensor direction") + " = <"
                           + prm.get("Sensor direction")
                           + "> must not be the zero vector."));
    test.direction = d / d.norm();
    return test;
  }


  std::unique_ptr<Load>
  Deflectometer::read(ParameterHandler &prm, const std::string &section)
  {
    const Deflectometer test = parse(prm, section);
    const std::string  &name = test.name;
    const double        pressure =
      test.peak_force / (M_PI * test.radius * test.radius);
    auto path = LoadPath::standing_at(name + "/Position", test.centre);
    return std::make_unique<PatchLoad>(
      name,
      pressure,
      LoadHistory(test.history_expression(), name + "/Pulse shape"),
      path,
      PatchLoad::Shape::disc,
      std::array<double, 2>{{2 * test.radius, 2 * test.radius}},
      Tensor<1, 2>());
  }


  bool
  Deflectometer::is_on() const
  {
    return peak_force != 0.0;
  }


  std::string
  Deflectometer::history_expression() const
  {
    if (pulse == Pulse::constant)
      return "1";
    // Full precision: the pulse ends exactly at T.
    std::ostringstream number;
    number.precision(17);
    number << M_PI / duration << "*tau";
    const std::string  s = "sin(" + number.str() + ")";
    std::ostringstream end;
    end.precision(17);
    end << duration;
    return "if(tau <= " + end.str() + ", "
           + (pulse == Pulse::half_sine ? s : s + "^2") + ", 0)";
  }


  std::vector<Point<2>>
  Deflectometer::sensor_points(const std::vector<double> &given) const
  {
    std::vector<Point<2>> points;
    for (const double d : given)
      points.push_back(centre + d * direction);
    return points;
  }
} // namespace liftoff
