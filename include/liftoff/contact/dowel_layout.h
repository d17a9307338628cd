#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <map>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class PlateGeometry;
  struct Joint;

  /// A dowel of the modelled part: its name dowel_<joint>_<k> (k from 1
  /// along the joint, numbered on the full plate), its joint (index in the
  /// layout's joints), its point, and the modelled part's share of it (1/2
  /// per symmetry plane through it).
  struct DowelSite
  {
    std::string  name;
    unsigned int joint;
    Point<2>     location;
    double       share;
  };


  /**
   * Where the dowels sit: the doweled joints by name, the dowels' distances
   * along each (a list for every joint, or one per joint by name, or
   * evenly from a spacing), and their places on a plate's joints with the
   * modelled part's share of each on a half or quarter model. Knows nothing
   * of the dowels' law (JointDowels).
   */
  class DowelLayout
  {
  public:
    /// Its entries in the current subsection (`Slabs/Dowels`).
    static void
    declare_parameters(ParameterHandler &prm);
    /// Reads them, refusing positions on a joint not listed and a listed
    /// joint without dowels.
    void
    parse_parameters(ParameterHandler &prm);
    /// Whether the scene has no doweled joint.
    bool
    is_empty() const;
    /// The dowels on the joints of `geometry`'s slabs, refusing a joint
    /// that is not there or is tied, a position off the joint or on a
    /// crossing, two dowels at one place, and dowels that are not mirror
    /// images across a symmetry plane.
    std::vector<DowelSite>
    place_on(const PlateGeometry &geometry) const;

  private:
    std::vector<std::string> joint_names;
    /// Slabs/Dowels/Positions by joint name ("": every joint).
    std::map<std::string, std::vector<double>> positions;
    double                                     spacing       = 0;
    double                                     edge_distance = 0;

    /// Slabs/Dowels/Positions into `positions`.
    void
    parse_positions(const std::string &text);
    /// The dowel positions along the joint `joint` of length `length`.
    std::vector<double>
    positions_along(const std::string &joint, const double length) const;
    /// The dowels of one joint into `sites`.
    void
    place_on_joint(const PlateGeometry    &geometry,
                   const Joint            &joint,
                   std::vector<DowelSite> &sites) const;
    /// The modelled part's share of a dowel at p on `joint`, whose dowels
    /// are at the distances `at` from its lower end: 0 on a mirror image.
    double
    modelled_share(const Point<2>            &p,
                   const PlateGeometry       &geometry,
                   const Joint               &joint,
                   const std::vector<double> &at) const;
  };
} // namespace liftoff
