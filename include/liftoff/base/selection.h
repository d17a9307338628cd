#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The names of an enum parameter and the values they stand for. One table
   * builds both the entry's Patterns::Selection and its parse, so every name
   * the pattern accepts has a value; a name that is not in the table (a
   * ParameterHandler that skipped the pattern) is an error, never a silent
   * default.
   *
   *   const Selection<Model> models = {{"tensionless", Model::tensionless},
   *                                    {"none", Model::none}};
   *   prm.declare_entry("Model", "tensionless", models.pattern(), "...");
   *   model = models.parse(prm.get("Model"), "Foundation/Model");
   */
  template <typename Value>
  class Selection
  {
  public:
    Selection(std::initializer_list<std::pair<std::string, Value>> entries)
        : entries(entries)
    {}

    /// "name1|name2|...", in the order of the table.
    std::string
    names() const
    {
      std::string text;
      for (const auto &entry : entries)
        text += (text.empty() ? "" : "|") + entry.first;
      return text;
    }

    Patterns::Selection
    pattern() const
    {
      return Patterns::Selection(names());
    }

    /// The value called `name`; `parameter` names the entry in the message
    /// of a name that is not in the table.
    Value
    parse(const std::string &name, const std::string &parameter) const
    {
      for (const auto &entry : entries)
        if (entry.first == name)
          return entry.second;
      AssertThrow(false,
                  ExcMessage(parameter + " = " + name + " is not one of "
                             + names() + "."));
      return entries.front().second;
    }

    /// The name of `value` in the table, for messages.
    std::string
    name(const Value value) const
    {
      for (const auto &entry : entries)
        if (entry.second == value)
          return entry.first;
      return "";
    }

  private:
    std::vector<std::pair<std::string, Value>> entries;
  };
} // namespace liftoff
