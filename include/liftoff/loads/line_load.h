#pragma once

#include <liftoff/loads/distributed_load.h>

#include <array>
#include <optional>

namespace liftoff
{
  /**
   * Magnitude * f(x, y, tau) per unit length along an Edge of the full
   * plate or a Segment anywhere on it, which a Path may move. Each cell
   * the line crosses is integrated along its piece; a piece off the plate
   * carries nothing.
   */
  class LineLoad : public DistributedLoad
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, const std::string &section);
    static std::unique_ptr<Load>
    read(ParameterHandler &prm, const std::string &section);

    bool
    touches(const PlateGeometry &geometry, const double tau) const override;
    void
    require_on_plate(const PlateGeometry &geometry) const override;
    void
    require_reducible(const std::string &symmetry) const override;
    std::optional<BoundingBox<2>>
    region_between(const double tau_begin, const double tau_end) const override;

  protected:
    void
    integrate(const PatchIntegrator          &integrator,
              const PatchIntegrator::Density &density,
              const BoundingBox<2>           &plate,
              const double                    tau,
              LA::MPI::Vector                &vector) const override;
    std::vector<Point<2>>
    quadrature_points_of_image(
      const PatchIntegrator                           &integrator,
      const std::function<Point<2>(const Point<2> &)> &image,
      const BoundingBox<2>                            &plate) const override;
    bool
    mirrors_geometry(const Load                &other,
                     const unsigned int         axis,
                     const BoundingBox<2>      &plate,
                     const std::vector<double> &times) const override;

  private:
    LineLoad(const std::string                            &name,
             const double                                  magnitude,
             LoadHistory                                 &&history,
             std::shared_ptr<const LoadPath>               path,
             Intensity                                   &&intensity,
             const unsigned int                            edge,
             const std::optional<std::array<Point<2>, 2>> &segment);

    /// Where it lies at tau (the plate's box places an Edge) ...
    PatchIntegrator::Segment
    line_at(const BoundingBox<2> &plate, const double tau) const;
    /// ... and one given by its Segment.
    PatchIntegrator::Segment
    segment_at(const double tau) const;

    unsigned int edge;
    /// Its ends (offsets from the path's point if it moves); none: it lies
    /// along `edge`.
    std::optional<std::array<Point<2>, 2>> segment;
  };
} // namespace liftoff
