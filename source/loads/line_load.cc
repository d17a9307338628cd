#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/loads/line_load.h>
#include <liftoff/loads/mirror_image.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace
  {
    // Edges of the full plate, by their boundary ids.
    const Selection<unsigned int> plate_edges = {
      {"Left", PlateGeometry::left_edge},
      {"Right", PlateGeometry::right_edge},
      {"Bottom", PlateGeometry::bottom_edge},
      {"Top", PlateGeometry::top_edge}};

    // "x1, y1, x2, y2" of a Segment; empty: none (an Edge).
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
  } // namespace


  void
  LineLoad::declare_parameters(ParameterHandler  &prm,
                               const std::string &section)
  {
    declare_load_entries(
      prm,
      section,
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
        LoadPath::declare_parameters(prm, "");
        prm.declare_entry("Intensity",
                          "1",
                          Patterns::Anything(),
                          "f(x, y, tau) along the line, muParser."
                            + quantity("number"));
      });
  }


  std::unique_ptr<Load>
  LineLoad::read(ParameterHandler &prm, const std::string &section)
  {
    const std::string  name      = "Loads/" + section;
    const double       magnitude = prm.get_double("Magnitude");
    LoadHistory        history   = LoadHistory::read(prm, name);
    auto               path      = LoadPath::read(prm, name);
    Intensity          intensity(prm.get("Intensity"), name + "/Intensity");
    const unsigned int edge =
      plate_edges.parse(prm.get("Edge"), name + "/Edge");
    const auto segment = parse_segment(prm.get("Segment"), name + "/Segment");
    AssertThrow(segment || path == nullptr,
                ExcMessage(name
                           + "/Path moves the line of its Segment, but Segment "
                             "is empty (the line is an Edge, which stays): "
                             "give a Segment."));
    return std::unique_ptr<Load>(new LineLoad(name,
                                              magnitude,
                                              std::move(history),
                                              std::move(path),
                                              std::move(intensity),
                                              edge,
                                              segment));
  }


  LineLoad::LineLoad(const std::string                            &name,
                     const double                                  magnitude,
                     LoadHistory                                 &&history,
                     std::shared_ptr<const LoadPath>               path,
                     Intensity                                   &&intensity,
                     const unsigned int                            edge,
                     const std::optional<std::array<Point<2>, 2>> &segment)
      : DistributedLoad(name,
                        magnitude,
                        std::move(history),
                        std::move(path),
                        std::move(intensity))
      , edge(edge)
      , segment(segment)
  {}


  PatchIntegrator::Segment
  LineLoad::line_at(const BoundingBox<2> &plate, const double tau) const
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
  LineLoad::segment_at(const double tau) const
  {
    // A line without a Path stands at position_at() = (0, 0).
    const Tensor<1, 2> shift = position_at(tau) - Point<2>();
    return {(*segment)[0] + shift, (*segment)[1] + shift};
  }


  bool
  LineLoad::touches(const PlateGeometry &geometry, const double tau) const
  {
    const BoundingBox<2> plate = geometry.plate_box();
    const auto           line  = line_at(plate, tau);
    if (geometry.shape() == PlateShape::rectangle)
      return PatchIntegrator::length_inside(line, plate) > 0;
    // Other outlines are asked point by point.
    for (unsigned int k = 0; k <= 64; ++k)
      if (geometry.is_on_plate(line.start + k / 64.0 * (line.end - line.start)))
        return true;
    return false;
  }


  void
  LineLoad::require_on_plate(const PlateGeometry &geometry) const
  {
    AssertThrow(geometry.shape() == PlateShape::rectangle || segment,
                ExcMessage(load_name
                           + " acts along an edge of the rectangle, which "
                           + geometry.shape_setting()
                           + " does not have; use a Segment."));
    if (segment)
      for (const Point<2> &end : *segment)
        AssertThrow(geometry.is_on_plate(end),
                    ExcMessage(load_name + "/Segment: its end "
                               + format_point(end[0], end[1]) + " lies outside "
                               + plate_named(geometry) + "."));
  }


  void
  LineLoad::require_reducible(const std::string &symmetry) const
  {
    // Its intensity would have to be compared where the line is at each
    // step: not done, so refused rather than half checked.
    AssertThrow(path() == nullptr,
                ExcMessage("Discretization/Symmetry = " + symmetry
                           + " does not take a moving line load yet, and "
                           + load_name + " has a Path; model the full plate."));
  }


  std::optional<BoundingBox<2>>
  LineLoad::region_between(const double tau_begin, const double tau_end) const
  {
    // A line along an edge covers a whole stretch of the plate; the mesh is
    // refined around what is concentrated.
    if (!segment)
      return std::nullopt;
    std::vector<Point<2>> corners;
    for (const double tau : sample_times(tau_begin, tau_end))
      {
        const auto line = segment_at(tau);
        corners.insert(corners.end(), {line.start, line.end});
      }
    return BoundingBox<2>(corners);
  }


  void
  LineLoad::integrate(const PatchIntegrator          &integrator,
                      const PatchIntegrator::Density &density,
                      const BoundingBox<2>           &plate,
                      const double                    tau,
                      LA::MPI::Vector                &vector) const
  {
    integrator.add(density, line_at(plate, tau), vector);
  }


  std::vector<Point<2>>
  LineLoad::quadrature_points_of_image(
    const PatchIntegrator                           &integrator,
    const std::function<Point<2>(const Point<2> &)> &image,
    const BoundingBox<2>                            &plate) const
  {
    const auto line = line_at(plate, 0);
    return integrator.quadrature_points(
      PatchIntegrator::Segment{image(line.start), image(line.end)});
  }


  bool
  LineLoad::mirrors_geometry(const Load           &other,
                             const unsigned int    axis,
                             const BoundingBox<2> &plate,
                             const std::vector<double> &) const
  {
    // Lines on a reduced model stand (require_reducible()).
    return mirror_image::is_mirrored_segment(
      line_at(plate, 0),
      static_cast<const LineLoad &>(other).line_at(plate, 0),
      axis);
  }
} // namespace liftoff
