#pragma once

#include <liftoff/loads/load.h>

namespace liftoff
{
  /**
   * A concentrated force at any point of the plate (not only nodes),
   * standing at its Position or moving along a Path; also a vehicle's
   * point wheel. Its vector is the shape functions at the point, exact
   * wherever it lies in a cell.
   */
  class PointLoad : public Load
  {
  public:
    /// The entries of subsection `section` ("Point load 1") of Loads.
    static void
    declare_parameters(ParameterHandler &prm, const std::string &section);
    /// The load of the current subsection `section`.
    static std::unique_ptr<Load>
    read(ParameterHandler &prm, const std::string &section);

    /// A force `magnitude` at `standing_point` or at `offset` from the
    /// point of `path`.
    PointLoad(const std::string              &name,
              const double                    magnitude,
              LoadHistory                   &&history,
              std::shared_ptr<const LoadPath> path,
              const Point<2>                 &standing_point,
              const Tensor<1, 2>             &offset);

    bool
    touches(const PlateGeometry &geometry, const double tau) const override;
    void
    require_on_plate(const PlateGeometry &geometry) const override;
    std::optional<BoundingBox<2>>
    region_between(const double tau_begin, const double tau_end) const override;

  protected:
    void
    add_spatial_part(const Discretization &discretization,
                     const double          tau,
                     LA::MPI::Vector      &vector) const override;
    bool
    mirrors_geometry(const Load                &other,
                     const unsigned int         axis,
                     const BoundingBox<2>      &plate,
                     const std::vector<double> &times) const override;
  };
} // namespace liftoff
