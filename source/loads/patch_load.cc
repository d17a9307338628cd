#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/selection.h>
#include <liftoff/fem/patch_integrator.h>
#include <liftoff/loads/mirror_image.h>
#include <liftoff/loads/patch_load.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace
  {
    const Selection<PatchLoad::Shape> patch_shapes = {
      {"rectangle", PatchLoad::Shape::rectangle},
      {"disc", PatchLoad::Shape::disc}};
  } // namespace


  void
  PatchLoad::declare_parameters(ParameterHandler  &prm,
                                const std::string &section)
  {
    declare_load_entries(
      prm, section, "Uniform pressure in units of F0 / L^2", "pressure", [&]() {
        prm.declare_entry("Shape",
                          "rectangle",
                          patch_shapes.pattern(),
                          "What the pressure covers (a tyre's "
                          "contact area), centred on the path.");
        prm.declare_entry("Size",
                          "0.1, 0.1",
                          size_pattern(),
                          "'a, b', the widths along x and y of a "
                          "rectangle, or 'd', a disc's diameter."
                            + quantity("length"));
        LoadPath::declare_parameters(prm, "0; 0");
      });
  }


  std::unique_ptr<Load>
  PatchLoad::read(ParameterHandler &prm, const std::string &section)
  {
    const std::string name      = "Loads/" + section;
    const double      magnitude = prm.get_double("Magnitude");
    LoadHistory       history   = LoadHistory::read(prm, name);
    auto              path      = LoadPath::read(prm, name);
    AssertThrow(path != nullptr, ExcMessage(name + "/Path must not be empty."));
    const Shape shape = patch_shapes.parse(prm.get("Shape"), name + "/Shape");
    const std::array<double, 2> size =
      parse_size(prm.get("Size"), shape, name + "/Size");
    return std::make_unique<PatchLoad>(name,
                                       magnitude,
                                       std::move(history),
                                       std::move(path),
                                       shape,
                                       size,
                                       Tensor<1, 2>());
  }


  Patterns::List
  PatchLoad::size_pattern()
  {
    // One or two widths; parse_size() decides how many the shape takes.
    return Patterns::List(Patterns::Double(0.0), 1, 2, ",");
  }


  std::array<double, 2>
  PatchLoad::parse_size(const std::string &text,
                        const Shape        shape,
                        const std::string &parameter)
  {
    const std::string message =
      parameter + " = <" + text
      + "> must be 'a, b' (widths along x and y, > 0) for a rectangle or "
        "'d' (the diameter, > 0) for a disc.";
    const std::vector<double> v = numbers_or_refuse(text, message);
    const unsigned int        n = (shape == Shape::rectangle ? 2 : 1);
    AssertThrow(v.size() == n && v[0] > 0 && v[n - 1] > 0 && std::isfinite(v[0])
                  && std::isfinite(v[n - 1]),
                ExcMessage(message));
    return {{v[0], v[n - 1]}};
  }


  PatchLoad::PatchLoad(const std::string              &name,
                       const double                    magnitude,
                       LoadHistory                   &&history,
                       std::shared_ptr<const LoadPath> path,
                       const Shape                     shape,
                       const std::array<double, 2>    &size,
                       const Tensor<1, 2>             &offset)
      : Load(name,
             magnitude,
             std::move(history),
             std::move(path),
             Point<2>(),
             offset)
      , shape(shape)
      , size(size)
  {}


  bool
  PatchLoad::touches(const PlateGeometry &geometry, const double tau) const
  {
    const Point<2> p = position_at(tau);
    if (geometry.shape() != PlateShape::rectangle)
      return area_touches(geometry, p, size, shape == Shape::disc);
    // Some area on the plate: the nearest point of the plate lies within
    // the disc, or the rectangle overlaps the plate.
    const BoundingBox<2> plate = geometry.plate_box();
    Point<2>             nearest;
    bool                 overlaps = true;
    for (unsigned int d = 0; d < 2; ++d)
      {
        nearest[d] =
          std::clamp(p[d], plate.lower_bound(d), plate.upper_bound(d));
        overlaps = overlaps && std::abs(p[d] - nearest[d]) < size[d] / 2;
      }
    return shape == Shape::disc ? (p - nearest).norm() < size[0] / 2 : overlaps;
  }


  void
  PatchLoad::require_on_plate(const PlateGeometry &) const
  {
    // A patch always has a path, which LoadSet checks.
  }


  std::optional<BoundingBox<2>>
  PatchLoad::region_between(const double tau_begin, const double tau_end) const
  {
    std::vector<Point<2>> corners;
    const Tensor<1, 2>    half({size[0] / 2, size[1] / 2});
    for (const double tau : sample_times(tau_begin, tau_end))
      {
        const Point<2> p = position_at(tau);
        corners.insert(corners.end(), {p - half, p + half});
      }
    return BoundingBox<2>(corners);
  }


  void
  PatchLoad::add_spatial_part(const Discretization &discretization,
                              const double          tau,
                              LA::MPI::Vector      &vector) const
  {
    const PatchIntegrator integrator(discretization);
    const auto            pressure = [&](const Point<2> &) {
      return std::array<double, 3>{{magnitude, 0.0, 0.0}};
    };
    const Point<2> centre = position_at(tau);
    if (shape == Shape::disc)
      {
        integrator.add(pressure,
                       PatchIntegrator::Disc{centre, size[0] / 2},
                       vector);
        return;
      }
    const Tensor<1, 2> half({size[0] / 2, size[1] / 2});
    integrator.add(pressure,
                   BoundingBox<2>(std::make_pair(centre - half, centre + half)),
                   vector);
  }


  bool
  PatchLoad::mirrors_geometry(const Load        &other_load,
                              const unsigned int axis,
                              const BoundingBox<2> &,
                              const std::vector<double> &times) const
  {
    const auto &other = static_cast<const PatchLoad &>(other_load);
    if (shape != other.shape || size != other.size)
      return false;
    return mirrors_position(other, axis, times);
  }
} // namespace liftoff
