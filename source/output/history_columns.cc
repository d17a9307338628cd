#include <deal.II/base/exceptions.h>

#include <liftoff/base/number_text.h>
#include <liftoff/output/history_columns.h>

#include <algorithm>

namespace liftoff
{
  HistoryRow::HistoryRow(std::vector<double>                             values,
                         std::shared_ptr<const std::vector<std::string>> names)
      : row(std::move(values))
      , column_names(std::move(names))
  {}


  double
  HistoryRow::operator[](const std::string &name) const
  {
    const auto found =
      std::find(column_names->begin(), column_names->end(), name);
    AssertThrow(found != column_names->end(),
                ExcMessage("The time history has no column <" + name
                           + ">; it has " + joined(*column_names, ", ") + "."));
    return row[found - column_names->begin()];
  }


  std::vector<double>
  HistoryRow::probes(const std::string &quantity) const
  {
    std::vector<double> values;
    for (unsigned int c = 0; c < column_names->size(); ++c)
      if ((*column_names)[c].rfind(quantity + "(", 0) == 0)
        values.push_back(row[c]);
    return values;
  }


  EnergyBalance
  HistoryRow::energies() const
  {
    const bool dissipates =
      std::find(column_names->begin(), column_names->end(), "dissipated_energy")
      != column_names->end();
    // The terms' energies stand between the kinetic energy and the work;
    // all but the plate's strain energy are its supports'.
    const auto at = [&](const std::string &name) {
      return std::find(column_names->begin(), column_names->end(), name)
             - column_names->begin();
    };
    double supports = 0;
    for (auto c = at("kinetic") + 1; c < at("work"); ++c)
      if ((*column_names)[c] != "strain")
        supports += row[c];
    return {(*this)["kinetic"],
            (*this)["strain"],
            supports,
            (*this)["work"],
            dissipates ? (*this)["dissipated_energy"] : 0.0,
            {}};
  }


  const std::vector<double> &
  HistoryRow::values() const
  {
    return row;
  }


  const std::vector<std::string> &
  HistoryRow::names() const
  {
    return *column_names;
  }


  void
  HistoryColumns::clear()
  {
    list.clear();
    groups.clear();
    shared_names = std::make_shared<const std::vector<std::string>>();
  }


  void
  HistoryColumns::add(const std::string            &name,
                      const PhysicalUnits::Quantity quantity,
                      Value                         value)
  {
    add({{name, quantity}}, [value = std::move(value)](const StepData &step) {
      return std::vector<double>{value(step)};
    });
  }


  void
  HistoryColumns::add(const std::vector<Column> &columns, Values values)
  {
    if (columns.empty())
      return;
    groups.emplace_back(list.size(), std::move(values));
    list.insert(list.end(), columns.begin(), columns.end());
    std::vector<std::string> all;
    for (const Column &column : list)
      all.push_back(column.name);
    shared_names =
      std::make_shared<const std::vector<std::string>>(std::move(all));
  }


  const std::vector<HistoryColumns::Column> &
  HistoryColumns::columns() const
  {
    return list;
  }


  const std::shared_ptr<const std::vector<std::string>> &
  HistoryColumns::names() const
  {
    return shared_names;
  }


  HistoryRow
  HistoryColumns::row_at(const StepData &step) const
  {
    std::vector<double> values;
    values.reserve(list.size());
    for (const auto &[first, group] : groups)
      {
        const std::vector<double> group_values = group(step);
        Assert(values.size() == first, ExcInternalError());
        values.insert(values.end(), group_values.begin(), group_values.end());
      }
    AssertThrow(values.size() == list.size(),
                ExcMessage("A group of history columns gave "
                           + std::to_string(values.size()) + " values for "
                           + std::to_string(list.size()) + " columns."));
    return {std::move(values), shared_names};
  }
} // namespace liftoff
