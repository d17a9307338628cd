#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/fem/plate_geometry.h>
#include <liftoff/loads/mirror_image.h>
#include <liftoff/loads/pressure.h>

#include <algorithm>

namespace liftoff
{
  void
  Pressure::declare_parameters(ParameterHandler  &prm,
                               const std::string &section)
  {
    declare_load_entries(
      prm, section, "Pressure in units of F0 / L^2", "pressure", [&]() {
        prm.declare_entry("Region",
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
  }


  std::unique_ptr<Load>
  Pressure::read(ParameterHandler &prm, const std::string &section)
  {
    const std::string name      = "Loads/" + section;
    const double      magnitude = prm.get_double("Magnitude");
    LoadHistory       history   = LoadHistory::read(prm, name);
    Intensity         intensity(prm.get("Intensity"), name + "/Intensity");
    std::unique_ptr<Pressure> load(new Pressure(name,
                                                magnitude,
                                                std::move(history),
                                                std::move(intensity),
                                                prm.get("Region")));
    // Regions are checked against the plate once the plate is known; here
    // only their form.
    load->region_in(BoundingBox<2>(
      std::make_pair(Point<2>(-1e300, -1e300), Point<2>(1e300, 1e300))));
    return load;
  }


  std::unique_ptr<Load>
  Pressure::self_weight(const double q)
  {
    const std::string         name = "Loads/Self weight";
    std::unique_ptr<Pressure> load(new Pressure(
      name, q, LoadHistory("1", name), Intensity("1", name), "whole plate"));
    load->permanent      = true;
    load->is_self_weight = true;
    return load;
  }


  void
  Pressure::use_plate(const MindlinPlate &plate)
  {
    slab_weights.clear();
    base_weight = 0;
    if (!is_self_weight)
      return;
    // The base's weight over the slab's (of a uniform plate, whose slab
    // weighs 1).
    if (plate.base.n_layers() == 2)
      base_weight = plate.base_section().mass;
    // Slabs alike (slab_sections empty) share the first's section; a base
    // adds its weight to it.
    const std::size_t n_sections =
      std::max<std::size_t>(plate.slab_sections.size(), 1);
    if (plate.slab_sections.empty() && !plate.base.present())
      return;
    for (unsigned int s = 0; s < n_sections; ++s)
      slab_weights.push_back(plate.section(s).mass);
  }


  double
  Pressure::density_factor(const Discretization &discretization,
                           const Point<2>       &x) const
  {
    if (slab_weights.empty())
      return 1.0;
    if (slab_weights.size() == 1)
      return slab_weights[0];
    return slab_weights[discretization.geometry().slabs().slab_of(x)];
  }


  Pressure::Pressure(const std::string &name,
                     const double       magnitude,
                     LoadHistory      &&history,
                     Intensity        &&intensity,
                     const std::string &region)
      : DistributedLoad(name,
                        magnitude,
                        std::move(history),
                        nullptr,
                        std::move(intensity))
      , region(region)
  {}


  BoundingBox<2>
  Pressure::region_in(const BoundingBox<2> &plate) const
  {
    if (region == "whole plate")
      return plate;

    const std::string message =
      load_name + "/Region = <" + abbreviated(region)
      + "> must be 'whole plate' or 'x_min, x_max, y_min, y_max' with "
        "x_min < x_max, y_min < y_max, inside the plate [-1/2, 1/2] x [-mu/2, "
        "mu/2] (on other shapes: inside the outline's bounding box).";
    const std::vector<double> v = numbers_or_refuse(region, message);
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


  bool
  Pressure::touches(const PlateGeometry &geometry, const double) const
  {
    // On the rectangle, region_in() keeps the region on the plate.
    if (geometry.shape() == PlateShape::rectangle)
      return true;
    const BoundingBox<2> box = region_in(geometry.plate_box());
    return area_touches(geometry,
                        box.center(),
                        {{box.side_length(0), box.side_length(1)}},
                        false);
  }


  void
  Pressure::require_on_plate(const PlateGeometry &geometry) const
  {
    region_in(geometry.plate_box());
    // A box within a round or meshed outline's bounding box may still miss
    // the plate.
    AssertThrow(geometry.shape() == PlateShape::rectangle
                  || touches(geometry, 0),
                ExcMessage(load_name + "/Region = <" + abbreviated(region)
                           + "> lies off " + plate_named(geometry)
                           + ": it would carry nothing."));
  }


  void
  Pressure::integrate(const PatchIntegrator          &integrator,
                      const PatchIntegrator::Density &density,
                      const BoundingBox<2>           &plate,
                      const double,
                      LA::MPI::Vector &vector) const
  {
    if (region == "whole plate")
      integrator.add(density, vector);
    else
      integrator.add(density, region_in(plate), vector);
    // A base of its own (tensionless) carries its own weight, on the
    // base's w: the density without the slab's section under x (slabs of
    // their own weigh differently; the base is one layer under all).
    if (base_weight > 0)
      PatchIntegrator(integrator)
        .on_layer(1)
        .add(
          [&](const Point<2> &x) {
            std::array<double, 3> f = density(x);
            f[0] *= base_weight / density_factor(integrator.mesh(), x);
            return f;
          },
          vector);
  }


  std::vector<Point<2>>
  Pressure::quadrature_points_of_image(
    const PatchIntegrator                           &integrator,
    const std::function<Point<2>(const Point<2> &)> &image,
    const BoundingBox<2>                            &plate) const
  {
    const BoundingBox<2> box = region_in(plate);
    const Point<2>       a   = image(box.get_boundary_points().first),
                   b         = image(box.get_boundary_points().second);
    return integrator.quadrature_points(BoundingBox<2>(
      std::make_pair(Point<2>(std::min(a[0], b[0]), std::min(a[1], b[1])),
                     Point<2>(std::max(a[0], b[0]), std::max(a[1], b[1])))));
  }


  bool
  Pressure::mirrors_geometry(const Load           &other,
                             const unsigned int    axis,
                             const BoundingBox<2> &plate,
                             const std::vector<double> &) const
  {
    return mirror_image::is_mirrored_rectangle(
      region_in(plate),
      static_cast<const Pressure &>(other).region_in(plate),
      axis);
  }
} // namespace liftoff
