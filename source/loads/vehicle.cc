#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/loads/axle_groups.h>
#include <liftoff/loads/patch_load.h>
#include <liftoff/loads/point_load.h>
#include <liftoff/loads/vehicle.h>

#include <cmath>
#include <optional>
#include <utility>

namespace liftoff
{
  namespace
  {
    // A point wheel, or the shape of a patch wheel.
    const Selection<std::optional<PatchLoad::Shape>> wheel_shapes = {
      {"point", std::nullopt},
      {"rectangle", PatchLoad::Shape::rectangle},
      {"disc", PatchLoad::Shape::disc}};


    // A tyre of Axles presses its contact area; a point would carry its
    // force on no area, and the stress under it grows without bound as the
    // mesh is refined.
    void
    require_tyre_areas(const std::string &name,
                       const bool         has_tyres,
                       const bool         has_area)
    {
      AssertThrow(!has_tyres || has_area,
                  ExcMessage(name + "/Wheel shape = point: the tyres of " + name
                             + "/Axles press their contact areas (load / "
                               "Tyre pressure); give Wheel shape = disc (a "
                               "circle, as practice takes it) or rectangle "
                               "(PCA's equivalent)."));
    }


    // The Wheel shape `text` of a vehicle with `tyres` (none: Wheels); a
    // tyre presses its contact area, which practice takes as a circle.
    std::optional<PatchLoad::Shape>
    wheel_shape(const std::string                   &text,
                const std::string                   &parameter,
                const std::vector<AxleGroups::Tyre> &tyres)
    {
      if (text != "default")
        return wheel_shapes.parse(text, parameter);
      if (tyres.empty())
        return std::nullopt;
      return PatchLoad::Shape::disc;
    }
  } // namespace


  void
  Vehicle::declare_parameters(ParameterHandler &prm, const std::string &section)
  {
    declare_load_entries(
      prm,
      section,
      "Force in units of F0 that each wheel's share multiplies",
      "force",
      [&]() {
        LoadPath::declare_parameters(prm, "0; 0");
        prm.declare_entry(
          "Wheels",
          "0, 0, 1",
          Patterns::Anything(),
          "dx, dy, share; dx, dy, share; ...: each wheel's offset from the "
          "path's point and its share of Magnitude; the wheels move "
          "together."
            + quantity("length, length, number"));
        prm.declare_entry("Wheel shape",
                          "default",
                          Patterns::Selection("default|"
                                              + wheel_shapes.names()),
                          "A point load, or a patch load of the wheel's "
                          "force spread over its area; default: a disc for "
                          "each tyre of Axles, a point for each wheel of "
                          "Wheels.");
        prm.declare_entry("Wheel size",
                          "0.1, 0.1",
                          PatchLoad::size_pattern(),
                          "As Size of a Patch load, for patch wheels of "
                          "Wheels: 'a, b', the widths along x and y of a "
                          "rectangle, or 'd', a disc's diameter (every size "
                          "in liftoff is a width or a diameter). With Axles "
                          "each tyre's size follows from its load and Tyre "
                          "pressure."
                            + quantity("length"));
        AxleGroups::declare_parameters(prm);
      });
  }


  std::vector<std::unique_ptr<Load>>
  Vehicle::read(ParameterHandler &prm, const std::string &section)
  {
    const std::string                   name      = "Loads/" + section;
    const double                        magnitude = prm.get_double("Magnitude");
    const LoadHistory                   history = LoadHistory::read(prm, name);
    const auto                          path    = LoadPath::read(prm, name);
    const std::vector<AxleGroups::Tyre> tyres   = AxleGroups::read(prm, name);
    const auto                          shape =
      wheel_shape(prm.get("Wheel shape"), name + "/Wheel shape", tyres);
    // Axles size each tyre by its load and pressure.
    const std::array<double, 2> size =
      (shape && tyres.empty() ? PatchLoad::parse_size(prm.get("Wheel size"),
                                                      *shape,
                                                      name + "/Wheel size")
                              : std::array<double, 2>{{0, 0}});
    AssertThrow(path != nullptr, ExcMessage(name + "/Path must not be empty."));
    const std::vector<std::array<double, 3>> wheels =
      parse_wheels(prm.get("Wheels"), name + "/Wheels");
    AssertThrow(tyres.empty() || magnitude == 0.0,
                ExcMessage(name + "/Magnitude = " + prm.get("Magnitude")
                           + " and " + name
                           + "/Axles: give the vehicle's load either as "
                             "Magnitude shared by Wheels or per axle in "
                             "Axles (Magnitude 0), not both."));
    require_tyre_areas(name, !tyres.empty(), shape.has_value());
    std::vector<std::unique_ptr<Load>> loads;
    if (magnitude == 0.0 && tyres.empty())
      return loads;

    // Axles face the direction of travel; Wheels are typed in the plate's
    // axes.
    const Tensor<1, 2> heading =
      path->heading_at(0).value_or(Tensor<1, 2>({1, 0}));
    const std::vector<Contact> contacts =
      tyres.empty() ? shared_contacts(wheels, magnitude, shape, size)
                    : tyre_contacts(tyres, shape, heading, name);
    for (unsigned int k = 0; k < contacts.size(); ++k)
      {
        const std::string wheel = name + ", wheel " + std::to_string(k + 1);
        LoadHistory       own_history(history.expression(), wheel);
        if (!shape)
          loads.push_back(std::make_unique<PointLoad>(wheel,
                                                      contacts[k].force,
                                                      std::move(own_history),
                                                      path,
                                                      Point<2>(),
                                                      contacts[k].offset));
        else
          loads.push_back(std::make_unique<PatchLoad>(wheel,
                                                      contacts[k].pressure,
                                                      std::move(own_history),
                                                      path,
                                                      *shape,
                                                      contacts[k].size,
                                                      contacts[k].offset));
        if (!tyres.empty())
          loads.back()->keep_heading(heading);
      }
    return loads;
  }


  std::vector<Vehicle::Contact>
  Vehicle::shared_contacts(const std::vector<std::array<double, 3>> &wheels,
                           const double                              magnitude,
                           const std::optional<PatchLoad::Shape>    &shape,
                           const std::array<double, 2>              &size)
  {
    // A wheel's force spread over its area is a pressure.
    const double area =
      (shape == PatchLoad::Shape::disc ? M_PI / 4 * size[0] * size[0]
                                       : size[0] * size[1]);
    std::vector<Contact> contacts;
    for (const auto &wheel : wheels)
      contacts.push_back({Tensor<1, 2>({wheel[0], wheel[1]}),
                          magnitude * wheel[2],
                          magnitude * wheel[2] / area,
                          size});
    return contacts;
  }


  std::vector<Vehicle::Contact>
  Vehicle::tyre_contacts(const std::vector<AxleGroups::Tyre>   &tyres,
                         const std::optional<PatchLoad::Shape> &shape,
                         const Tensor<1, 2>                    &heading,
                         const std::string                     &name)
  {
    // A rectangle is integrated in the plate's axes: it can turn only by
    // a quarter.
    const bool across = std::abs(heading[1]) > 1 - 1e-9;
    AssertThrow(shape != PatchLoad::Shape::rectangle || across
                  || std::abs(heading[0]) > 1 - 1e-9,
                ExcMessage(name
                           + "/Wheel shape = rectangle: PCA's rectangles lie "
                             "along x or y, but "
                           + name + "/Path heads "
                           + LoadPath::heading_text(heading)
                           + " at tau = 0; give Wheel shape = disc, or a "
                             "path along x or y."));
    // The vehicle's axes, forward and to its left, in the plate's.
    const Tensor<1, 2>   left({-heading[1], heading[0]});
    std::vector<Contact> contacts;
    for (const AxleGroups::Tyre &tyre : tyres)
      {
        // The contact area load / pressure: a circle, as practice takes
        // it, or PCA's equivalent rectangle of 0.8712 l along the path by
        // 0.6 l across (Huang, Pavement analysis and design, 2004), l from
        // the area.
        const double          area = tyre.force / tyre.pressure;
        std::array<double, 2> size;
        if (shape == PatchLoad::Shape::rectangle)
          {
            const double l = std::sqrt(area / (0.8712 * 0.6));
            size           = {{0.8712 * l, 0.6 * l}};
          }
        else
          size.fill(std::sqrt(4 * area / M_PI));
        if (across)
          std::swap(size[0], size[1]);
        contacts.push_back({tyre.offset[0] * heading + tyre.offset[1] * left,
                            tyre.force,
                            tyre.pressure,
                            size});
      }
    return contacts;
  }


  std::vector<std::array<double, 3>>
  Vehicle::parse_wheels(const std::string &text, const std::string &parameter)
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
        // A wheel presses; a vehicle whose wheels carry nothing is no load
        // at all, which a scene never means.
        AssertThrow(wheel[2] >= 0,
                    ExcMessage(parameter + " = <" + abbreviated(text)
                               + ">: a wheel's share must be >= 0."));
        total_share += wheel[2];
      }
    AssertThrow(total_share > 0,
                ExcMessage(parameter + " = <" + abbreviated(text)
                           + ">: the wheels' shares add up to 0, so the "
                             "vehicle carries no load; give each wheel its "
                             "share of Magnitude (> 0 in all)."));
    return wheels;
  }
} // namespace liftoff
