#pragma once

#include <deal.II/base/patterns.h>

#include <liftoff/loads/load.h>

#include <array>

namespace liftoff
{
  /**
   * A uniform pressure on a rectangle or a disc (a tyre's contact area)
   * centred on a path; also a vehicle's patch wheel. The meshed part's
   * cells clip it (PatchIntegrator): whatever lies off the plate or beyond
   * a symmetry plane (the mirror image's share) is not integrated.
   */
  class PatchLoad : public Load
  {
  public:
    enum class Shape
    {
      rectangle,
      disc
    };

    static void
    declare_parameters(ParameterHandler &prm, const std::string &section);
    static std::unique_ptr<Load>
    read(ParameterHandler &prm, const std::string &section);

    /// The pattern of Size: one or two widths.
    static Patterns::List
    size_pattern();
    /// "a, b" of a rectangle, "d" of a disc (then twice): both widths, or
    /// refused naming `parameter`.
    static std::array<double, 2>
    parse_size(const std::string &text,
               const Shape        shape,
               const std::string &parameter);

    /// A pressure `magnitude` on `shape` of `size` at `offset` from the
    /// point of `path`.
    PatchLoad(const std::string              &name,
              const double                    magnitude,
              LoadHistory                   &&history,
              std::shared_ptr<const LoadPath> path,
              const Shape                     shape,
              const std::array<double, 2>    &size,
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

  private:
    Shape shape;
    /// Widths along x and y (a disc: its diameter twice).
    std::array<double, 2> size;
  };
} // namespace liftoff
