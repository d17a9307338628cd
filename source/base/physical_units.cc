#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/output_files.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <vector>

namespace liftoff
{
  namespace
  {
    /// `text` with each match of `pattern` replaced by `replacement` of it.
    std::string
    replace_matches(
      const std::string                                     &text,
      const std::regex                                      &pattern,
      const std::function<std::string(const std::smatch &)> &replacement)
    {
      std::string result;
      auto        from = text.cbegin();
      for (std::sregex_iterator m(text.cbegin(), text.cend(), pattern), end;
           m != end;
           ++m)
        {
          result.append(from, (*m)[0].first);
          result += replacement(*m);
          from = (*m)[0].second;
        }
      return result.append(from, text.cend());
    }


    /// `message` with each "tau = X" (a time) and "dtau = X" (a step) of
    /// the twin's as "t = X t0 s" and "dt = X t0 s", the scene's.
    std::string
    with_seconds(const std::string &message, const double t0)
    {
      static const std::regex tau(
        R"(\b(d?)tau = ([-+]?[0-9]+(?:\.[0-9]+)?(?:[eE][-+]?[0-9]+)?))");
      return replace_matches(message, tau, [&](const std::smatch &m) {
        return m[1].str() + "t = " + format_number(t0 * std::stod(m[2].str()))
               + " s";
      });
    }


    /// `message` with each number or point tagged with its solver's unit
    /// (tagged(): "3.1e-05 [F0^2*L^2/D]", "(0.6, 0.25) [L]") in the units
    /// `scale` gives, with their symbol ("0.012 J", "(8.7, 3.6) m").
    std::string
    with_tagged_numbers(const std::string                     &message,
                        const std::function<double(Quantity)> &scale)
    {
      static const std::string number =
        R"([-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)";
      static const std::regex tag("(?:\\((" + number + "), (" + number
                                  + ")\\)|(" + number + R"()) \[([^\]]+)\])");
      return replace_matches(message, tag, [&](const std::smatch &m) {
        auto q = Quantity::number;
        while (q < Quantity::mu && dimensionless_scales(q) != m[4].str())
          q = static_cast<Quantity>(static_cast<int>(q) + 1);
        if (q == Quantity::mu || q == Quantity::text)
          return m[0].str();
        const auto in_scene = [&](const std::string &x) {
          return std::stod(x) * scale(q);
        };
        return (m[3].matched
                  ? format_number(in_scene(m[3].str()))
                  : "("
                      + format_point(in_scene(m[1].str()), in_scene(m[2].str()))
                      + ")")
               + " " + si_symbol(q);
      });
    }


    using System                         = PhysicalUnits::System;
    using Quantity                       = PhysicalUnits::Quantity;
    const Selection<System> system_names = {{"dimensionless",
                                             System::dimensionless},
                                            {"SI", System::si}};

    // The dimensionless groups an SI scene gives by the entries of Units:
    // the entries that give each, which a scene must not set beside the
    // group, and the formula that errors of the group's range quote.
    struct GroupSource
    {
      std::string physical, formula;
    };
    const std::map<Quantity, GroupSource> group_sources = {
      {Quantity::mu, {"Units/Width", "Units/Width / Length"}},
      {Quantity::Delta, {"Units/Thickness", "Units/Thickness / Units/Length"}},
      {Quantity::Gamma,
       {"Units/Subgrade modulus", "Units/Subgrade modulus k L^4 / D"}},
      {Quantity::damping,
       {"Units/Dashpot coefficient",
        "Units/Dashpot coefficient C L^2 / sqrt(rho H D)"}},
      {Quantity::shear_layer,
       {"Units/Shear layer modulus", "Units/Shear layer modulus G_f L^2 / D"}},
      {Quantity::self_weight,
       {"Units/Density and Units/Gravity",
        "Units/Density * Gravity * Thickness"}}};

    using Entry = DeclaredEntry;

    // Whether the scene must be watched for setting `entry`: a group an SI
    // scene must not set, an entry whose default stays dimensionless (a
    // disc's radius L / 2) unless the scene sets it, or one whose default
    // in an SI scene is another (si_default()).
    bool
    is_watched(const Entry &entry)
    {
      const auto quantities = declared_quantities(entry.documentation);
      return !si_default_of(entry.documentation).empty()
             || (!quantities.empty()
                 && (is_group(quantities[0])
                     || converts_only_if_set(entry.documentation)));
    }

    // Sets `path` of `prm` to `value`, which the scene gave as `written`; a
    // value the entry does not allow is refused in the user's terms.
    void
    set_entry(ParameterHandler  &prm,
              const std::string &path,
              const std::string &value,
              const std::string &written)
    {
      const std::vector<std::string> names =
        Utilities::split_string_list(path, '/');
      for (unsigned int k = 0; k + 1 < names.size(); ++k)
        prm.enter_subsection(names[k]);
      std::string error;
      try
        {
          prm.set(names.back(), value);
        }
      catch (const std::exception &e)
        {
          error = message_of(e);
        }
      for (unsigned int k = 0; k + 1 < names.size(); ++k)
        prm.leave_subsection();
      AssertThrow(error.empty(),
                  ExcMessage(written + " gives " + path + " = " + value
                             + " in the dimensionless scene, which that entry "
                               "does not allow: "
                             + error));
    }

    // The items of `text` and the separator after each (',' or ';'; none
    // after the last): split at ',' and ';' outside parentheses, so that a
    // muParser call if(a, b, c) is one item.
    std::vector<std::pair<std::string, std::string>>
    items_of(const std::string &text)
    {
      std::vector<std::pair<std::string, std::string>> items;
      std::string                                      item;
      int                                              depth = 0;
      for (const char c : text)
        {
          depth += (c == '(') - (c == ')');
          if (depth == 0 && (c == ',' || c == ';'))
            {
              items.emplace_back(Utilities::trim(item), std::string(1, c));
              item.clear();
            }
          else
            item += c;
        }
      items.emplace_back(Utilities::trim(item), "");
      return items;
    }

    // Whether `text` is a muParser expression in x, y, t: what is not (a
    // keyword as 'whole plate', or an expression the user mistyped) is
    // passed on as written, for the entry's owner to read or refuse.
    bool
    is_expression(const std::string &text)
    {
      try
        {
          parse_expression<2>("", text, 1, "x,y,t", true);
          return true;
        }
      catch (...)
        {
          return false;
        }
    }

    /**
     * The entries of an SI scene written into its dimensionless twin `out`,
     * each by the quantity its owner declared with it (entry_quantity.h):
     * numbers divided by their unit, muParser expressions in x, y [m] and
     * t [s] rewritten in the solver's x, y and tau and divided by their
     * unit, the groups given by the entries of Units. Each error names the
     * entry as the user wrote it.
     */
    struct SceneConverter
    {
      std::map<std::string, Entry>             entries;
      std::function<bool(const std::string &)> is_set;
      ParameterHandler                        &out;
      double                                   length, width, t0;
      bool                                     is_rectangle;
      std::map<Quantity, double>               units;

      // x, y [m] and t [s] of `si` as the solver's x, y and tau.
      std::string
      expression(const std::string &si) const
      {
        static const std::regex name("[A-Za-z_][A-Za-z0-9_]*");
        std::string             result;
        auto                    from = si.cbegin();
        for (std::sregex_iterator i(si.begin(), si.end(), name), end; i != end;
             ++i)
          {
            const std::string word = i->str();
            result.append(from, (*i)[0].first);
            from = (*i)[0].second;
            if (word == "x" || word == "y")
              result += "(" + format_exact(length) + "*" + word + ")";
            else if (word == "t")
              result += "(" + format_exact(t0) + "*tau)";
            else
              result += word;
          }
        return result.append(from, si.cend());
      }

      // A point the scene gives in metres from the plate's centre is
      // refused in metres if it lies outside the rectangle; other shapes
      // check their points themselves (with the scales of the twin's
      // numbers, explain_errors_of()).
      void
      check_on_plate(const std::string &path,
                     const std::string &point,
                     const double       x,
                     const double       y) const
      {
        if (!is_rectangle)
          return;
        AssertThrow(std::abs(x) <= length / 2 * (1 + 1e-12)
                      && std::abs(y) <= width / 2 * (1 + 1e-12),
                    ExcMessage(path + ": the point " + point
                               + " [m] lies outside the plate, [-"
                               + format_number(length / 2) + ", "
                               + format_number(length / 2) + "] x [-"
                               + format_number(width / 2) + ", "
                               + format_number(width / 2)
                               + "] m with its centre at the origin."));
      }

      // NAME(x; y) of a probe quantity: x, y a position in metres (other
      // forms are checked where the twin is read).
      std::string
      named_point(const std::string &path, const std::string &item) const
      {
        static const std::regex named(R"(([^()]*)\(([^;()]*);([^;()]*)\))");
        std::smatch             m;
        if (!std::regex_match(item, m, named))
          return item;
        const std::string x = Utilities::trim(m[2]), y = Utilities::trim(m[3]);
        if (!Patterns::Double().match(x) || !Patterns::Double().match(y))
          return item;
        const double px = Utilities::string_to_double(x),
                     py = Utilities::string_to_double(y);
        check_on_plate(path, "(" + m[2].str() + ";" + m[3].str() + ")", px, py);
        return m[1].str() + "(" + format_exact(px / length) + "; "
               + format_exact(py / length) + ")";
      }

      /// One item of `path` in the quantity `unit`; `point` collects the
      /// coordinates of a position until both are there.
      std::string
      converted_item(const std::string   &path,
                     const std::string   &item,
                     const Quantity       unit,
                     std::vector<double> &point,
                     std::string         &point_text) const
      {
        if (unit == Quantity::text || item.empty())
          return item;
        // A number labelled by a name (Slabs/Dowels/Positions: x1: 0.5);
        // not muParser's a ? b : c.
        static const std::regex label(R"(^\s*[A-Za-z_][A-Za-z0-9_]*\s*:)");
        const std::size_t       colon = item.find(':');
        if (std::regex_search(item, label)
            && Patterns::Double().match(
              Utilities::trim(item.substr(colon + 1))))
          return item.substr(0, colon + 1) + " "
                 + converted_item(path,
                                  Utilities::trim(item.substr(colon + 1)),
                                  unit,
                                  point,
                                  point_text);
        const double scale = units.at(unit);
        if (Patterns::Double().match(item))
          {
            const double x = Utilities::string_to_double(item);
            if (unit == Quantity::position)
              {
                point.push_back(x);
                point_text += (point_text.empty() ? "" : ", ") + item;
                if (point.size() == 2)
                  check_on_plate(path, point_text, point[0], point[1]);
                if (point.size() == 2)
                  point.clear(), point_text.clear();
              }
            return format_exact(x / scale);
          }
        if (unit == Quantity::position && item.find('(') != std::string::npos)
          return named_point(path, item);
        // tau is refused even where the expression is not one in x, y, t.
        static const std::regex tau(R"(\btau\b)");
        AssertThrow(!std::regex_search(item, tau),
                    ExcMessage(path + " = <" + entries.at(path).value
                               + ">: a scene with Units/System = SI writes "
                                 "time as t in seconds, not tau."));
        if (!is_expression(item))
          return item;
        const std::string rewritten = expression(item);
        return scale == 1 ? rewritten
                          : "(" + rewritten + ")/" + format_exact(scale);
      }

      /// The value of `path` in the twin, by the quantities its owner
      /// declared (the items take them in turn).
      std::string
      converted(const std::string &path, const Entry &entry) const
      {
        const std::vector<Quantity> quantities =
          declared_quantities(entry.documentation);
        std::string         result, point_text;
        std::vector<double> point;
        const auto          items = items_of(entry.value);
        for (unsigned int k = 0; k < items.size(); ++k)
          result += converted_item(path,
                                   items[k].first,
                                   quantities[k % quantities.size()],
                                   point,
                                   point_text)
                    + items[k].second + (items[k].second.empty() ? "" : " ");
        return result;
      }

      /// Every entry with a declared quantity, into `out`; `changed` gets
      /// each entry it changed (by its path, the scene's value and the
      /// twin's), `group_entries` the group of each group entry.
      void
      convert_all(const std::map<Quantity, double>                &groups,
                  std::map<std::string, PhysicalUnits::Converted> &changed,
                  std::map<std::string, Quantity> &group_entries) const
      {
        for (const auto &[path, entry] : entries)
          {
            const auto quantities = declared_quantities(entry.documentation);
            if (quantities.empty()
                || quantities == std::vector<Quantity>{Quantity::text}
                || (converts_only_if_set(entry.documentation) && !is_set(path)))
              continue;
            std::string twin;
            if (const auto group = groups.find(quantities[0]);
                group != groups.end())
              {
                twin                = format_exact(group->second);
                group_entries[path] = quantities[0];
                set_entry(out,
                          path,
                          twin,
                          group_sources.at(quantities[0]).formula);
              }
            else
              {
                twin = converted(path, entry);
                set_entry(out, path, twin, path + " = " + entry.value);
              }
            if (twin != entry.value)
              changed[path] = {entry.value,
                               twin,
                               quantities[0],
                               entry.value == entry.default_value};
          }
      }

      // The dimensionless twin reads no physical entry.
      void
      reset_physical_entries() const
      {
        for (const auto &[path, entry] : entries)
          if (path.rfind("Units/", 0) == 0)
            set_entry(out, path, entry.default_value, path);
      }
    };
  } // namespace


  void
  PhysicalUnits::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Units");
    prm.declare_entry(
      "System",
      "dimensionless",
      system_names.pattern(),
      "dimensionless: every entry is a group of doc/model.md (lengths in L, "
      "time in t0, forces in F0); the other entries of Units are not read. "
      "SI: the plate and the bed are the other entries of Units, and every "
      "other dimensional entry is in SI units: forces in N, pressures in Pa, "
      "line loads in N/m, positions, regions, gaps and deflections in m "
      "(the plate's centre at the origin, x along Length), rotations in "
      "rad, times in s; expressions are in x, y (m) and t (s) instead of "
      "tau. Plate/Aspect ratio, Thickness ratio, Foundation/Stiffness, "
      "Damping, Shear modulus and Loads/Self weight are then given by the "
      "entries of Units and must not be set. Results are written in SI "
      "units (doc/model.md, \"Scenes in SI units\").");
    const auto declare = [&](const std::string &name,
                             const std::string &default_value,
                             const std::string &documentation) {
      prm.declare_entry(name,
                        default_value,
                        Patterns::Double(0.0, 1e100),
                        documentation);
    };
    declare("Length",
            "0",
            "SI: L, the plate (a mesh file) along x [m]; 0: the sum of "
            "Slabs/Slab lengths, if given.");
    declare("Width",
            "0",
            "SI: the rectangle along y [m]; 0: the sum of Slabs/Slab widths, "
            "if given, else = Length.");
    declare("Thickness", "0", "SI: H [m].");
    declare("Young's modulus",
            "0",
            "SI: E [Pa]; with Plate/Poisson ratio nu, D = E H^3 / (12 (1 - "
            "nu^2)) and the shear modulus E / (2 (1 + nu)).");
    declare("Density", "2400", "SI: rho [kg/m^3]; concrete's by default.");
    declare("Gravity",
            "9.81",
            "SI: g [m/s^2]; the plate's weight rho g H [Pa] acts as "
            "Loads/Self weight does (0: a weightless plate).");
    declare("Subgrade modulus",
            "0",
            "SI: k, the Winkler springs' pressure per deflection [N/m^3].");
    declare("Dashpot coefficient",
            "0",
            "SI: the dashpots' pressure per velocity [Pa s/m]; 0: none.");
    declare("Shear layer modulus",
            "0",
            "SI: G_f of a Pasternak shear layer, its shear force per unit "
            "length and unit slope [N/m]; 0: none.");
    prm.leave_subsection();
  }


  void
  PhysicalUnits::watch(ParameterHandler &scene)
  {
    set_counts.clear();
    for (const auto &[path, entry] : declared_entries(scene))
      if ((path.rfind("Units/", 0) == 0 && path != "Units/System")
          || is_watched(entry))
        {
          const std::vector<std::string> names =
            Utilities::split_string_list(path, '/');
          for (unsigned int k = 0; k + 1 < names.size(); ++k)
            scene.enter_subsection(names[k]);
          auto count       = std::make_shared<unsigned int>(0);
          set_counts[path] = count;
          scene.add_action(names.back(),
                           [count](const std::string &) { ++*count; });
          for (unsigned int k = 0; k + 1 < names.size(); ++k)
            scene.leave_subsection();
        }
  }


  void
  PhysicalUnits::take_si_defaults(ParameterHandler &scene) const
  {
    scene.enter_subsection("Units");
    const System written =
      system_names.parse(scene.get("System"), "Units/System");
    scene.leave_subsection();
    if (written != System::si)
      return;
    for (const auto &[path, entry] : declared_entries(scene))
      if (const std::string value = si_default_of(entry.documentation);
          !value.empty() && !is_set(path))
        set_entry(scene, path, value, path + " = " + value);
  }


  bool
  PhysicalUnits::is_set(const std::string &path) const
  {
    return *set_counts.at(path) > 1;
  }


  void
  PhysicalUnits::parse_parameters(ParameterHandler   &scene,
                                  const SceneOutline &outline)
  {
    scene.enter_subsection("Units");
    system = system_names.parse(scene.get("System"), "Units/System");
    length = scene.get_double("Length");
    if (length == 0.0)
      length = outline.length_of_slabs;
    width = scene.get_double("Width");
    if (width == 0.0)
      width = outline.width_of_slabs > 0 ? outline.width_of_slabs : length;
    thickness        = scene.get_double("Thickness");
    youngs_modulus   = scene.get_double("Young's modulus");
    density          = scene.get_double("Density");
    gravity          = scene.get_double("Gravity");
    subgrade_modulus = scene.get_double("Subgrade modulus");
    dashpot          = scene.get_double("Dashpot coefficient");
    shear_layer      = scene.get_double("Shear layer modulus");
    scene.leave_subsection();
    poisson_ratio = outline.poisson_ratio;
    is_rectangle  = outline.is_rectangle;
    AssertThrow(!set_counts.empty(),
                ExcMessage("PhysicalUnits::watch() must see the scene's "
                           "handler before the scene is read into it."));

    if (system == System::dimensionless)
      {
        for (const auto &[path, count] : set_counts)
          AssertThrow(path.rfind("Units/", 0) != 0 || !is_set(path),
                      ExcMessage(path
                                 + " is an entry of a scene in SI "
                                   "units, but Units/System = "
                                   "dimensionless: set Units/System = "
                                   "SI, or leave "
                                 + path + " out."));
        return;
      }
    for (const auto &[path, entry] : declared_entries(scene))
      if (const auto quantities = declared_quantities(entry.documentation);
          !quantities.empty() && is_group(quantities[0]))
        AssertThrow(!is_set(path),
                    ExcMessage(path
                               + " is a dimensionless group, which a scene "
                                 "with Units/System = SI gives by "
                               + group_sources.at(quantities[0]).physical
                               + ": leave " + path
                               + " out (or write the scene dimensionless)."));
    check_physical_values(outline);

    bending_stiffness = youngs_modulus * std::pow(thickness, 3)
                        / (12 * (1 - poisson_ratio * poisson_ratio));
    t0 = length * length * std::sqrt(density * thickness / bending_stiffness);
    // The force scale is free (doc/model.md); D / L makes the solver's
    // deflection w / L, a number of order 1e-5 to 1e-2 for real slabs.
    f0 = bending_stiffness / length;
  }


  void
  PhysicalUnits::check_physical_values(const SceneOutline &outline) const
  {
    for (const auto &[name, value] :
         std::vector<std::pair<std::string, double>>{{"Length", length},
                                                     {"Thickness", thickness},
                                                     {"Young's modulus",
                                                      youngs_modulus},
                                                     {"Density", density}})
      AssertThrow(value > 0,
                  ExcMessage("Units/" + name
                             + " must be given (> 0) in a scene with "
                               "Units/System = SI."));
    // The bed's entries, which a choice of another class may require.
    const std::map<std::string, std::pair<double, std::string>> bed = {
      {"Subgrade modulus", {subgrade_modulus, "N/m^3"}},
      {"Dashpot coefficient", {dashpot, "Pa s/m"}},
      {"Shear layer modulus", {shear_layer, "N/m"}}};
    for (const auto &[name, reason] : outline.required)
      AssertThrow(bed.at(name).first > 0,
                  ExcMessage("Units/" + name + " must be given (> 0, in "
                             + bed.at(name).second
                             + ") in a scene with Units/System = SI and "
                             + reason + "."));
    for (const auto &[name, message] : outline.refused)
      AssertThrow(!is_set("Units/" + name), ExcMessage(message));
  }


  bool
  PhysicalUnits::is_physical() const
  {
    return system == System::si;
  }


  ParameterHandler &
  PhysicalUnits::solver_scene(
    ParameterHandler                              &scene,
    const std::function<void(ParameterHandler &)> &declare)
  {
    dimensionless_text.clear();
    if (!is_physical())
      return scene;
    converted = std::make_shared<ParameterHandler>();
    declare(*converted);
    convert(scene, *converted);
    // Without its Units subsection (all defaults), so that the twin runs
    // as it stands: setting a Units entry, even to its default, makes a
    // dimensionless scene a mix.
    std::stringstream text;
    converted->print_parameters(text, ParameterHandler::ShortPRM);
    bool in_units = false;
    for (std::string line; std::getline(text, line);)
      {
        const bool was_in_units = in_units;
        in_units = was_in_units ? line != "end" : line == "subsection Units";
        if (!in_units && !was_in_units)
          dimensionless_text += line + '\n';
      }
    return *converted;
  }


  std::string
  PhysicalUnits::record_of(const std::string &scene_text) const
  {
    if (!is_physical())
      return scene_text;
    // Both forms: the scene as written, which reruns it, and what the
    // solver read, for a dimensionless study of the same slab.
    std::string record = scene_text
                         + "\n# The dimensionless scene this SI scene was "
                           "converted to (doc/model.md, \"Scenes in SI "
                           "units\"):\n";
    std::istringstream lines(dimensionless_text);
    for (std::string line; std::getline(lines, line);)
      record += "# " + line + '\n';
    return record;
  }


  void
  PhysicalUnits::convert(ParameterHandler &scene,
                         ParameterHandler &dimensionless)
  {
    std::stringstream text;
    scene.print_parameters(text, ParameterHandler::ShortPRM);
    dimensionless.parse_input(text, "the scene");
    std::map<Quantity, double> units, groups;
    for (auto q = Quantity::number; q <= Quantity::self_weight;
         q      = static_cast<Quantity>(static_cast<int>(q) + 1))
      if (is_group(q))
        groups[q] = group_value(q);
      else if (q != Quantity::text)
        units[q] = si_scale(q);
    const SceneConverter convert{declared_entries(scene),
                                 [this](const std::string &path) {
                                   return is_set(path);
                                 },
                                 dimensionless,
                                 length,
                                 width,
                                 t0,
                                 is_rectangle,
                                 units};
    twin_values.clear();
    group_entries.clear();
    convert.convert_all(groups, twin_values, group_entries);
    convert.reset_physical_entries();
  }


  double
  PhysicalUnits::group_value(const Quantity group) const
  {
    switch (group)
      {
      case Quantity::mu:
        return width / length;
      case Quantity::Delta:
        return thickness / length;
      case Quantity::Gamma:
        return subgrade_modulus * std::pow(length, 4) / bending_stiffness;
      case Quantity::damping:
        return dashpot * length * length
               / std::sqrt(density * thickness * bending_stiffness);
      case Quantity::shear_layer:
        return shear_layer * length * length / bending_stiffness;
      case Quantity::self_weight:
        return density * gravity * thickness / scale(Quantity::pressure);
      default:
        Assert(false, ExcInternalError());
        return 0;
      }
  }


  std::vector<std::pair<std::string, double>>
  PhysicalUnits::groups() const
  {
    std::vector<std::pair<std::string, double>> list = {
      {"D [N m]", bending_stiffness},
      {"mu", width / length},
      {"Delta", thickness / length},
      {"Gamma", subgrade_modulus * std::pow(length, 4) / bending_stiffness},
      {"t0 [s]", t0}};
    if (subgrade_modulus > 0)
      list.emplace_back("l [m]",
                        std::pow(bending_stiffness / subgrade_modulus, 0.25));
    list.emplace_back("F0 = D/L [N]", f0);
    return list;
  }


  void
  PhysicalUnits::explain_errors_of(const std::function<void()> &read) const
  {
    if (!is_physical())
      return read();
    try
      {
        read();
      }
    catch (const std::exception &e)
      {
        AssertThrow(false,
                    ExcMessage(in_scene_terms(message_of(e))
                               + " (This SI scene runs as its dimensionless "
                                 "twin, whose numbers the message quotes: "
                                 "lengths in L = "
                               + format_number(length)
                               + " m, times in t0 = " + format_number(t0)
                               + " s, forces in F0 = " + format_number(f0)
                               + " N; doc/model.md, \"Scenes in SI "
                                 "units\".)"));
      }
  }


  void
  PhysicalUnits::explain_run_errors_of(const std::function<void()> &run) const
  {
    if (!is_physical())
      return run();
    try
      {
        run();
      }
    catch (const ExcMessage &e)
      {
        const std::string message = message_of(e);
        const std::string terms   = in_scene_terms(message);
        if (terms == message)
          throw;
        AssertThrow(false, ExcMessage(terms));
      }
  }


  std::string
  PhysicalUnits::with_written_numbers(const std::string &message) const
  {
    // A number an owner quotes as <value> in its own format (fewer digits
    // than the twin's text) is the entry whose twin value it rounds, if
    // one does.
    static const std::regex quoted(R"(<([-+0-9.eE]+)>)");
    return replace_matches(message, quoted, [&](const std::smatch &m) {
      std::string token = m[0].str();
      if (Patterns::Double().match(m[1].str()))
        for (const auto &[path, entry] : twin_values)
          if (Patterns::Double().match(entry.twin))
            {
              const double quoted_value = std::stod(m[1].str());
              const double twin         = std::stod(entry.twin);
              if (twin != 0
                  && std::abs(quoted_value - twin) <= 1e-7 * std::abs(twin))
                token = "<" + entry.si + ">";
            }
      return token;
    });
  }


  std::string
  PhysicalUnits::in_scene_terms(std::string message) const
  {
    if (!is_physical())
      return message;
    const auto replace = [&](const std::string &from, const std::string &to) {
      message = Utilities::replace_in_string(message, from, to);
    };
    // An owner quotes a value it refuses as <value>: the twin's, not what
    // the user wrote.
    for (const auto &[path, entry] : twin_values)
      {
        replace("<" + entry.twin + ">", "<" + entry.si + ">");
        replace("<" + abbreviated(entry.twin) + ">",
                "<" + abbreviated(entry.si) + ">");
      }
    message = with_written_numbers(message);
    message = with_seconds(message, t0);
    message = with_tagged_numbers(message, [this](const Quantity q) {
      return scale(q);
    });
    // A group the message names is an entry the scene cannot set.
    for (const auto &[path, group] : group_entries)
      if (const auto at = message.find(path); at != std::string::npos)
        message.insert(at + path.size(),
                       " (in this SI scene " + origin_of(group) + ")");
    // A number of the twin beyond 1e100 (or below 1e-100) is a unit of
    // these Units far from the slab's: the likely cause, whatever
    // overflowed.
    // An entry the scene wrote before one left at its default (the
    // Duration of a deflectometer that is off).
    for (const bool defaults : {false, true})
      for (const auto &[path, entry] : twin_values)
        for (const auto &[item, separator] : items_of(
               group_entries.count(path) == 0 && entry.is_default == defaults
                 ? entry.twin
                 : ""))
          if (Patterns::Double().match(item))
            if (const double x = std::abs(Utilities::string_to_double(item));
                x > 1e100 || (x > 0 && x < 1e-100))
              return message + " The cause in this SI scene: " + path + " = "
                     + entry.si + " is " + item + " in the solver's unit of "
                     + name_of(entry.quantity) + ", "
                     + unit_origin(entry.quantity) + ".";
    return message;
  }


  std::string
  PhysicalUnits::stiffness_origin() const
  {
    return "D = E H^3 / (12 (1 - nu^2)) = " + format_number(bending_stiffness)
           + " N m from Units/Young's modulus = "
           + format_number(youngs_modulus)
           + " Pa and Units/Thickness = " + format_number(thickness) + " m";
  }


  std::string
  PhysicalUnits::unit_origin(const Quantity quantity) const
  {
    const std::string plate = stiffness_origin();
    if (quantity == Quantity::time || quantity == Quantity::velocity
        || quantity == Quantity::angular_velocity)
      return "t0 = L^2 sqrt(rho H / D) = " + format_number(t0)
             + " s from Units/Density = " + format_number(density)
             + " kg/m^3, Units/Length = " + format_number(length) + " m and "
             + plate;
    if (quantity == Quantity::force || quantity == Quantity::pressure
        || quantity == Quantity::force_per_length)
      return "F0 = D / L = " + format_number(f0) + " N from " + plate
             + " and Units/Length = " + format_number(length) + " m";
    if (quantity == Quantity::temperature_difference)
      return "the scene's own (K, not converted)";
    return "L = Units/Length = " + format_number(length) + " m";
  }


  std::string
  PhysicalUnits::origin_of(const Quantity group) const
  {
    const auto value =
      [](const std::string &entry, const double x, const std::string &unit) {
        return "Units/" + entry + " = " + format_number(x) + " " + unit;
      };
    const std::string plate = stiffness_origin();
    const std::string l     = value("Length", length, "m");
    if (group == Quantity::mu)
      return "W / L = " + format_number(width / length) + " from "
             + value("Width", width, "m") + " and " + l;
    if (group == Quantity::Delta)
      return "H / L = " + format_number(thickness / length) + " from "
             + value("Thickness", thickness, "m") + " and " + l;
    if (group == Quantity::Gamma)
      return "k L^4 / D = "
             + format_number(subgrade_modulus * std::pow(length, 4)
                             / bending_stiffness)
             + " from " + value("Subgrade modulus", subgrade_modulus, "N/m^3")
             + ", " + l + " and " + plate;
    if (group == Quantity::damping)
      return "C L^2 / sqrt(rho H D) from "
             + value("Dashpot coefficient", dashpot, "Pa s/m") + ", "
             + value("Density", density, "kg/m^3") + " and " + plate;
    if (group == Quantity::shear_layer)
      return "G_f L^2 / D from "
             + value("Shear layer modulus", shear_layer, "N/m") + " and "
             + plate;
    return "rho g H from " + value("Density", density, "kg/m^3") + " and "
           + value("Gravity", gravity, "m/s^2");
  }


  std::string
  PhysicalUnits::groups_line() const
  {
    if (!is_physical())
      return "";
    std::string line = "\nliftoff: SI scene:";
    for (const auto &[name, value] : groups())
      line +=
        (line.back() == ':' ? " " : ", ") + name + " = " + format_number(value);
    return line;
  }


  double
  PhysicalUnits::si_scale(const Quantity quantity) const
  {
    // With F0 = D / L the deflection scale F0 L^2 / D is L and rotations
    // are in radians; the products are kept so that the table reads as
    // doc/model.md's units.
    const double w = f0 * length * length / bending_stiffness;
    switch (quantity)
      {
      case Quantity::length:
      case Quantity::position:
        return length;
      case Quantity::deflection:
        return w;
      case Quantity::time:
        return t0;
      case Quantity::force:
      case Quantity::moment:
        return f0;
      case Quantity::pressure:
        return f0 / (length * length);
      case Quantity::pressure_per_length:
        return f0 / (length * length) / length;
      case Quantity::area:
        return length * length;
      case Quantity::energy:
        return f0 * w;
      case Quantity::force_per_length:
        return f0 / length;
      case Quantity::rotation:
      case Quantity::thermal_expansion:
        return w / length;
      case Quantity::velocity:
        return w / t0;
      case Quantity::angular_velocity:
        return w / (length * t0);
      case Quantity::frequency:
        return 1 / t0;
      default:
        return 1;
      }
  }


  double
  PhysicalUnits::scale(const Quantity quantity) const
  {
    return is_physical() ? si_scale(quantity) : 1;
  }


  std::string
  PhysicalUnits::unit(const Quantity quantity) const
  {
    const std::string &symbol = si_symbol(quantity);
    return is_physical() && symbol != "1" ? " [" + symbol + "]" : "";
  }


  std::string
  PhysicalUnits::unit_symbol(const Quantity quantity) const
  {
    return is_physical() ? si_symbol(quantity) : dimensionless_scales(quantity);
  }
} // namespace liftoff
