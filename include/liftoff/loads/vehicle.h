#pragma once

#include <liftoff/loads/load.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  /**
   * A vehicle: wheels at fixed offsets from one path that share its time
   * history, each a PointLoad or a PatchLoad (its share of Magnitude spread
   * over its area) on that path. history.csv follows the path's point.
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
    /// "dx, dy, share; ..." or refused naming `parameter`.
    static std::vector<std::array<double, 3>>
    parse_wheels(const std::string &text, const std::string &parameter);
  };
} // namespace liftoff
