#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/fem/point_functional.h>
#include <liftoff/loads/mirror_image.h>
#include <liftoff/loads/point_load.h>

namespace liftoff
{
  void
  PointLoad::declare_parameters(ParameterHandler  &prm,
                                const std::string &section)
  {
    declare_load_entries(prm, section, "Force in units of F0", "force", [&]() {
      prm.declare_entry("Position",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 2, ","),
                        "x, y on the full plate (any point, not only "
                        "nodes), if Path is empty."
                          + quantity("position"));
      LoadPath::declare_parameters(prm, "");
    });
  }


  std::unique_ptr<Load>
  PointLoad::read(ParameterHandler &prm, const std::string &section)
  {
    // A load that is off (Magnitude 0) is checked all the same: a broken
    // expression is an error whether or not it is used yet.
    const std::string name      = "Loads/" + section;
    const double      magnitude = prm.get_double("Magnitude");
    LoadHistory       history   = LoadHistory::read(prm, name);
    auto              path      = LoadPath::read(prm, name);
    const auto        xy        = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Position"), ','));
    return std::make_unique<PointLoad>(name,
                                       magnitude,
                                       std::move(history),
                                       std::move(path),
                                       Point<2>(xy[0], xy[1]),
                                       Tensor<1, 2>());
  }


  PointLoad::PointLoad(const std::string              &name,
                       const double                    magnitude,
                       LoadHistory                   &&history,
                       std::shared_ptr<const LoadPath> path,
                       const Point<2>                 &standing_point,
                       const Tensor<1, 2>             &offset)
      : Load(name,
             magnitude,
             std::move(history),
             std::move(path),
             standing_point,
             offset)
  {}


  bool
  PointLoad::touches(const PlateGeometry &geometry, const double tau) const
  {
    return geometry.is_on_plate(position_at(tau));
  }


  void
  PointLoad::require_on_plate(const PlateGeometry &geometry) const
  {
    const Point<2> p = position_at(0);
    AssertThrow(geometry.is_on_plate(p),
                ExcMessage(load_name + "/Position = " + format_point(p[0], p[1])
                           + " lies outside " + plate_named(geometry) + "."));
  }


  std::optional<BoundingBox<2>>
  PointLoad::region_between(const double tau_begin, const double tau_end) const
  {
    std::vector<Point<2>> corners;
    for (const double tau : sample_times(tau_begin, tau_end))
      corners.push_back(position_at(tau));
    return BoundingBox<2>(corners);
  }


  void
  PointLoad::add_spatial_part(const Discretization &disc,
                              const double          tau,
                              LA::MPI::Vector      &vector) const
  {
    // A point load outside the meshed part is represented by its image
    // inside it, or is off the plate and carries nothing.
    const Point<2> p = position_at(tau);
    if (!disc.geometry().is_on_modelled_part(p))
      return;
    const PointFunctional functional(disc, p, 0, true);
    functional.add_to(vector,
                      magnitude * disc.geometry().share_of_point_load(p),
                      disc.constraints);
    vector.compress(VectorOperation::add);
  }


  bool
  PointLoad::mirrors_geometry(const Load        &other,
                              const unsigned int axis,
                              const BoundingBox<2> &,
                              const std::vector<double> &times) const
  {
    return mirrors_position(other, axis, times);
  }
} // namespace liftoff
