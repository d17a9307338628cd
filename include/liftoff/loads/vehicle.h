#pragma once

#include <liftoff/loads/axle_groups.h>
#include <liftoff/loads/load.h>
#include <liftoff/loads/patch_load.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace liftoff
{
  /**
   * A vehicle: wheels at fixed offsets from one path that share its time
   * history, each a PointLoad or a PatchLoad (its share of Magnitude spread
   * over its area) on that path, given wheel by wheel (Wheels, a share of
   * Magnitude each) or as axle groups (AxleGroups: a tyre's contact area
   * its load / the tyre pressure). history.csv follows the path's point.
   */
  class Vehicle
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, const std::string &section);
    /// The wheels of the current subsection `section`, none if its
    /// Magnitude is 0 (its entries are checked all the same).
    static std::vector<std::unique_ptr<Load>>
    read(ParameterHandler &prm, const std::string &section);

  private:
    /// A wheel: its offset, force, pressure on its contact area and the
    /// area's size (widths along x and y; a disc's diameter twice).
    struct Contact
    {
      Tensor<1, 2>          offset;
      double                force;
      double                pressure;
      std::array<double, 2> size;
    };

    /// The wheels of Wheels, each its share of `magnitude` on `size`.
    static std::vector<Contact>
    shared_contacts(const std::vector<std::array<double, 3>> &wheels,
                    const double                              magnitude,
                    const std::optional<PatchLoad::Shape>    &shape,
                    const std::array<double, 2>              &size);
    /// The tyres of Axles, a disc or PCA's rectangle of area force /
    /// pressure each, the vehicle facing `heading` (a unit vector; a
    /// rectangle only along x or y, else refused naming `name`'s entries).
    static std::vector<Contact>
    tyre_contacts(const std::vector<AxleGroups::Tyre>   &tyres,
                  const std::optional<PatchLoad::Shape> &shape,
                  const Tensor<1, 2>                    &heading,
                  const std::string                     &name);
    /// "dx, dy, share; ..." or refused naming `parameter`.
    static std::vector<std::array<double, 3>>
    parse_wheels(const std::string &text, const std::string &parameter);
  };
} // namespace liftoff
