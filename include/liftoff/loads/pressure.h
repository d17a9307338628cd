#pragma once

#include <liftoff/loads/distributed_load.h>

namespace liftoff
{
  /**
   * Magnitude * f(x, y, tau) on a rectangle of the full plate (or the whole
   * plate): each cell the rectangle cuts is integrated over its part
   * inside. The self-weight is one, on the whole plate and permanent.
   */
  class Pressure : public DistributedLoad
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, const std::string &section);
    static std::unique_ptr<Load>
    read(ParameterHandler &prm, const std::string &section);
    /// Loads/Self weight = q: a uniform pressure on the whole plate that
    /// is always on.
    static std::unique_ptr<Load>
    self_weight(const double q);

    bool
    touches(const PlateGeometry &geometry, const double tau) const override;
    void
    require_on_plate(const PlateGeometry &geometry) const override;
    /// The self-weight keeps the slabs' thicknesses.
    void
    use_plate(const MindlinPlate &plate) override;

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
    double
    density_factor(const Discretization &discretization,
                   const Point<2>       &x) const override;
    bool
    mirrors_geometry(const Load                &other,
                     const unsigned int         axis,
                     const BoundingBox<2>      &plate,
                     const std::vector<double> &times) const override;

  private:
    Pressure(const std::string &name,
             const double       magnitude,
             LoadHistory      &&history,
             Intensity        &&intensity,
             const std::string &region);

    /// The rectangle of Region in full plate coordinates, refused unless
    /// it lies in `plate`.
    BoundingBox<2>
    region_in(const BoundingBox<2> &plate) const;

    /// "whole plate" or "x_min, x_max, y_min, y_max".
    std::string region;
    /// The self-weight's H_s / H by slab number, where the slabs differ.
    bool                is_self_weight = false;
    std::vector<double> slab_weights;
    /// rho_b H_b / (rho H) of a base of its own (tensionless), 0 if none.
    double base_weight = 0;
  };
} // namespace liftoff
