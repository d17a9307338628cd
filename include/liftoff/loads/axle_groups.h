#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * A vehicle's wheels from its axle groups, as a pavement engineer gives
   * them: single, tandem or tridem axles on single or dual tyres (or an
   * aircraft's gear, one dual assembly on the path), each with its load
   * per axle, and the tyre pressure. The tyres' offsets are in the
   * vehicle's axes, x forward and y to its left (Vehicle turns them to
   * the path's direction of travel); the wheels lie behind the path's
   * point: the first group's middle is at the path's point, each next group
   * `Group spacings` behind the one before; a group's axles `Axle spacing`
   * apart; an axle's two ends `Track width` apart (between the middles of its
   * dual pairs), the two tyres of a pair `Dual spacing` apart. An axle's load
   * is shared equally by its tyres; a tyre's contact area is its load / Tyre
   * pressure (Vehicle makes it a disc or PCA's equivalent rectangle).
   *
   * The defaults of the spacings are typical road vehicles' in metres, for
   * an SI scene (a dimensionless scene gives its own, in units of L).
   */
  class AxleGroups
  {
  public:
    /// One tyre: its offset from the path's point, its force and the
    /// pressure on its contact area.
    struct Tyre
    {
      Tensor<1, 2> offset;
      double       force;
      double       pressure;
    };

    /// The entries of the current subsection (a Vehicle's).
    static void
    declare_parameters(ParameterHandler &prm);
    /// The tyres of the current subsection's Axles (none if it is empty),
    /// refused naming the entry of `name` (e.g. "Loads/Vehicle 1").
    static std::vector<Tyre>
    read(ParameterHandler &prm, const std::string &name);
  };
} // namespace liftoff
