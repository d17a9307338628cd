#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/fem/load_set.h>
#include <liftoff/fem/patch_integrator.h>
#include <liftoff/fem/point_functional.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <optional>
#include <regex>
#include <sstream>

namespace liftoff
{
  namespace
  {
    std::string
    subsection_name(const std::string &kind, const unsigned int i)
    {
      return kind + " " + std::to_string(i);
    }

    bool
    names_tau(const std::string &expression)
    {
      static const std::regex tau("(^|[^A-Za-z0-9_])tau([^A-Za-z0-9_]|$)");
      return std::regex_search(expression, tau);
    }

    Point<2>
    mirrored(const Point<2> &p, const unsigned int axis)
    {
      Point<2> q = p;
      q[axis]    = -q[axis];
      return q;
    }

    // Edges of the full plate, by their boundary ids.
    const Selection<unsigned int> plate_edges = {
      {"Left", PlateGeometry::left_edge},
      {"Right", PlateGeometry::right_edge},
      {"Bottom", PlateGeometry::bottom_edge},
      {"Top", PlateGeometry::top_edge}};

    // The shapes of a patch load and of a vehicle's wheels.
    const Selection<LoadSet::Shape> patch_shapes = {
      {"rectangle", LoadSet::Shape::rectangle},
      {"disc", LoadSet::Shape::disc}};
    const Selection<LoadSet::Shape> wheel_shapes = {
      {"point", LoadSet::Shape::point},
      {"rectangle", LoadSet::Shape::rectangle},
      {"disc", LoadSet::Shape::disc}};

    const char *path_documentation =
      "x(tau); y(tau): two muParser expressions in tau separated by ';', "
      "the position on the full plate at time tau (e.g. -0.7 + 0.5*tau; 0, "
      "a constant speed 0.5 along y = 0). The load vector is built at the "
      "current position at every step; whatever is off the plate carries "
      "nothing, and a path that never brings the load onto the plate at a "
      "step time is refused.";

    // One or two widths; patch_size() decides how many the shape takes.
    const Patterns::List size_pattern(Patterns::Double(0.0), 1, 2, ",");

    void
    declare_path(ParameterHandler &prm, const std::string &default_value)
    {
      prm.declare_entry("Path",
                        default_value,
                        Patterns::Anything(),
                        path_documentation + quantity("length"));
    }

    // The comma-separated numbers of `text`, or refused with `message`.
    std::vector<double>
    numbers_or_refuse(const std::string &text, const std::string &message)
    {
      try
        {
          return Utilities::string_to_double(
            Utilities::split_string_list(text, ','));
        }
      catch (...)
        {
          AssertThrow(false, ExcMessage(message));
        }
      return {};
    }


    // "a, b" of a rectangle, "d" of a disc: both widths, or refused.
    std::array<double, 2>
    patch_size(const std::string   &text,
               const LoadSet::Shape shape,
               const std::string   &parameter)
    {
      const std::string message =
        parameter + " = <" + text
        + "> must be 'a, b' (widths along x and y, > 0) for a rectangle or "
          "'d' (the diameter, > 0) for a disc.";
      const std::vector<double> v = numbers_or_refuse(text, message);
      const unsigned int n = (shape == LoadSet::Shape::rectangle ? 2 : 1);
      AssertThrow(v.size() == n && v[0] > 0 && v[n - 1] > 0
                    && std::isfinite(v[0]) && std::isfinite(v[n - 1]),
                  ExcMessage(message));
      return {{v[0], v[n - 1]}};
    }

    // "x1, y1, x2, y2" of a line load's Segment; empty: none (an Edge).
    std::optional<std::array<Point<2>, 2>>
    parse_segment(const std::string &text, const std::string &parameter)
    {
      if (text.empty())
        return std::nullopt;
      const std::string message =
        parameter + " = <" + abbreviated(text)
        + "> must be 'x1, y1, x2, y2', the ends of the line (finite "
          "numbers, two different points), or empty for an Edge.";
      const std::vector<double> v = numbers_or_refuse(text, message);
      AssertThrow(v.size() == 4
                    && std::all_of(v.begin(),
                                   v.end(),
                                   [](double x) { return std::isfinite(x); }),
                  ExcMessage(message));
      const std::array<Point<2>, 2> ends = {
        {Point<2>(v[0], v[1]), Point<2>(v[2], v[3])}};
      AssertThrow(ends[0].distance(ends[1]) > 0, ExcMessage(message));
      return ends;
    }


    // "Point load 2" -> "point_load_2", the prefix of history columns.
    std::string
    column_name(const std::string &section)
    {
      std::string name = Utilities::replace_in_string(section, " ", "_");
      std::transform(name.begin(), name.end(), name.begin(), [](char c) {
        return static_cast<char>(std::tolower(c));
      });
      return name;
    }

    bool
    nearly_equal(const double a, const double b)
    {
      return std::abs(a - b)
             <= 1e-10 * std::max(1.0, std::abs(a) + std::abs(b));
    }

    std::string
    time_text(const double tau)
    {
      std::ostringstream text;
      text << std::setprecision(8) << tau;
      return text.str();
    }

    // Every load has a Magnitude (whose unit depends on its kind) and a
    // Time history; `declare_own` adds the entries of its kind.
    void
    declare_load(ParameterHandler            &prm,
                 const std::string           &section,
                 const std::string           &unit,
                 const std::string           &unit_name,
                 const std::function<void()> &declare_own)
    {
      prm.enter_subsection(section);
      prm.declare_entry("Magnitude",
                        "0",
                        Patterns::Double(),
                        unit + "; 0 switches the load off."
                          + quantity(unit_name));
      declare_own();
      prm.declare_entry(
        "Time history",
        "1",
        Patterns::Anything(),
        "h(tau), a muParser expression in tau (dimensionless time); the load "
        "is Magnitude * h(tau). Examples: 1 (suddenly applied), tau (linear "
        "ramp), sin(2*pi*tau/2.5) (pulsating), if(tau<0.1,1,0) (pulse)."
          + quantity("number"));
      prm.leave_subsection();
    }
    // Whether rectangle b is rectangle a mirrored normal to `axis`.
    bool
    is_mirrored_rectangle(const BoundingBox<2> &a,
                          const BoundingBox<2> &b,
                          const unsigned int    axis)
    {
      const Point<2> lo = a.get_boundary_points().first;
      const Point<2> hi = a.get_boundary_points().second;
      // Mirroring swaps the roles of the corners along the axis.
      Point<2> image_lo = lo, image_hi = hi;
      image_lo[axis] = -hi[axis];
      image_hi[axis] = -lo[axis];
      return (image_lo - b.get_boundary_points().first).norm() <= 1e-12
             && (image_hi - b.get_boundary_points().second).norm() <= 1e-12;
    }
    // Whether segment b is segment a mirrored normal to `axis`, either
    // way round.
    bool
    is_mirrored_segment(const PatchIntegrator::Segment &a,
                        const PatchIntegrator::Segment &b,
                        const unsigned int              axis)
    {
      const Point<2> start = mirrored(a.start, axis),
                     end   = mirrored(a.end, axis);
      const auto near      = [](const Point<2> &p, const Point<2> &q) {
        return p.distance(q) < 1e-12;
      };
      return (near(start, b.start) && near(end, b.end))
             || (near(start, b.end) && near(end, b.start));
    }


    // "dx, dy, share; ..." of a vehicle, or refused naming `parameter`.
    std::vector<std::array<double, 3>>
    parse_wheels(const std::string &text, const std::string &parameter)
    {
      const std::string message =
        parameter + " = <" + abbreviated(text)
        + "> must be 'dx, dy, share' per wheel, separated by ';' (finite "
          "numbers).";
      std::vector<std::array<double, 3>> wheels;
      try
        {
          for (const auto &wheel : Utilities::split_string_list(text, ';'))
            {
              const std::vector<double> v = Utilities::string_to_double(
                Utilities::split_string_list(wheel, ','));
              AssertThrow(v.size() == 3, ExcMessage(message));
              wheels.push_back({{v[0], v[1], v[2]}});
            }
        }
      catch (...)
        {
          AssertThrow(false, ExcMessage(message));
        }
      AssertThrow(!wheels.empty(), ExcMessage(message));
      double total_share = 0;
      for (const auto &wheel : wheels)
        {
          for (const double v : wheel)
            AssertThrow(std::isfinite(v), ExcMessage(message));
          // A wheel presses; a vehicle whose wheels carry nothing is no
          // load at all, which a scene never means.
          AssertThrow(wheel[2] >= 0,
                      ExcMessage(parameter + " = <" + abbreviated(text)
                                 + ">: a wheel's share must be >= 0."));
          total_share += wheel[2];
        }
      AssertThrow(total_share > 0,
                  ExcMessage(parameter + " = <" + abbreviated(text)
                             + ">: the wheels' shares add up to 0, so the "
                               "vehicle carries no load; give each wheel "
                               "its share of Magnitude (> 0 in all)."));
      return wheels;
    }

    // The i-th patch load and vehicle, whose entries only moving loads
    // have.
    void
    declare_moving_loads(ParameterHandler &prm, const unsigned int i)
    {
      declare_load(prm,
                   subsection_name("Patch load", i),
                   "Uniform pressure in units of F0 / L^2",
                   "pressure",
                   [&]() {
                     prm.declare_entry("Shape",
                                       "rectangle",
                                       patch_shapes.pattern(),
                                       "What the pressure covers (a tyre's "
                                       "contact area), centred on the path.");
                     prm.declare_entry("Size",
                                       "0.1, 0.1",
                                       size_pattern,
                                       "'a, b', the widths along x and y of a "
                                       "rectangle, or 'd', a disc's diameter."
                                         + quantity("length"));
                     declare_path(prm, "0; 0");
                   });
      declare_load(
        prm,
        subsection_name("Vehicle", i),
        "Force in units of F0 that each wheel's share multiplies",
        "force",
        [&]() {
          declare_path(prm, "0; 0");
          prm.declare_entry(
            "Wheels",
            "0, 0, 1",
            Patterns::Anything(),
            "dx, dy, share; dx, dy, share; ...: each wheel's offset from the "
            "path's point and its share of Magnitude; the wheels move "
            "together."
              + quantity("length, length, number"));
          prm.declare_entry("Wheel shape",
                            "point",
                            wheel_shapes.pattern(),
                            "A point load, or a patch load of the wheel's "
                            "force spread over its area.");
          prm.declare_entry("Wheel size",
                            "0.1, 0.1",
                            size_pattern,
                            "As Size of a Patch load, for patch wheels."
                              + quantity("length"));
        });
    }

    // The i-th line load: along an Edge or a Segment, standing or moving.
    void
    declare_line_load(ParameterHandler &prm, const unsigned int i)
    {
      declare_load(prm,
                   subsection_name("Line load", i),
                   "Force per unit length in units of F0 / L",
                   "force per length",
                   [&]() {
                     prm.declare_entry("Edge",
                                       "Right",
                                       plate_edges.pattern(),
                                       "Edge of the full plate that carries "
                                       "the load, when Segment is empty.");
                     prm.declare_entry(
                       "Segment",
                       "",
                       Patterns::Anything(),
                       "x1, y1, x2, y2: a straight line anywhere on the full "
                       "plate that carries the load instead of an Edge; with "
                       "a Path its ends are offsets from the path's point and "
                       "the line moves with it. Each cell it crosses is "
                       "integrated along its piece (exactly for intensities "
                       "of degree up to 3 along the line); a piece off the "
                       "plate carries nothing."
                         + quantity("length"));
                     declare_path(prm, "");
                     prm.declare_entry("Intensity",
                                       "1",
                                       Patterns::Anything(),
                                       "f(x, y, tau) along the line, muParser."
                                         + quantity("number"));
                   });
    }

    /// The plate as messages about loads off it name it.
    std::string
    plate_named(const PlateGeometry &geometry)
    {
      return geometry.shape() == PlateShape::rectangle
               ? std::string("the plate [-1/2, 1/2] x [-mu/2, mu/2]")
               : geometry.plate_description();
    }
  } // namespace


  double
  LoadSet::Load::intensity_at(const Point<2> &p, const double tau) const
  {
    intensity->set_time(tau);
    return intensity->value(p);
  }


  Point<2>
  LoadSet::Load::position_at(const double tau) const
  {
    if (path == nullptr)
      return position + offset;
    return Point<2>(path->value(Point<1>(tau), 0),
                    path->value(Point<1>(tau), 1))
           + offset;
  }


  PatchIntegrator::Segment
  LoadSet::Load::line_at(const BoundingBox<2> &plate, const double tau) const
  {
    if (segment)
      return segment_at(tau);
    // Edges 0, 1 lie at x = -1/2, 1/2; edges 2, 3 at y = -mu/2, mu/2.
    const unsigned int normal = edge / 2;
    Point<2>           start  = plate.get_boundary_points().first;
    Point<2>           end    = plate.get_boundary_points().second;
    if (edge % 2 == 0)
      end[normal] = start[normal];
    else
      start[normal] = end[normal];
    return {start, end};
  }


  PatchIntegrator::Segment
  LoadSet::Load::segment_at(const double tau) const
  {
    // A line without a Path stands at position_at() = (0, 0).
    const Tensor<1, 2> shift = position_at(tau) - Point<2>();
    return {(*segment)[0] + shift, (*segment)[1] + shift};
  }


  bool
  LoadSet::Load::touches(const PlateGeometry &geometry, const double tau) const
  {
    const Point<2> p = position_at(tau);
    if (kind == Kind::point)
      return geometry.is_on_plate(p);
    const BoundingBox<2> plate = geometry.plate_box();
    if (geometry.shape() != PlateShape::rectangle)
      {
        // Other outlines are asked point by point.
        std::vector<Point<2>> samples;
        if (kind == Kind::line)
          {
            const auto line = line_at(plate, tau);
            for (unsigned int k = 0; k <= 64; ++k)
              samples.push_back(line.start
                                + k / 64.0 * (line.end - line.start));
            return std::any_of(samples.begin(),
                               samples.end(),
                               [&](const Point<2> &x) {
                                 return geometry.is_on_plate(x);
                               });
          }
        // A pressure's box or a patch about its centre.
        const BoundingBox<2> box =
          kind == Kind::pressure ? region_of(*this, plate) : BoundingBox<2>();
        const Point<2> centre = kind == Kind::pressure ? box.center() : p;
        const std::array<double, 2> sides = {
          {kind == Kind::pressure ? box.side_length(0) : size[0],
           kind == Kind::pressure ? box.side_length(1) : size[1]}};
        for (unsigned int i = 0; i <= 16; ++i)
          for (unsigned int j = 0; j <= 16; ++j)
            {
              const Tensor<1, 2> offset(
                {(i / 16.0 - 0.5) * sides[0], (j / 16.0 - 0.5) * sides[1]});
              if (kind != Kind::patch || shape != Shape::disc
                  || offset.norm() <= sides[0] / 2)
                samples.push_back(centre + offset);
            }
        return std::any_of(samples.begin(),
                           samples.end(),
                           [&](const Point<2> &x) {
                             return geometry.is_on_plate(x);
                           });
      }
    if (kind == Kind::line)
      return PatchIntegrator::length_inside(line_at(plate, tau), plate) > 0;
    // Some area on the plate: the nearest point of the plate lies within
    // the disc, or the rectangle overlaps the plate.
    Point<2> nearest;
    bool     overlaps = true;
    for (unsigned int d = 0; d < 2; ++d)
      {
        nearest[d] =
          std::clamp(p[d], plate.lower_bound(d), plate.upper_bound(d));
        overlaps = overlaps && std::abs(p[d] - nearest[d]) < size[d] / 2;
      }
    return shape == Shape::disc ? (p - nearest).norm() < size[0] / 2 : overlaps;
  }


  void
  LoadSet::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry(
      "Self weight",
      "0",
      Patterns::Double(0.0, 1e100),
      "q, the plate's weight per unit area in units of F0 / L^2, the unit "
      "of every pressure (>= 0, at most 1e100, beyond which its settled "
      "state overflows; 0: a weightless plate): a uniform pressure "
      "that acts from before tau = 0. "
      "A time integration starts from the static equilibrium under it (the "
      "slab settled on its bed, in contact wherever q pre-compresses the "
      "springs), with the initial displacement added to that equilibrium; "
      "the other loads act on top. A static analysis adds it to the loads."
        + quantity("self weight"));
    for (unsigned int i = 1; i <= max_loads_per_kind; ++i)
      declare_numbered_loads(prm, i);
    prm.leave_subsection();
  }


  void
  LoadSet::declare_numbered_loads(ParameterHandler &prm, const unsigned int i)
  {
    declare_load(prm,
                 subsection_name("Point load", i),
                 "Force in units of F0",
                 "force",
                 [&]() {
                   prm.declare_entry(
                     "Position",
                     "0, 0",
                     Patterns::List(Patterns::Double(), 2, 2, ","),
                     "x, y on the full plate (any point, not only "
                     "nodes), if Path is empty."
                       + quantity("position"));
                   declare_path(prm, "");
                 });
    declare_moving_loads(prm, i);
    declare_load(prm,
                 subsection_name("Pressure", i),
                 "Pressure in units of F0 / L^2",
                 "pressure",
                 [&]() {
                   prm.declare_entry(
                     "Region",
                     "whole plate",
                     Patterns::Anything(),
                     "'whole plate' or 'x_min, x_max, y_min, y_max' on "
                     "the full plate, anywhere on the mesh: each cell "
                     "the rectangle cuts is integrated over its part "
                     "inside (exactly for intensities of degree up to "
                     "p+3 in x and in y)."
                       + quantity("length"));
                   prm.declare_entry("Intensity",
                                     "1",
                                     Patterns::Anything(),
                                     "f(x, y, tau), muParser; the pressure is "
                                     "Magnitude * f * h(tau)."
                                       + quantity("number"));
                 });
    declare_line_load(prm, i);
  }


  LoadSet::Load
  LoadSet::read_timed(ParameterHandler  &prm,
                      const Kind         kind,
                      const std::string &section)
  {
    Load load;
    load.kind       = kind;
    load.name       = "Loads/" + section;
    load.path_owner = load.name;
    load.magnitude  = prm.get_double("Magnitude");
    // A load that is off (Magnitude 0) is checked all the same: a
    // broken expression is an error whether or not it is used yet.
    load.history_expression = prm.get("Time history");
    load.history            = parse_expression<1>(
      load.name + "/Time history", load.history_expression, 1, "tau", false);
    if (kind != Kind::pressure)
      {
        load.path_expression = prm.get("Path");
        if (!load.path_expression.empty())
          {
            load.path = parse_expression<1>(
              load.name + "/Path", load.path_expression, 2, "tau", false);
            load.moves = names_tau(load.path_expression);
          }
      }
    return load;
  }


  LoadSet::Load
  LoadSet::read_load(ParameterHandler  &prm,
                     const Kind         kind,
                     const std::string &section) const
  {
    // Regions are checked against the plate once the plate is known; here
    // only their form.
    const BoundingBox<2> unbounded(
      std::make_pair(Point<2>(-1e300, -1e300), Point<2>(1e300, 1e300)));
    Load load = read_timed(prm, kind, section);
    if (kind == Kind::point)
      {
        const auto xy = Utilities::string_to_double(
          Utilities::split_string_list(prm.get("Position"), ','));
        load.position = Point<2>(xy[0], xy[1]);
      }
    else if (kind == Kind::patch)
      {
        AssertThrow(load.path != nullptr,
                    ExcMessage(load.name + "/Path must not be empty."));
        load.shape = patch_shapes.parse(prm.get("Shape"), load.name + "/Shape");
        load.size =
          patch_size(prm.get("Size"), load.shape, load.name + "/Size");
      }
    else
      {
        load.intensity_expression = prm.get("Intensity");
        load.intensity = parse_expression<2>(load.name + "/Intensity",
                                             load.intensity_expression,
                                             1,
                                             "x,y,tau",
                                             true);
        load.intensity_depends_on_time = names_tau(load.intensity_expression);
        if (kind == Kind::pressure)
          {
            load.region = prm.get("Region");
            region_of(load, unbounded);
          }
        else
          {
            load.edge = plate_edges.parse(prm.get("Edge"), load.name + "/Edge");
            load.segment =
              parse_segment(prm.get("Segment"), load.name + "/Segment");
            AssertThrow(load.segment || load.path == nullptr,
                        ExcMessage(load.name
                                   + "/Path moves the line of its Segment, "
                                     "but Segment is empty (the line is an "
                                     "Edge, which stays): give a Segment."));
          }
      }
    return load;
  }


  void
  LoadSet::read_vehicle(ParameterHandler &prm, const std::string &section)
  {
    // The wheels are point or patch loads that share the vehicle's path
    // and time history; a wheel's force spread over its area is a pressure.
    Load              vehicle     = read_timed(prm, Kind::point, section);
    const std::string wheels_text = prm.get("Wheels");
    const Shape       shape =
      wheel_shapes.parse(prm.get("Wheel shape"), vehicle.name + "/Wheel shape");
    const std::array<double, 2> size =
      (shape == Shape::point ? std::array<double, 2>{{0, 0}}
                             : patch_size(prm.get("Wheel size"),
                                          shape,
                                          vehicle.name + "/Wheel size"));
    AssertThrow(vehicle.path != nullptr,
                ExcMessage(vehicle.name + "/Path must not be empty."));
    const std::vector<std::array<double, 3>> wheels =
      parse_wheels(wheels_text, vehicle.name + "/Wheels");
    if (vehicle.magnitude == 0.0)
      return;

    const double area =
      (shape == Shape::disc ? M_PI / 4 * size[0] * size[0] : size[0] * size[1]);
    Track track{column_name(section), {}};
    for (unsigned int k = 0; k < wheels.size(); ++k)
      {
        Load wheel;
        wheel.kind  = (shape == Shape::point ? Kind::point : Kind::patch);
        wheel.name  = vehicle.name + ", wheel " + std::to_string(k + 1);
        wheel.shape = shape;
        wheel.size  = size;
        wheel.magnitude =
          vehicle.magnitude * wheels[k][2] / (shape == Shape::point ? 1 : area);
        wheel.history_expression = vehicle.history_expression;
        wheel.history            = parse_expression<1>(
          wheel.name, wheel.history_expression, 1, "tau", false);
        wheel.path_expression = vehicle.path_expression;
        wheel.path            = vehicle.path;
        wheel.path_owner      = vehicle.name;
        wheel.moves           = vehicle.moves;
        wheel.offset          = Tensor<1, 2>({wheels[k][0], wheels[k][1]});
        track.members.push_back(loads.size());
        loads.push_back(std::move(wheel));
      }
    tracks.push_back(std::move(track));
  }


  void
  LoadSet::parse_parameters(ParameterHandler &prm)
  {
    loads.clear();
    tracks.clear();
    prm.enter_subsection("Loads");
    const std::array<std::pair<Kind, std::string>, 4> kinds = {
      {{Kind::point, "Point load"},
       {Kind::pressure, "Pressure"},
       {Kind::line, "Line load"},
       {Kind::patch, "Patch load"}}};
    for (const auto &[kind, kind_name] : kinds)
      for (unsigned int i = 1; i <= max_loads_per_kind; ++i)
        {
          const std::string section = subsection_name(kind_name, i);
          prm.enter_subsection(section);
          Load load = read_load(prm, kind, section);
          if (load.magnitude != 0.0)
            {
              // A moving load is followed in history.csv under its name.
              if (load.moves)
                tracks.push_back({column_name(section),
                                  {static_cast<unsigned int>(loads.size())}});
              loads.push_back(std::move(load));
            }
          prm.leave_subsection();
        }
    for (unsigned int i = 1; i <= max_loads_per_kind; ++i)
      {
        const std::string section = subsection_name("Vehicle", i);
        prm.enter_subsection(section);
        read_vehicle(prm, section);
        prm.leave_subsection();
      }
    // The pattern refuses a negative, nan or infinite weight.
    const double self_weight = prm.get_double("Self weight");
    if (self_weight != 0.0)
      {
        // A uniform pressure on the whole plate that is always on.
        Load load;
        load.kind               = Kind::pressure;
        load.name               = "Loads/Self weight";
        load.magnitude          = self_weight;
        load.history_expression = "1";
        load.history            = parse_expression<1>(
          load.name, load.history_expression, 1, "tau", false);
        load.intensity_expression = "1";
        load.intensity            = parse_expression<2>(
          load.name, load.intensity_expression, 1, "x,y,tau", true);
        load.region       = "whole plate";
        load.is_permanent = true;
        loads.push_back(std::move(load));
      }
    prm.leave_subsection();
  }


  bool
  LoadSet::has_permanent_loads() const
  {
    return std::any_of(loads.begin(), loads.end(), [](const Load &load) {
      return load.is_permanent;
    });
  }


  void
  LoadSet::assemble_permanent(LA::MPI::Vector &load_vector) const
  {
    assemble_selected(
      0.0, [](const Load &load) { return load.is_permanent; }, load_vector);
  }


  bool
  LoadSet::is_empty() const
  {
    return loads.empty() && body_force == nullptr;
  }


  std::vector<std::vector<BoundingBox<2>>>
  LoadSet::regions_in_windows(const double       tau,
                              const double       window,
                              const unsigned int n_windows) const
  {
    std::vector<std::vector<BoundingBox<2>>> regions;
    for (unsigned int k = 0; k < n_windows; ++k)
      regions.push_back(
        regions_under_loads(tau + k * window, tau + (k + 1) * window));
    return regions;
  }


  std::vector<BoundingBox<2>>
  LoadSet::regions_under_loads(const double tau_begin,
                               const double tau_end) const
  {
    std::vector<BoundingBox<2>> regions;
    for (const auto &load : loads)
      {
        // Pressures, and lines along edges, cover whole stretches of the
        // plate; the mesh is refined around what is concentrated.
        if (load.kind == Kind::pressure
            || (load.kind == Kind::line && !load.segment))
          continue;
        // A path over the interval: its positions at nine times (a path
        // that bends between them is covered up to that sampling).
        const unsigned int    n_samples = load.moves ? 9 : 1;
        std::vector<Point<2>> corners;
        for (unsigned int k = 0; k < n_samples; ++k)
          {
            const double tau =
              n_samples == 1
                ? tau_begin
                : tau_begin + (tau_end - tau_begin) * k / (n_samples - 1);
            if (load.kind == Kind::line)
              {
                const auto line = load.segment_at(tau);
                corners.insert(corners.end(), {line.start, line.end});
                continue;
              }
            const Point<2>     p = load.position_at(tau);
            const Tensor<1, 2> half({load.size[0] / 2, load.size[1] / 2});
            corners.insert(corners.end(), {p - half, p + half});
          }
        // A box off the meshed part touches no cell: a symmetric scene
        // has each load's image among its loads.
        regions.emplace_back(corners);
      }
    return regions;
  }


  std::vector<std::string>
  LoadSet::moving_load_names() const
  {
    std::vector<std::string> names;
    for (const Track &track : tracks)
      names.push_back(track.name);
    return names;
  }


  std::vector<double>
  LoadSet::moving_load_positions(const double tau) const
  {
    const PlateGeometry &geometry = discretization->geometry();
    std::vector<double>  values;
    for (const Track &track : tracks)
      {
        // The path's own point: a vehicle's wheels sit at offsets from it.
        const Load    &first = loads[track.members.front()];
        const Point<2> p     = first.position_at(tau) - first.offset;
        unsigned int   on    = 0;
        for (const unsigned int k : track.members)
          on += loads[k].touches(geometry, tau);
        values.insert(values.end(), {p[0], p[1], double(on)});
      }
    return values;
  }


  void
  LoadSet::require_path_on_plate(const Load                &load,
                                 const std::vector<double> &times,
                                 const PlateGeometry       &geometry) const
  {
    // The loads on this path: one, or a vehicle's wheels, of which one on
    // the plate is enough.
    bool touches = false;
    for (const double tau : times)
      {
        const Point<2> p = load.position_at(tau) - load.offset;
        AssertThrow(std::isfinite(p[0]) && std::isfinite(p[1]),
                    ExcMessage(load.path_owner + "/Path = <"
                               + load.path_expression + "> is not finite at "
                               + "tau = " + time_text(tau) + "."));
        for (const Load &other : loads)
          touches =
            touches
            || (other.path == load.path && other.touches(geometry, tau));
      }
    AssertThrow(touches,
                ExcMessage(load.path_owner + "/Path = <"
                           + abbreviated(load.path_expression)
                           + "> keeps the load off the plate at every step "
                             "time from tau = 0 to the End time: it would "
                             "carry nothing. Move the path onto "
                           + plate_named(geometry) + "."));
  }


  BoundingBox<2>
  LoadSet::region_of(const Load &load, const BoundingBox<2> &plate)
  {
    if (load.region == "whole plate")
      return plate;

    const std::string message =
      load.name + "/Region = <" + abbreviated(load.region)
      + "> must be 'whole plate' or 'x_min, x_max, y_min, y_max' with "
        "x_min < x_max, y_min < y_max, inside the plate [-1/2, 1/2] x [-mu/2, "
        "mu/2] (on other shapes: inside the outline's bounding box).";
    const std::vector<double> v = numbers_or_refuse(load.region, message);
    AssertThrow(v.size() == 4, ExcMessage(message));
    AssertThrow(v[0] < v[1] && v[2] < v[3], ExcMessage(message));
    const BoundingBox<2> box(
      std::make_pair(Point<2>(v[0], v[2]), Point<2>(v[1], v[3])));
    AssertThrow(plate.point_inside(box.get_boundary_points().first, 1e-12)
                  && plate.point_inside(box.get_boundary_points().second,
                                        1e-12),
                ExcMessage(message));
    return box;
  }


  void
  LoadSet::check_against(const Discretization &disc,
                         const double          time_step,
                         const unsigned int    n_steps) const
  {
    std::vector<double> times(n_steps + 1);
    for (unsigned int k = 0; k <= n_steps; ++k)
      times[k] = k * time_step;
    require_on_plate(times, disc.geometry());
    if (disc.geometry().symmetry() == Symmetry::full)
      return;
    check_symmetry(times, disc);
  }


  void
  LoadSet::require_on_plate(const std::vector<double> &times,
                            const PlateGeometry       &geometry) const
  {
    const BoundingBox<2> plate = geometry.plate_box();
    for (const auto &load : loads)
      {
        AssertThrow(geometry.shape() == PlateShape::rectangle
                      || load.kind != Kind::line || load.segment,
                    ExcMessage(load.name
                               + " acts along an edge of the rectangle, "
                                 "which "
                               + geometry.shape_setting()
                               + " does not have; use a Segment."));
        // Once per path (a vehicle's wheels share theirs).
        const auto first_on_path =
          std::find_if(loads.begin(), loads.end(), [&](const Load &other) {
            return other.path == load.path;
          });
        if (load.path != nullptr && &*first_on_path == &load)
          require_path_on_plate(load, times, geometry);
        else if (load.kind == Kind::point)
          {
            AssertThrow(geometry.is_on_plate(load.position),
                        ExcMessage(
                          load.name + "/Position = "
                          + format_point(load.position[0], load.position[1])
                          + " lies outside " + plate_named(geometry) + "."));
          }
        else if (load.kind == Kind::line && load.segment)
          {
            for (const Point<2> &end : *load.segment)
              AssertThrow(geometry.is_on_plate(end),
                          ExcMessage(load.name + "/Segment: its end "
                                     + format_point(end[0], end[1])
                                     + " lies outside " + plate_named(geometry)
                                     + "."));
          }
        if (load.kind == Kind::pressure)
          region_of(load, plate);
        // A box within a round or meshed outline's bounding box may still
        // miss the plate.
        if (load.kind == Kind::pressure
            && geometry.shape() != PlateShape::rectangle)
          {
            AssertThrow(load.touches(geometry, 0),
                        ExcMessage(load.name + "/Region = <"
                                   + abbreviated(load.region) + "> lies off "
                                   + plate_named(geometry)
                                   + ": it would carry nothing."));
          }
      }
  }


  void
  LoadSet::check_symmetry(const std::vector<double> &times,
                          const Discretization      &disc) const
  {
    const BoundingBox<2> plate = disc.geometry().plate_box();
    // A reduced model is right only if what it integrates is symmetric: the
    // loads are compared where they are evaluated (every quadrature point of
    // the full plate's mesh) and when (every time the run visits), not at
    // samples, which a load can dodge.
    const std::string symmetry =
      (disc.geometry().symmetry() == Symmetry::half ? "half" : "quarter");
    // Its intensity would have to be compared where the line is at each
    // step: not done, so refused rather than half checked.
    for (const auto &load : loads)
      AssertThrow(load.kind != Kind::line || load.path == nullptr,
                  ExcMessage("Discretization/Symmetry = " + symmetry
                             + " does not take a moving line load yet, and "
                             + load.name
                             + " has a Path; model the full plate."));
    // NaN equals nothing, not even its mirror image: a load that is not
    // finite somewhere is named as such before the comparison blames the
    // symmetry.
    for (const auto &load : loads)
      require_finite_values(load, times, plate, disc);
    for (const unsigned int axis : disc.geometry().symmetry_axes())
      for (const auto &load : loads)
        {
          bool has_image = false;
          for (const auto &other : loads)
            has_image =
              has_image
              || is_mirror_image(load, other, axis, plate, times, disc);
          AssertThrow(has_image,
                      ExcMessage(
                        "Discretization/Symmetry = " + symmetry
                        + " needs symmetric loads, but " + load.name
                        + " has no mirror image about the plane "
                        + (axis == 0 ? "x = 0" : "y = 0")
                        + " (compared at every quadrature point of the full "
                          "plate and every step time). Add the mirrored load "
                          "or model the full plate."));
        }
  }


  std::vector<Point<2>>
  LoadSet::full_plate_points_on(const Load           &load,
                                const BoundingBox<2> &plate,
                                const Discretization &disc)
  {
    // The full plate's mesh is the meshed part and its mirror images, and
    // the points of a region (or a line) on a mirrored cell are the images
    // of those of the mirrored region on the meshed cell.
    const PatchIntegrator           integrator(disc);
    const std::vector<unsigned int> axes = disc.geometry().symmetry_axes();
    std::vector<Point<2>>           points;
    for (unsigned int planes = 0; planes < (1u << axes.size()); ++planes)
      {
        const auto image = [&](const Point<2> &p) {
          Point<2> q = p;
          for (unsigned int k = 0; k < axes.size(); ++k)
            if (planes & (1u << k))
              q = mirrored(q, axes[k]);
          return q;
        };
        std::vector<Point<2>> found;
        if (load.kind == Kind::line)
          {
            const auto line = load.line_at(plate, 0);
            found           = integrator.quadrature_points(
              PatchIntegrator::Segment{image(line.start), image(line.end)});
          }
        else
          {
            const BoundingBox<2> region = region_of(load, plate);
            const Point<2>       a = image(region.get_boundary_points().first),
                           b       = image(region.get_boundary_points().second);
            found = integrator.quadrature_points(BoundingBox<2>(std::make_pair(
              Point<2>(std::min(a[0], b[0]), std::min(a[1], b[1])),
              Point<2>(std::max(a[0], b[0]), std::max(a[1], b[1])))));
          }
        for (const auto &p : found)
          points.push_back(image(p));
      }
    return points;
  }


  bool
  LoadSet::is_mirror_image(const Load                &load,
                           const Load                &other,
                           const unsigned int         axis,
                           const BoundingBox<2>      &plate,
                           const std::vector<double> &times,
                           const Discretization      &disc)
  {
    // Cheap comparisons first; all of these are the same on every rank.
    if (load.kind != other.kind
        || !nearly_equal(load.magnitude, other.magnitude))
      return false;
    switch (load.kind)
      {
      case Kind::point:
      case Kind::patch:
        if (load.shape != other.shape || load.size != other.size)
          return false;
        // A moving load's image follows the mirrored path at every time.
        for (const double tau : times)
          if ((mirrored(load.position_at(tau), axis) - other.position_at(tau))
                .norm()
              >= 1e-12)
            return false;
        break;
      case Kind::pressure:
        if (!is_mirrored_rectangle(region_of(load, plate),
                                   region_of(other, plate),
                                   axis))
          return false;
        break;
      case Kind::line:
        // Lines on a reduced model stand (check_symmetry()).
        if (!is_mirrored_segment(load.line_at(plate, 0),
                                 other.line_at(plate, 0),
                                 axis))
          return false;
        break;
      }

    for (const double tau : times)
      if (!nearly_equal(load.history->value(Point<1>(tau)),
                        other.history->value(Point<1>(tau))))
        return false;
    if (load.kind == Kind::point || load.kind == Kind::patch)
      return true;
    return have_mirrored_intensities(load,
                                     other,
                                     axis,
                                     full_plate_points_on(load, plate, disc),
                                     times,
                                     disc.mpi_communicator);
  }


  bool
  LoadSet::have_mirrored_intensities(const Load                  &load,
                                     const Load                  &other,
                                     const unsigned int           axis,
                                     const std::vector<Point<2>> &candidates,
                                     const std::vector<double>   &times,
                                     const MPI_Comm               comm)
  {
    // Intensities at every quadrature point the load covers, at every step
    // time if either names tau (otherwise once).
    const bool time_dependent =
      load.intensity_depends_on_time || other.intensity_depends_on_time;
    const auto   n_times  = time_dependent ? times.size() : 1;
    unsigned int is_image = 1;
    for (const auto &p : candidates)
      for (unsigned int k = 0; k < n_times && is_image; ++k)
        is_image =
          nearly_equal(load.intensity_at(p, times[k]),
                       other.intensity_at(mirrored(p, axis), times[k]));
    return Utilities::MPI::min(is_image, comm) == 1;
  }


  std::string
  LoadSet::non_finite_history(const Load &load, const double tau)
  {
    return load.name + "/Time history = <" + load.history_expression + "> is "
           + format_exact(load.history->value(Point<1>(tau)))
           + " at tau = " + time_text(tau) + ".";
  }


  std::string
  LoadSet::non_finite_intensity(const Load &load, const double tau)
  {
    return load.name + "/Intensity = <" + load.intensity_expression
           + "> times Magnitude is not a finite number at some quadrature "
             "point at tau = "
           + time_text(tau) + ".";
  }


  std::string
  LoadSet::non_finite_load(const double tau) const
  {
    LA::MPI::Vector scratch;
    discretization->reinit_vector(scratch);
    for (const auto &load : loads)
      {
        const double h = load.history->value(Point<1>(tau));
        if (!std::isfinite(h))
          return non_finite_history(load, tau);
        if (is_rebuilt_every_step(load))
          assemble_spatial_part(load, tau, scratch);
        else
          scratch = load.spatial_part;
        if (!is_finite(scratch))
          return load.kind == Kind::point || load.kind == Kind::patch
                   ? load.name + ": Magnitude = " + format_exact(load.magnitude)
                       + " is too large to be represented."
                   : non_finite_intensity(load, tau);
        scratch *= h;
        if (!is_finite(scratch))
          return load.name + ": Magnitude * Time history overflows at tau = "
                 + time_text(tau) + ".";
      }
    if (body_force != nullptr)
      return "the body force at tau = " + time_text(tau) + ".";
    return "the sum of the loads overflows at tau = " + time_text(tau) + ".";
  }


  void
  LoadSet::require_finite_values(const Load                &load,
                                 const std::vector<double> &times,
                                 const BoundingBox<2>      &plate,
                                 const Discretization      &disc)
  {
    for (const double tau : times)
      AssertThrow(std::isfinite(load.history->value(Point<1>(tau))),
                  ExcMessage(non_finite_history(load, tau)));
    if (load.kind == Kind::point || load.kind == Kind::patch)
      return;
    const auto   n_times = load.intensity_depends_on_time ? times.size() : 1;
    unsigned int first_bad_time = n_times;
    for (const auto &p : full_plate_points_on(load, plate, disc))
      for (unsigned int k = 0; k < first_bad_time; ++k)
        if (!std::isfinite(load.magnitude * load.intensity_at(p, times[k])))
          first_bad_time = k;
    first_bad_time = Utilities::MPI::min(first_bad_time, disc.mpi_communicator);
    AssertThrow(first_bad_time == n_times,
                ExcMessage(non_finite_intensity(load, times[first_bad_time])));
  }


  void
  LoadSet::setup(const Discretization &disc)
  {
    discretization = &disc;
    for (auto &load : loads)
      {
        disc.reinit_vector(load.spatial_part);
        if (!is_rebuilt_every_step(load))
          assemble_spatial_part(load, 0.0, load.spatial_part);
      }
  }


  bool
  LoadSet::is_rebuilt_every_step(const Load &load)
  {
    return load.intensity_depends_on_time || load.moves;
  }


  void
  LoadSet::assemble_spatial_part(const Load      &load,
                                 const double     tau,
                                 LA::MPI::Vector &vector) const
  {
    const auto density = [&](const Point<2> &x) {
      return std::array<double, 3>{
        {load.magnitude * load.intensity_at(x, tau), 0.0, 0.0}};
    };
    vector = 0;
    switch (load.kind)
      {
      case Kind::point:
        add_point_load(load, tau, vector);
        break;
      case Kind::pressure:
        if (load.region == "whole plate")
          PatchIntegrator(*discretization).add(density, vector);
        else
          PatchIntegrator(*discretization)
            .add(density,
                 region_of(load, discretization->geometry().plate_box()),
                 vector);
        break;
      case Kind::line:
        PatchIntegrator(*discretization)
          .add(density,
               load.line_at(discretization->geometry().plate_box(), tau),
               vector);
        break;
      case Kind::patch:
        add_patch(load, tau, vector);
        break;
      }
  }


  void
  LoadSet::add_point_load(const Load      &load,
                          const double     tau,
                          LA::MPI::Vector &vector) const
  {
    // A point load outside the meshed part is represented by its image
    // inside it, or is off the plate and carries nothing. Its vector is
    // the shape functions at the point, exact wherever it lies in a cell.
    const Discretization &disc = *discretization;
    const Point<2>        p    = load.position_at(tau);
    if (!disc.geometry().is_on_modelled_part(p))
      return;
    const PointFunctional functional(disc, p);
    functional.add_to(vector,
                      load.magnitude * disc.geometry().share_of_point_load(p),
                      disc.constraints);
    vector.compress(VectorOperation::add);
  }


  void
  LoadSet::add_patch(const Load      &load,
                     const double     tau,
                     LA::MPI::Vector &vector) const
  {
    // The meshed part's cells clip the patch: whatever lies off the plate
    // or beyond a symmetry plane (the mirror image's share) is not
    // integrated.
    const PatchIntegrator integrator(*discretization);
    const auto            pressure = [&](const Point<2> &) {
      return std::array<double, 3>{{load.magnitude, 0.0, 0.0}};
    };
    const Point<2> centre = load.position_at(tau);
    if (load.shape == Shape::disc)
      {
        integrator.add(pressure,
                       PatchIntegrator::Disc{centre, load.size[0] / 2},
                       vector);
        return;
      }
    const Tensor<1, 2> half({load.size[0] / 2, load.size[1] / 2});
    integrator.add(pressure,
                   BoundingBox<2>(std::make_pair(centre - half, centre + half)),
                   vector);
  }


  void
  LoadSet::assemble(const double tau, LA::MPI::Vector &load_vector) const
  {
    assemble_selected(
      tau, [](const Load &) { return true; }, load_vector);
    if (body_force != nullptr)
      add_body_force(tau, load_vector);
  }


  void
  LoadSet::assemble_selected(const double                             tau,
                             const std::function<bool(const Load &)> &selected,
                             LA::MPI::Vector &load_vector) const
  {
    load_vector = 0;
    LA::MPI::Vector scratch;
    for (const auto &load : loads)
      {
        if (!selected(load))
          continue;
        const double h = load.history->value(Point<1>(tau));
        if (is_rebuilt_every_step(load))
          {
            if (scratch.size() == 0)
              discretization->reinit_vector(scratch);
            assemble_spatial_part(load, tau, scratch);
            load_vector.add(h, scratch);
          }
        else
          load_vector.add(h, load.spatial_part);
      }
  }


  void
  LoadSet::set_body_force(Function<2> *force)
  {
    Assert(force == nullptr || force->n_components == 3,
           ExcDimensionMismatch(force->n_components, 3));
    body_force = force;
  }


  void
  LoadSet::add_body_force(const double tau, LA::MPI::Vector &load_vector) const
  {
    body_force->set_time(tau);
    // Functions may implement only vector_value(); ask for all components.
    Vector<double> values(3);
    PatchIntegrator(*discretization)
      .add(
        [&](const Point<2> &x) {
          body_force->vector_value(x, values);
          return std::array<double, 3>{{values[0], values[1], values[2]}};
        },
        load_vector);
  }

} // namespace liftoff
