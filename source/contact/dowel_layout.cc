#include <deal.II/base/utilities.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/contact/dowel_layout.h>
#include <liftoff/fem/plate_geometry.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace
  {
    /// A dowel at p, `at` along `joint`, refused where another joint that
    /// is not tied crosses it: there four slabs meet, and the dowel would
    /// join two of them by the order of the cells.
    void
    require_off_crossings(const Point<2>           &p,
                          const Joint              &joint,
                          const std::vector<Joint> &joints,
                          const double              at)
    {
      const double tolerance = 1e-10 * (joint.end - joint.start);
      for (const Joint &other : joints)
        {
          const unsigned int along = 1 - other.normal_axis;
          AssertThrow(&other == &joint || other.tied
                        || std::abs(p[other.normal_axis] - other.position)
                             > tolerance
                        || p[along] < other.start - tolerance
                        || p[along] > other.end + tolerance,
                      ExcMessage("Slabs/Dowels: the dowel at "
                                 + format_number(at) + " on the joint "
                                 + joint.name + " lies on the joint "
                                 + other.name
                                 + ", where the slabs meet at a corner: "
                                   "move it off the crossing."));
        }
    }


    /// Two dowels at one place would be one dowel of twice the stiffness,
    /// with two force columns that each show half: refused.
    void
    require_distinct(const std::vector<double> &at,
                     const std::string         &joint,
                     const double               length)
    {
      for (unsigned int k = 0; k < at.size(); ++k)
        for (unsigned int j = 0; j < k; ++j)
          AssertThrow(std::abs(at[k] - at[j]) > 1e-10 * length,
                      ExcMessage("Slabs/Dowels/Positions: two dowels at "
                                 + format_number(at[k]) + " on the joint "
                                 + joint
                                 + "; give each position once (a stiffer "
                                   "dowel there: Stiffness)."));
    }


  } // namespace


  void
  DowelLayout::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Joints",
                      "",
                      Patterns::Anything(),
                      "The joints with dowels, by name (x1, x2, ... across "
                      "x; y1, ... across y), separated by commas; empty: "
                      "no dowels. A joint with dowels may also have "
                      "Slabs/Shear stiffness; it may not be tied."
                        + quantity("text"));
    prm.declare_entry(
      "Positions",
      "",
      Patterns::Anything(),
      "The dowels' distances along a doweled joint from where it begins "
      "(its end at the lower y for x1, ... and for a mesh file's joints "
      "along y, at the lower x for y1, ... and joints along x: on the "
      "rectangle the plate's edge): one list for every joint of "
      "Slabs/Dowels/Joints (0.5, 1.5, 2.5), or a list per joint, its name "
      "before a colon (x1: 0.5, 1.5; y1: 1, 3); empty: from Spacing (also "
      "for a joint the lists per joint leave out)."
        + quantity("length"));
    prm.declare_entry("Spacing",
                      "0",
                      Patterns::Double(0.0),
                      "The distance between neighbouring dowels, used when "
                      "Positions is empty: dowels from Edge distance to the "
                      "length of the joint less Edge distance; 0.3 m (12 in) "
                      "by default in an SI scene."
                        + si_default("0.3") + quantity("length"));
    prm.declare_entry("Edge distance",
                      "0",
                      Patterns::Double(0.0),
                      "The distance of the first dowel from the joint's "
                      "lower end (with Spacing); 0: half the spacing."
                        + quantity("length"));
  }


  void
  DowelLayout::parse_parameters(ParameterHandler &prm)
  {
    const std::string joints_text = prm.get("Joints");
    joint_names                   = Utilities::split_string_list(joints_text);
    joint_names.erase(std::remove(joint_names.begin(), joint_names.end(), ""),
                      joint_names.end());
    parse_positions(prm.get("Positions"));
    spacing       = prm.get_double("Spacing");
    edge_distance = prm.get_double("Edge distance");
    if (joint_names.empty())
      return;
    for (const auto &[name, at] : positions)
      AssertThrow(name.empty()
                    || std::count(joint_names.begin(), joint_names.end(), name)
                         > 0,
                  ExcMessage("Slabs/Dowels/Positions gives positions on " + name
                             + ", which is not among Slabs/Dowels/"
                               "Joints = "
                             + joints_text + "."));
    for (const std::string &name : joint_names)
      AssertThrow(positions.count("") + positions.count(name) > 0
                    || spacing > 0,
                  ExcMessage("Slabs/Dowels/Joints = " + joints_text
                             + ": the joint " + name
                             + " has no dowels: give Slabs/Dowels/Positions "
                               "for it or a Spacing > 0."));
  }


  bool
  DowelLayout::is_empty() const
  {
    return joint_names.empty();
  }


  void
  DowelLayout::parse_positions(const std::string &text)
  {
    // Groups "x1: 0.5, 1.5" separated by ';', or one list for all joints
    // (the name "").
    const std::string entry = "Slabs/Dowels/Positions = " + text;
    positions.clear();
    const std::vector<std::string> groups =
      Utilities::split_string_list(text, ';');
    for (const std::string &group : groups)
      {
        if (group.empty() && groups.size() == 1)
          break;
        const std::size_t colon = group.find(':');
        const std::string name  = colon == std::string::npos
                                    ? ""
                                    : Utilities::trim(group.substr(0, colon));
        AssertThrow((colon != std::string::npos || groups.size() == 1)
                      && positions.count(name) == 0,
                    ExcMessage(entry
                               + ": give one list of distances for every "
                                 "joint (0.5, 1.5), or one per joint, each "
                                 "once (x1: 0.5, 1.5; y1: 1, 3)."));
        std::vector<double> &at = positions[name];
        for (const std::string &item : Utilities::split_string_list(
               colon == std::string::npos ? group : group.substr(colon + 1)))
          {
            AssertThrow(Patterns::Double(0.0).match(item),
                        ExcMessage(entry + ": '" + item
                                   + "' is not a distance (a number >= 0)."));
            at.push_back(Utilities::string_to_double(item));
          }
      }
  }


  std::vector<double>
  DowelLayout::positions_along(const std::string &joint,
                               const double       length) const
  {
    for (const std::string &name : {std::string(), joint})
      if (positions.count(name) > 0)
        return positions.at(name);
    const double        edge = edge_distance > 0 ? edge_distance : spacing / 2;
    std::vector<double> along;
    for (double d = edge; d <= length - edge + 1e-10 * length; d += spacing)
      along.push_back(d);
    return along;
  }


  std::vector<DowelSite>
  DowelLayout::place_on(const PlateGeometry &geometry) const
  {
    std::vector<DowelSite>    sites;
    const std::vector<Joint> &joints = geometry.slabs().joints();
    std::string               known;
    for (const Joint &joint : joints)
      known += (known.empty() ? "" : ", ") + joint.name;
    for (const std::string &name : joint_names)
      {
        const auto joint =
          std::find_if(joints.begin(), joints.end(), [&](const Joint &j) {
            return j.name == name;
          });
        AssertThrow(joint != joints.end(),
                    ExcMessage("Slabs/Dowels/Joints names " + name
                               + ", which the modelled plate does not have; "
                                 "its joints are: "
                               + (known.empty() ? "none" : known)
                               + " (Slabs/Slabs along x and y; a half or "
                                 "quarter model has the joints of its "
                                 "part)."));
        AssertThrow(!joint->tied,
                    ExcMessage("Slabs/Dowels/Joints names " + name
                               + ", which Slabs/Tied joints ties: a tied "
                                 "joint is monolithic and has no dowels."));
        AssertThrow(
          std::count(joint_names.begin(), joint_names.end(), name) == 1,
          ExcMessage("Slabs/Dowels/Joints names " + name + " twice."));
        place_on_joint(geometry, *joint, sites);
      }
    return sites;
  }


  void
  DowelLayout::place_on_joint(const PlateGeometry    &geometry,
                              const Joint            &joint,
                              std::vector<DowelSite> &sites) const
  {
    const std::vector<Joint> &joints = geometry.slabs().joints();
    const std::string        &name   = joint.name;
    const unsigned int        along  = 1 - joint.normal_axis;
    const double              length = joint.end - joint.start;
    const std::vector<double> at     = positions_along(name, length);
    AssertThrow(!at.empty(),
                ExcMessage("Slabs/Dowels: Spacing and Edge distance put "
                           "no dowel on the joint "
                           + name + ", which is " + format_number(length)
                           + " long."));
    require_distinct(at, name, length);
    for (unsigned int k = 0; k < at.size(); ++k)
      {
        AssertThrow(at[k] > 0 && at[k] < length,
                    ExcMessage("Slabs/Dowels: a dowel at "
                               + format_number(at[k]) + " from the edge is "
                               + "off the joint " + name + ", which is "
                               + format_number(length) + " long."));
        Point<2> p;
        p[joint.normal_axis] = joint.position;
        p[along]             = joint.start + at[k];
        require_off_crossings(p, joint, joints, at[k]);
        const double share = modelled_share(p, geometry, joint, at);
        if (share > 0)
          sites.push_back({"dowel_" + name + "_" + std::to_string(k + 1),
                           static_cast<unsigned int>(&joint - joints.data()),
                           p,
                           share});
      }
  }


  double
  DowelLayout::modelled_share(const Point<2>            &p,
                              const PlateGeometry       &geometry,
                              const Joint               &joint,
                              const std::vector<double> &at) const
  {
    const unsigned int along     = 1 - joint.normal_axis;
    const double       tolerance = 1e-10 * (joint.end - joint.start);
    double             share     = 1;
    for (const unsigned int axis : geometry.symmetry_axes())
      {
        share *= std::abs(p[axis]) <= tolerance ? 0.5 : (p[axis] < 0 ? 0 : 1);
        // A plane across the joint mirrors each dowel onto another.
        const double mirror = -p[along] - joint.start;
        AssertThrow(axis != along
                      || std::any_of(at.begin(),
                                     at.end(),
                                     [&](const double a) {
                                       return std::abs(a - mirror) <= tolerance;
                                     }),
                    ExcMessage("Slabs/Dowels: the dowel at "
                               + format_number(p[along] - joint.start)
                               + " on the joint " + joint.name
                               + " has no mirror image at "
                               + format_number(mirror)
                               + " about the symmetry plane, so "
                                 "Discretization/Symmetry would model other "
                                 "dowels: place them symmetrically, or model "
                                 "the full plate."));
      }
    return share;
  }


} // namespace liftoff
