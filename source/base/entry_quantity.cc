#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <liftoff/base/entry_quantity.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <functional>
#include <regex>
#include <sstream>

namespace liftoff
{
  namespace
  {
    const std::string tag_start = "[quantity: ";
    const std::string if_set    = " (if set)";
    const std::string si_start  = "[SI default: ";
  } // namespace


  namespace
  {
    // The one table of the quantities: each with its name, its SI unit and
    // the dimensionless scales of doc/model.md it is made of. The SI value
    // of one unit depends on the scene (PhysicalUnits::scale()).
    struct Spelling
    {
      Quantity    quantity;
      std::string name, si_symbol, scales;
    };
    const std::vector<Spelling> &
    spellings()
    {
      // Built at its first use: entries may be declared while statics are
      // being initialised.
      static const std::vector<Spelling> table = {
        {Quantity::number, "number", "1", "1"},
        {Quantity::text, "text", "", ""},
        {Quantity::length, "length", "m", "L"},
        {Quantity::position, "position", "m", "L"},
        {Quantity::deflection, "deflection", "m", "F0*L^2/D"},
        {Quantity::rotation, "rotation", "rad", "F0*L/D"},
        {Quantity::time, "time", "s", "t0"},
        {Quantity::force, "force", "N", "F0"},
        {Quantity::pressure, "pressure", "Pa", "F0/L^2"},
        {Quantity::force_per_length, "force per length", "N/m", "F0/L"},
        {Quantity::pressure_per_length,
         "pressure per length",
         "Pa/m",
         "F0/L^3"},
        {Quantity::velocity, "velocity", "m/s", "F0*L^2/(D*t0)"},
        {Quantity::angular_velocity,
         "angular velocity",
         "rad/s",
         "F0*L/(D*t0)"},
        {Quantity::area, "area", "m^2", "L^2"},
        {Quantity::energy, "energy", "J", "F0^2*L^2/D"},
        {Quantity::moment, "moment per length", "N m/m", "F0"},
        {Quantity::angle_degrees, "angle in degrees", "degree", "degree"},
        {Quantity::temperature_difference, "temperature difference", "K", "K"},
        {Quantity::thermal_expansion, "thermal expansion", "1/K", "F0*L/(D*K)"},
        {Quantity::frequency, "frequency", "rad/s", "1/t0"},
        {Quantity::mu, "mu", "1", "mu"},
        {Quantity::Delta, "Delta", "1", "Delta"},
        {Quantity::Gamma, "Gamma", "1", "Gamma"},
        {Quantity::damping, "damping", "1", "damping"},
        {Quantity::shear_layer, "shear layer", "1", "shear layer"},
        {Quantity::self_weight, "self weight", "1", "self weight"}};
      return table;
    }

    const Spelling &
    spelling_of(const Quantity quantity)
    {
      const auto s = std::find_if(spellings().begin(),
                                  spellings().end(),
                                  [quantity](const Spelling &s) {
                                    return s.quantity == quantity;
                                  });
      Assert(s != spellings().end(), ExcInternalError());
      return *s;
    }
  } // namespace


  const std::string &
  name_of(const Quantity quantity)
  {
    return spelling_of(quantity).name;
  }


  const std::string &
  si_symbol(const Quantity quantity)
  {
    return spelling_of(quantity).si_symbol;
  }


  const std::string &
  dimensionless_scales(const Quantity quantity)
  {
    return spelling_of(quantity).scales;
  }


  bool
  is_group(const Quantity quantity)
  {
    return quantity >= Quantity::mu;
  }


  Quantity
  quantity_named(const std::string &name)
  {
    const auto s =
      std::find_if(spellings().begin(),
                   spellings().end(),
                   [&name](const Spelling &s) { return s.name == name; });
    std::string known;
    for (const Spelling &each : spellings())
      known += (known.empty() ? "" : ", ") + each.name;
    AssertThrow(s != spellings().end(),
                ExcMessage("An entry is declared with the quantity <" + name
                           + ">, which is none of " + known + "."));
    return s->quantity;
  }


  std::string
  quantity(const std::string &names)
  {
    const std::string tag = " " + tag_start + names + "]";
    declared_quantities(tag);
    return tag;
  }


  std::vector<Quantity>
  declared_quantities(const std::string &documentation)
  {
    const auto start = documentation.rfind(tag_start);
    if (start == std::string::npos || documentation.back() != ']')
      return {};
    std::string names =
      documentation.substr(start + tag_start.size(),
                           documentation.size() - 1 - start - tag_start.size());
    if (names.size() > if_set.size()
        && names.compare(names.size() - if_set.size(), if_set.size(), if_set)
             == 0)
      names.resize(names.size() - if_set.size());
    std::vector<Quantity> quantities;
    for (const std::string &name : Utilities::split_string_list(names, ','))
      quantities.push_back(quantity_named(name));
    return quantities;
  }


  bool
  converts_only_if_set(const std::string &documentation)
  {
    const std::string tail = if_set + "]";
    return documentation.size() > tail.size()
           && documentation.compare(documentation.size() - tail.size(),
                                    tail.size(),
                                    tail)
                == 0;
  }


  std::string
  tagged(const std::string &number, const Quantity quantity)
  {
    return number + " [" + dimensionless_scales(quantity) + "]";
  }


  std::string
  si_default(const std::string &value)
  {
    return " " + si_start + value + "]";
  }


  std::string
  si_default_of(const std::string &documentation)
  {
    const auto start = documentation.rfind(si_start);
    if (start == std::string::npos)
      return "";
    const auto from = start + si_start.size();
    const auto end  = documentation.find(']', from);
    return end == std::string::npos ? ""
                                    : documentation.substr(from, end - from);
  }


  std::map<std::string, DeclaredEntry>
  declared_entries(const ParameterHandler &prm)
  {
    std::stringstream json;
    prm.print_parameters(json, ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    std::map<std::string, DeclaredEntry> entries;
    const std::function<void(const boost::property_tree::ptree &,
                             const std::string &)>
      collect =
        [&](const boost::property_tree::ptree &node, const std::string &path) {
          for (const auto &[key, child] : node)
            if (const auto value = child.get_optional<std::string>("value"))
              entries[path + key] = {*value,
                                     child.get<std::string>("default_value"),
                                     child.get<std::string>(
                                       "pattern_description"),
                                     child.get<std::string>("documentation")};
            else
              collect(child, path + key + "/");
        };
    collect(tree, "");
    return entries;
  }
} // namespace liftoff
