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
  } // namespace


  const std::vector<std::string> &
  quantity_names()
  {
    static const std::vector<std::string> names = {"number",
                                                   "text",
                                                   "length",
                                                   "position",
                                                   "deflection",
                                                   "rotation",
                                                   "time",
                                                   "force",
                                                   "pressure",
                                                   "force per length",
                                                   "velocity",
                                                   "angular velocity",
                                                   "mu",
                                                   "Delta",
                                                   "Gamma",
                                                   "damping",
                                                   "shear layer",
                                                   "self weight",
                                                   "temperature difference",
                                                   "thermal expansion",
                                                   "pressure per length"};
    return names;
  }


  std::string
  quantity(const std::string &names)
  {
    const std::string tag = " " + tag_start + names + "]";
    for (const std::string &name : declared_quantities(tag))
      AssertThrow(
        std::count(quantity_names().begin(), quantity_names().end(), name) == 1,
        ExcMessage("An entry is declared with the quantity <" + name
                   + ">, which is none of quantity_names()."));
    return tag;
  }


  std::vector<std::string>
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
    return Utilities::split_string_list(names, ',');
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
