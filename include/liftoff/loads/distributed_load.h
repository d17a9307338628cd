#pragma once

#include <deal.II/base/function_parser.h>

#include <liftoff/fem/patch_integrator.h>
#include <liftoff/loads/load.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /// A load's f(x, y, tau), a muParser expression.
  class Intensity
  {
  public:
    /// `parameter` names the expression in a message about it.
    Intensity(const std::string &expression, const std::string &parameter);

    double
    at(const Point<2> &p, const double tau) const;
    bool
    depends_on_time() const;
    const std::string &
    expression() const;

  private:
    std::string                        text;
    std::unique_ptr<FunctionParser<2>> function;
    bool                               names_tau_;
  };


  /**
   * A load spread over an area or along a line with Magnitude * f(x, y,
   * tau) (Pressure, LineLoad), integrated by PatchIntegrator. Its intensity
   * is checked and compared with its mirror image's at every quadrature
   * point of the full plate's mesh it covers.
   */
  class DistributedLoad : public Load
  {
  public:
    std::string
    non_finite_spatial_part(const double tau) const override;

  protected:
    DistributedLoad(const std::string              &name,
                    const double                    magnitude,
                    LoadHistory                   &&history,
                    std::shared_ptr<const LoadPath> path,
                    Intensity                     &&intensity);

    /// vector += the integral of `density` over where it acts at tau.
    virtual void
    integrate(const PatchIntegrator          &integrator,
              const PatchIntegrator::Density &density,
              const BoundingBox<2>           &plate,
              const double                    tau,
              LA::MPI::Vector                &vector) const = 0;
    /// The quadrature points of `integrator` on the image of where it
    /// stands under `image` (a composition of mirrors).
    virtual std::vector<Point<2>>
    quadrature_points_of_image(
      const PatchIntegrator                           &integrator,
      const std::function<Point<2>(const Point<2> &)> &image,
      const BoundingBox<2>                            &plate) const = 0;

    bool
    is_rebuilt_every_step() const override;
    void
    add_spatial_part(const Discretization &discretization,
                     const double          tau,
                     LA::MPI::Vector      &vector) const override;
    bool
    mirrors_intensity(const Load                &other,
                      const unsigned int         axis,
                      const BoundingBox<2>      &plate,
                      const std::vector<double> &times,
                      const Discretization      &discretization) const override;
    void
    require_finite_intensity(
      const std::vector<double> &times,
      const BoundingBox<2>      &plate,
      const Discretization      &discretization) const override;

    /// What multiplies the density at x besides Magnitude and the
    /// intensity (a self-weight: the slab's thickness over the plate's); 1.
    virtual double
    density_factor(const Discretization &discretization,
                   const Point<2>       &x) const;

    /// f(x, y, tau) (without Magnitude), for a kind that integrates it
    /// itself.
    const Intensity &
    intensity_function() const;

  private:
    /// The points at which the full plate's mesh (this rank's share)
    /// evaluates it.
    std::vector<Point<2>>
    full_plate_points(const BoundingBox<2> &plate,
                      const Discretization &discretization) const;

    Intensity intensity;
  };
} // namespace liftoff
