#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/loads/axle_groups.h>
#include <liftoff/loads/load.h>

#include <cmath>

namespace liftoff
{
  namespace
  {
    enum class Tyres
    {
      single,
      dual,
      gear
    };

    const Selection<unsigned int> axle_counts = {{"single", 1},
                                                 {"tandem", 2},
                                                 {"tridem", 3}};
    const Selection<Tyres>        tyre_sets   = {{"single", Tyres::single},
                                                 {"dual", Tyres::dual},
                                                 {"gear", Tyres::gear}};

    struct Group
    {
      unsigned int n_axles;
      Tyres        tyres;
      double       load_per_axle;
    };

    /// "kind, tyres, load; ..." or refused naming `parameter`.
    std::vector<Group>
    parse_groups(const std::string &text, const std::string &parameter)
    {
      const std::string message =
        parameter + " = <" + abbreviated(text)
        + "> must be 'axles, tyres, load per axle' per group, front first, "
          "separated by ';': axles "
        + axle_counts.names() + ", tyres " + tyre_sets.names()
        + ", the load a finite number > 0.";
      std::vector<Group> groups;
      for (const auto &item : Utilities::split_string_list(text, ';'))
        {
          const std::vector<std::string> v =
            Utilities::split_string_list(item, ',');
          AssertThrow(v.size() == 3, ExcMessage(message));
          Group group{0, Tyres::single, 0.0};
          try
            {
              group = {axle_counts.parse(v[0], parameter),
                       tyre_sets.parse(v[1], parameter),
                       Utilities::string_to_double(v[2])};
            }
          catch (...)
            {
              AssertThrow(false, ExcMessage(message));
            }
          AssertThrow(std::isfinite(group.load_per_axle)
                        && group.load_per_axle > 0,
                      ExcMessage(message));
          groups.push_back(group);
        }
      return groups;
    }

    /// The offsets across the path (y) of an axle's tyres, left first.
    std::vector<double>
    tyres_across(const Tyres tyres, const double track, const double dual)
    {
      switch (tyres)
        {
        case Tyres::single:
          return {track / 2, -track / 2};
        case Tyres::dual:
          return {(track + dual) / 2,
                  (track - dual) / 2,
                  -(track - dual) / 2,
                  -(track + dual) / 2};
        case Tyres::gear:
          return {dual / 2, -dual / 2};
        }
      return {};
    }

    /// Refuse spacings that put tyres of `groups` on top of each other.
    void
    require_spacings(const std::vector<Group> &groups,
                     const double              track,
                     const double              dual,
                     const double              axle,
                     const std::string        &name)
    {
      for (const Group &group : groups)
        {
          AssertThrow(group.tyres == Tyres::gear || track > 0,
                      ExcMessage(name
                                 + "/Track width must be > 0 for an "
                                   "axle of single or dual tyres."));
          AssertThrow(group.tyres == Tyres::single || dual > 0,
                      ExcMessage(name
                                 + "/Dual spacing must be > 0 for dual "
                                   "tyres or a gear."));
          AssertThrow(group.tyres != Tyres::dual || track > dual,
                      ExcMessage(name
                                 + "/Track width must exceed Dual "
                                   "spacing: the dual pairs at the "
                                   "axle's ends would cross."));
          AssertThrow(group.n_axles == 1 || axle > 0,
                      ExcMessage(name
                                 + "/Axle spacing must be > 0 for a "
                                   "tandem or tridem group."));
        }
    }
  } // namespace


  void
  AxleGroups::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Axles",
      "",
      Patterns::Anything(),
      "The vehicle as axle groups instead of Wheels (then Magnitude stays "
      "0): 'axles, tyres, load per axle; ...' front first, axles single, "
      "tandem or tridem, tyres single (one tyre at each end of an axle), "
      "dual (a pair at each end) or gear (one dual pair on the path: an "
      "aircraft's main gear, prm/gears/), the load per axle a force "
      "shared equally by the axle's tyres. E.g. 'single, single, 50e3; "
      "tandem, dual, 80e3' (a steering axle and a tandem). The vehicle "
      "faces the direction its Path heads at the start (+x if it stands "
      "then), and keeps it: a path that turns is refused. Empty: the "
      "Wheels entry."
        + quantity("text, text, force"));
    prm.declare_entry("Tyre pressure",
                      "0",
                      Patterns::Double(0.0),
                      "p, the contact pressure of every tyre of Axles (> 0 "
                      "with Axles): a tyre's contact area is its load / p; "
                      "a truck's 0.7 MPa by default in an SI scene."
                        + si_default("0.7e6") + quantity("pressure"));
    prm.declare_entry("Track width",
                      "1.8",
                      Patterns::Double(0.0),
                      "The distance across the path between the two ends "
                      "of an axle of Axles (the middles of their dual "
                      "pairs); the default is a truck's 1.8 m."
                        + quantity("length"));
    prm.declare_entry("Dual spacing",
                      "0.34",
                      Patterns::Double(0.0),
                      "The distance between the centres of the two tyres "
                      "of a dual pair (or a gear's); the default is a "
                      "truck's 0.34 m."
                        + quantity("length"));
    prm.declare_entry("Axle spacing",
                      "1.3",
                      Patterns::Double(0.0),
                      "The distance along the path between the axles of a "
                      "tandem or tridem group; the default is a truck's "
                      "1.3 m."
                        + quantity("length"));
    prm.declare_entry("Group spacings",
                      "",
                      Patterns::List(Patterns::Double(0.0), 0),
                      "The distances along the path from the middle of each "
                      "group of Axles to the middle of the next, one fewer "
                      "than the groups (empty for one group)."
                        + quantity("length"));
  }


  std::vector<AxleGroups::Tyre>
  AxleGroups::read(ParameterHandler &prm, const std::string &name)
  {
    const std::string text = prm.get("Axles");
    if (text.find_first_not_of(" \t") == std::string::npos)
      return {};
    const std::vector<Group> groups = parse_groups(text, name + "/Axles");
    const std::string        spacings_text = prm.get("Group spacings");
    const std::string        spacings_message =
      name + "/Group spacings = <" + abbreviated(spacings_text) + "> must be "
      + std::to_string(groups.size() - 1)
      + " distance(s) > 0, from the middle of each group of Axles to the "
        "next.";
    const std::vector<double> spacings =
      spacings_text.find_first_not_of(" \t") == std::string::npos
        ? std::vector<double>()
        : numbers_or_refuse(spacings_text, spacings_message);
    AssertThrow(spacings.size() + 1 == groups.size(),
                ExcMessage(spacings_message));
    for (const double s : spacings)
      AssertThrow(std::isfinite(s) && s > 0, ExcMessage(spacings_message));
    const double pressure = prm.get_double("Tyre pressure");
    AssertThrow(pressure > 0 && std::isfinite(pressure),
                ExcMessage(name
                           + "/Tyre pressure must be a finite number > 0 with "
                             "Axles: a tyre's contact area is its load / "
                             "Tyre pressure."));
    const double track = prm.get_double("Track width");
    const double dual  = prm.get_double("Dual spacing");
    const double axle  = prm.get_double("Axle spacing");
    require_spacings(groups, track, dual, axle, name);

    std::vector<Tyre> tyres;
    double            middle = 0;
    for (unsigned int g = 0; g < groups.size(); ++g)
      {
        if (g > 0)
          middle -= spacings[g - 1];
        const std::vector<double> across =
          tyres_across(groups[g].tyres, track, dual);
        for (unsigned int a = 0; a < groups[g].n_axles; ++a)
          for (const double y : across)
            tyres.push_back(
              {Tensor<1, 2>(
                 {middle + ((groups[g].n_axles - 1) / 2.0 - a) * axle, y}),
               groups[g].load_per_axle / across.size(),
               pressure});
      }
    return tyres;
  }
} // namespace liftoff
