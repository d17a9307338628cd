#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <liftoff/base/number_text.h>
#include <liftoff/base/output_files.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/base/selection.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <array>
#include <charconv>
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
    using System                         = PhysicalUnits::System;
    const Selection<System> system_names = {{"dimensionless",
                                             System::dimensionless},
                                            {"SI", System::si}};

    // The dimensionless groups an SI scene gives by its physical entries:
    // a scene that sets both is refused, naming both.
    const std::vector<std::pair<std::string, std::string>> replaced_entries = {
      {"Plate/Aspect ratio", "Units/Width"},
      {"Plate/Thickness ratio", "Units/Thickness"},
      {"Foundation/Stiffness", "Units/Subgrade modulus"},
      {"Foundation/Damping", "Units/Dashpot coefficient"},
      {"Foundation/Shear modulus", "Units/Shear layer modulus"},
      {"Loads/Self weight", "Units/Density and Units/Gravity"}};

    // The shortest text that reads back as x, so that the dimensionless
    // scene is the SI one exactly.
    std::string
    exact(const double x)
    {
      std::array<char, 32> text;
      const auto end = std::to_chars(text.data(), text.data() + text.size(), x);
      return std::string(text.data(), end.ptr);
    }

    /**
     * How often each watched entry of a ParameterHandler was given a value:
     * ParameterHandler keeps only the value, and a group set to its
     * default beside the physical entry that replaces it is a mix all the
     * same. An action counts (ParameterHandler runs it once with the
     * default when it is added, then at every set). Keyed by the handler's
     * address: a handler declared later at the same address replaces the
     * counters.
     */
    std::map<const ParameterHandler *,
             std::map<std::string, std::shared_ptr<unsigned int>>> &
    set_counts()
    {
      static std::map<const ParameterHandler *,
                      std::map<std::string, std::shared_ptr<unsigned int>>>
        counts;
      return counts;
    }

    void
    watch(ParameterHandler &prm, const std::string &path)
    {
      const std::vector<std::string> names =
        Utilities::split_string_list(path, '/');
      for (unsigned int k = 0; k + 1 < names.size(); ++k)
        prm.enter_subsection(names[k]);
      auto count               = std::make_shared<unsigned int>(0);
      set_counts()[&prm][path] = count;
      prm.add_action(names.back(), [count](const std::string &) { ++*count; });
      for (unsigned int k = 0; k + 1 < names.size(); ++k)
        prm.leave_subsection();
    }

    // Whether the scene gave `path` a value (watched entries only).
    bool
    is_set(const ParameterHandler &prm, const std::string &path)
    {
      return *set_counts().at(&prm).at(path) > 1;
    }

    struct Entry
    {
      std::string value, default_value;
    };

    // Every entry of `prm` by its path "Subsection/Entry", with its value
    // and default, from ParameterHandler's own tree in its JSON form.
    std::map<std::string, Entry>
    entries_of(const ParameterHandler &prm)
    {
      std::stringstream json;
      prm.print_parameters(json, ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      std::map<std::string, Entry> entries;
      const std::function<void(const boost::property_tree::ptree &,
                               const std::string &)>
        collect = [&](const boost::property_tree::ptree &node,
                      const std::string                 &path) {
          for (const auto &[key, child] : node)
            if (const auto value = child.get_optional<std::string>("value"))
              entries[path + key] = {*value,
                                     child.get<std::string>("default_value")};
            else
              collect(child, path + key + "/");
        };
      collect(tree, "");
      return entries;
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

    // A list of numbers divided by `unit` one by one.
    std::string
    divided_list(const std::string &text,
                 const double       unit,
                 const char         separator = ',')
    {
      std::string result;
      for (const double x : Utilities::string_to_double(
             Utilities::split_string_list(text, separator)))
        result += (result.empty() ? "" : std::string(1, separator) + " ")
                  + exact(x / unit);
      return result;
    }
    /**
     * The entries of an SI scene written into its dimensionless twin
     * `out`: values divided by their unit, lists of points and times,
     * muParser expressions in x, y [m] and t [s] rewritten in the solver's
     * x, y and tau. Each error names the entry as the user wrote it.
     */
    struct SceneConverter
    {
      std::map<std::string, Entry> entries;
      ParameterHandler            &out;
      double                       length, width, t0, w_unit, psi_unit;

      void
      set(const std::string &path,
          const double       value,
          const std::string &written) const
      {
        set_entry(out, path, exact(value), written);
      }

      double
      value(const std::string &path) const
      {
        return Utilities::string_to_double(entries.at(path).value);
      }

      std::string
      expression(const std::string &path) const
      {
        static const std::regex name("[A-Za-z_][A-Za-z0-9_]*");
        const std::string       si = entries.at(path).value;
        std::string             result;
        auto                    from = si.cbegin();
        for (std::sregex_iterator i(si.begin(), si.end(), name), end; i != end;
             ++i)
          {
            const std::string word = i->str();
            AssertThrow(word != "tau",
                        ExcMessage(path + " = <" + si
                                   + ">: a scene with Units/System = SI "
                                     "writes time as t in seconds, not "
                                     "tau."));
            result.append(from, (*i)[0].first);
            from = (*i)[0].second;
            if (word == "x" || word == "y")
              result += "(" + exact(length) + "*" + word + ")";
            else if (word == "t")
              result += "(" + exact(t0) + "*tau)";
            else
              result += word;
          }
        return result.append(from, si.cend());
      }

      void
      set_expression(const std::string &path,
                     const std::string &prefix = "",
                     const std::string &suffix = "") const
      {
        set_entry(out,
                  path,
                  prefix + expression(path) + suffix,
                  path + " = <" + entries.at(path).value + ">");
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
        if (entries.at("Discretization/Shape").value != "rectangle")
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

      // Points "x, y" separated by `separator`, in metres from the
      // plate's centre; one outside the plate is refused in metres.
      void
      set_positions(const std::string &path, const char separator = ';') const
      {
        std::string result;
        for (const std::string &point :
             Utilities::split_string_list(entries.at(path).value, separator))
          {
            const auto xy = Utilities::string_to_double(
              Utilities::split_string_list(point, ','));
            check_on_plate(path, point, xy[0], xy[1]);
            result += (result.empty() ? "" : std::string(1, separator) + " ")
                      + divided_list(point, length);
          }
        set_entry(out,
                  path,
                  result,
                  path + " = " + entries.at(path).value + " [m]");
      }

      // Every numbered load of Loads: its magnitude in N, Pa or N/m, its
      // position or region in m, its expressions.
      void
      loads(const double force, const double pressure, const double line) const
      {
        for (const auto &[path, entry] : entries)
          {
            if (path.rfind("Loads/", 0) != 0)
              continue;
            const std::string section = path.substr(0, path.rfind('/') + 1);
            const std::string name    = path.substr(section.size());
            const auto        is      = [&](const std::string &kind) {
              return section.rfind("Loads/" + kind, 0) == 0;
            };
            const double unit = is("Point load") || is("Vehicle")    ? force
                                : is("Pressure") || is("Patch load") ? pressure
                                                                     : line;
            if (name == "Magnitude")
              set(path, value(path) / unit, path + " = " + entry.value);
            else if (name == "Time history" || name == "Intensity")
              set_expression(path);
            else if (name == "Position")
              set_positions(path);
            else if (name == "Path" && !entry.value.empty())
              path_in_metres(path);
            else if (name == "Size" || name == "Wheel size")
              set_entry(out,
                        path,
                        divided_list(entry.value, length),
                        path + " = " + entry.value + " [m]");
            else if (name == "Wheels")
              wheels_in_metres(path);
            else if (name == "Region" && entry.value != "whole plate")
              set_entry(out,
                        path,
                        divided_list(entry.value, length),
                        path + " = " + entry.value + " [m]");
          }
      }

      // x(t); y(t) in metres and seconds: t becomes t0 tau, the position
      // is divided by L.
      void
      path_in_metres(const std::string &path) const
      {
        const auto xy = Utilities::split_string_list(expression(path), ';');
        AssertThrow(xy.size() == 2,
                    ExcMessage(path + " = <" + entries.at(path).value
                               + "> must be x(t); y(t), two muParser "
                                 "expressions in t [s] separated by ';'."));
        set_entry(out,
                  path,
                  "(" + xy[0] + ")/" + exact(length) + "; (" + xy[1] + ")/"
                    + exact(length),
                  path + " = <" + entries.at(path).value + ">");
      }

      // dx, dy, share; ... with the offsets in metres.
      void
      wheels_in_metres(const std::string &path) const
      {
        std::string result;
        for (const std::string &wheel :
             Utilities::split_string_list(entries.at(path).value, ';'))
          {
            const auto v = Utilities::split_string_list(wheel, ',');
            AssertThrow(v.size() == 3 && Patterns::Double().match(v[0])
                          && Patterns::Double().match(v[1]),
                        ExcMessage(path + " = <" + entries.at(path).value
                                   + "> must be dx, dy, share; ... with the "
                                     "offsets in metres."));
            result += (result.empty() ? "" : "; ")
                      + divided_list(v[0] + ", " + v[1], length) + ", " + v[2];
          }
        set_entry(out,
                  path,
                  result,
                  path + " = " + entries.at(path).value + " [m]");
      }

      void
      times_and_points() const
      {
        for (const std::string path :
             {"Time integration/Time step", "Time integration/End time"})
          set(path, value(path) / t0, path + " = " + entries.at(path).value);
        const std::string times = "Output/Profile times";
        set_entry(out,
                  times,
                  divided_list(entries.at(times).value, t0),
                  times + " = " + entries.at(times).value);
        for (const std::string path : {"Output/Probe points",
                                       "Output/Profile start",
                                       "Output/Profile end"})
          set_positions(path);
        quantity_probes();
      }

      // NAME(x; y), ... with x, y in metres from the plate's centre; the
      // form itself is checked where the dimensionless scene is read.
      void
      quantity_probes() const
      {
        const std::string path = "Output/Probe quantities";
        const std::regex  point(R"(\(([^;()]*);([^;()]*)\))");
        const std::string text = entries.at(path).value;
        std::string       result;
        auto              from = text.cbegin();
        for (std::sregex_iterator i(text.begin(), text.end(), point), end;
             i != end;
             ++i)
          {
            result.append(from, (*i)[0].first);
            from                  = (*i)[0].second;
            const auto coordinate = [&](const std::string &x) {
              return Patterns::Double().match(Utilities::trim(x))
                       ? divided_list(x, length)
                       : x;
            };
            const std::string x = (*i)[1].str(), y = (*i)[2].str();
            if (Patterns::Double().match(Utilities::trim(x))
                && Patterns::Double().match(Utilities::trim(y)))
              check_on_plate(path,
                             (*i)[0].str(),
                             Utilities::string_to_double(Utilities::trim(x)),
                             Utilities::string_to_double(Utilities::trim(y)));
            result += "(" + coordinate(x) + "; " + coordinate(y) + ")";
          }
        set_entry(out,
                  path,
                  result.append(from, text.cend()),
                  path + " = " + text + " [m]");
      }

      // w; psi_x; psi_y in m and rad, and their velocities.
      void
      initial_conditions() const
      {
        for (const auto &[field, time_unit] :
             std::vector<std::pair<std::string, double>>{{"Displacement", 1.0},
                                                         {"Velocity", t0}})
          {
            const std::string path = "Initial conditions/" + field;
            const auto        parts =
              Utilities::split_string_list(expression(path), ';');
            AssertThrow(parts.size() == 3,
                        ExcMessage(path
                                   + " must be three muParser expressions "
                                     "separated by ';' (w; psi_x; psi_y)."));
            set_entry(out,
                      path,
                      "(" + parts[0] + ")*" + exact(time_unit / w_unit) + "; ("
                        + parts[1] + ")*" + exact(time_unit / psi_unit) + "; ("
                        + parts[2] + ")*" + exact(time_unit / psi_unit),
                      path + " = <" + entries.at(path).value + ">");
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
    std::vector<std::string> physical;
    const auto               declare = [&](const std::string &name,
                             const std::string &default_value,
                             const std::string &documentation) {
      prm.declare_entry(name,
                        default_value,
                        Patterns::Double(0.0, 1e100),
                        documentation);
      physical.push_back("Units/" + name);
    };
    declare("Length", "0", "SI: L, the plate (a mesh file) along x [m].");
    declare("Width", "0", "SI: the rectangle along y [m]; 0: = Length.");
    declare("Thickness", "0", "SI: H [m].");
    declare("Young's modulus",
            "0",
            "SI: E [Pa]; with Plate/Poisson ratio nu, D = E H^3 / (12 (1 - "
            "nu^2)) and the shear modulus E / (2 (1 + nu)).");
    declare("Density", "0", "SI: rho [kg/m^3].");
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
    for (const std::string &path : physical)
      watch(prm, path);
    for (const auto &[group, physical_entry] : replaced_entries)
      watch(prm, group);
    // In metres where an SI scene sets them (convert()).
    watch(prm, "Discretization/Radius");
    watch(prm, "Discretization/Inner radius");
  }


  void
  PhysicalUnits::parse_parameters(ParameterHandler &scene)
  {
    scene.enter_subsection("Units");
    system = system_names.parse(scene.get("System"), "Units/System");
    length = scene.get_double("Length");
    width  = scene.get_double("Width");
    if (width == 0.0)
      width = length;
    thickness        = scene.get_double("Thickness");
    youngs_modulus   = scene.get_double("Young's modulus");
    density          = scene.get_double("Density");
    gravity          = scene.get_double("Gravity");
    subgrade_modulus = scene.get_double("Subgrade modulus");
    dashpot          = scene.get_double("Dashpot coefficient");
    shear_layer      = scene.get_double("Shear layer modulus");
    scene.leave_subsection();
    scene.enter_subsection("Plate");
    poisson_ratio = scene.get_double("Poisson ratio");
    scene.leave_subsection();

    if (system == System::dimensionless)
      {
        for (const auto &[path, count] : set_counts().at(&scene))
          AssertThrow(path.rfind("Units/", 0) != 0 || !is_set(scene, path),
                      ExcMessage(path
                                 + " is an entry of a scene in SI "
                                   "units, but Units/System = "
                                   "dimensionless: set Units/System = "
                                   "SI, or leave "
                                 + path + " out."));
        return;
      }
    for (const auto &[group, physical] : replaced_entries)
      AssertThrow(!is_set(scene, group),
                  ExcMessage(group
                             + " is a dimensionless group, which a scene "
                               "with Units/System = SI gives by "
                             + physical + ": leave " + group
                             + " out (or write the scene dimensionless)."));
    check_physical_values(scene);

    bending_stiffness = youngs_modulus * std::pow(thickness, 3)
                        / (12 * (1 - poisson_ratio * poisson_ratio));
    t0 = length * length * std::sqrt(density * thickness / bending_stiffness);
    // The force scale is free (doc/model.md); D / L makes the solver's
    // deflection w / L, a number of order 1e-5 to 1e-2 for real slabs.
    f0 = bending_stiffness / length;
  }


  void
  PhysicalUnits::check_physical_values(ParameterHandler &scene) const
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
    scene.enter_subsection("Foundation");
    const bool has_bed = scene.get("Model") != "none";
    scene.leave_subsection();
    AssertThrow(!has_bed || subgrade_modulus > 0,
                ExcMessage("Units/Subgrade modulus must be given (> 0, in "
                           "N/m^3) in a scene with Units/System = SI and a "
                           "Foundation/Model other than none."));
    // A mesh file's outline is its own; its length along x is checked
    // against Units/Length where the mesh is read (PlateGeometry).
    scene.enter_subsection("Discretization");
    const bool is_mesh_file = scene.get("Shape") == "mesh file";
    scene.leave_subsection();
    AssertThrow(!is_mesh_file || !is_set(scene, "Units/Width"),
                ExcMessage("Units/Width is the width of the rectangle; with "
                           "Discretization/Shape = mesh file the mesh, in "
                           "metres, is the plate and Units/Length its length "
                           "along x: leave Units/Width out."));
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
                         ParameterHandler &dimensionless) const
  {
    std::stringstream text;
    scene.print_parameters(text, ParameterHandler::ShortPRM);
    dimensionless.parse_input(text, "the scene");
    const SceneConverter convert{entries_of(scene),
                                 dimensionless,
                                 length,
                                 width,
                                 t0,
                                 scale(Quantity::deflection),
                                 f0 * length / bending_stiffness};

    // The plate and the bed.
    convert.set("Plate/Aspect ratio", width / length, "Units/Width / Length");
    convert.set("Plate/Thickness ratio",
                thickness / length,
                "Units/Thickness / Units/Length");
    convert.set("Foundation/Stiffness",
                subgrade_modulus * std::pow(length, 4) / bending_stiffness,
                "Units/Subgrade modulus k L^4 / D");
    convert.set("Foundation/Damping",
                dashpot * length * length
                  / std::sqrt(density * thickness * bending_stiffness),
                "Units/Dashpot coefficient C L^2 / sqrt(rho H D)");
    convert.set("Foundation/Shear modulus",
                shear_layer * length * length / bending_stiffness,
                "Units/Shear layer modulus G_f L^2 / D");
    convert.set("Loads/Self weight",
                density * gravity * thickness / scale(Quantity::pressure),
                "Units/Density * Gravity * Thickness");
    convert.set_expression("Foundation/Initial gap",
                           "(",
                           ")/" + exact(convert.w_unit));

    convert.loads(scale(Quantity::force),
                  scale(Quantity::pressure),
                  scale(Quantity::shear_force));
    convert.times_and_points();
    convert.initial_conditions();
    // The radii of a disc or an annulus in metres where the scene gives
    // them; unset, they stay the dimensionless defaults (R = L / 2,
    // R_i = L / 4).
    for (const std::string radius :
         {"Discretization/Radius", "Discretization/Inner radius"})
      if (is_set(scene, radius))
        convert.set(radius,
                    convert.value(radius) / length,
                    radius + " = " + convert.entries.at(radius).value + " [m]");
    convert.reset_physical_entries();
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
                    ExcMessage(message_of(e)
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


  PhysicalUnits::Measure
  PhysicalUnits::measure(const Quantity quantity) const
  {
    // With F0 = D / L the deflection scale F0 L^2 / D is L and rotations
    // are in radians; the products are kept so that the table reads as
    // doc/model.md's units.
    const double w = f0 * length * length / bending_stiffness;
    switch (quantity)
      {
      case Quantity::length:
        return {length, "m", "L"};
      case Quantity::deflection:
        return {w, "m", "F0*L^2/D"};
      case Quantity::time:
        return {t0, "s", "t0"};
      case Quantity::force:
        return {f0, "N", "F0"};
      case Quantity::pressure:
        return {f0 / (length * length), "Pa", "F0/L^2"};
      case Quantity::area:
        return {length * length, "m^2", "L^2"};
      case Quantity::energy:
        return {f0 * w, "J", "F0^2*L^2/D"};
      case Quantity::moment:
        return {f0, "N m/m", "F0"};
      case Quantity::shear_force:
        return {f0 / length, "N/m", "F0/L"};
      case Quantity::rotation:
        return {w / length, "rad", "F0*L/D"};
      case Quantity::velocity:
        return {w / t0, "m/s", "F0*L^2/(D*t0)"};
      case Quantity::angular_velocity:
        return {w / (length * t0), "rad/s", "F0*L/(D*t0)"};
      case Quantity::angle_degrees:
        return {1, "degree", "degree"};
      default:
        return {1, "1", "1"};
      }
  }


  double
  PhysicalUnits::scale(const Quantity quantity) const
  {
    return is_physical() ? measure(quantity).si_scale : 1;
  }


  std::string
  PhysicalUnits::unit(const Quantity quantity) const
  {
    const std::string symbol = measure(quantity).si_symbol;
    return is_physical() && symbol != "1" ? " [" + symbol + "]" : "";
  }


  std::string
  PhysicalUnits::unit_symbol(const Quantity quantity) const
  {
    const Measure m = measure(quantity);
    return is_physical() ? m.si_symbol : m.scales;
  }
} // namespace liftoff
