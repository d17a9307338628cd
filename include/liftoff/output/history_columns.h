#pragma once

#include <liftoff/base/physical_units.h>
#include <liftoff/output/output.h>
#include <liftoff/time/energy_balance.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  /**
   * One row of history.csv as the run computed it, in the solver's units,
   * read by the name of its column in a dimensionless scene ("tau",
   * "contact_fraction", "w(0.5;0)", "kinetic", "vehicle_1_x"): the tests and
   * the summary read the rows, a checkpoint keeps them.
   */
  class HistoryRow
  {
  public:
    HistoryRow(std::vector<double>                             values,
               std::shared_ptr<const std::vector<std::string>> names);

    /// The value of the column `name`; a name the run does not write is
    /// refused, naming those it writes.
    double
    operator[](const std::string &name) const;
    /// The probes of `quantity` ("w": the columns "w(x;y)"), in the order
    /// of their points.
    std::vector<double>
    probes(const std::string &quantity) const;
    /// The energy columns as an EnergyBalance (dissipated 0 without
    /// dashpots).
    EnergyBalance
    energies() const;
    /// Every column's value and name, in the file's order.
    const std::vector<double> &
    values() const;
    const std::vector<std::string> &
    names() const;

  private:
    std::vector<double>                             row;
    std::shared_ptr<const std::vector<std::string>> column_names;
  };


  /**
   * The columns of history.csv: each a name, the quantity it is (its unit
   * in an SI scene) and how a step gives its value. Whoever writes a column
   * adds it here with these three, in one place; columns computed together
   * (a resultant and its centre, from one pass over the Gauss points) are
   * added as a group whose one function gives their values in order.
   */
  class HistoryColumns
  {
  public:
    struct Column
    {
      std::string             name;
      PhysicalUnits::Quantity quantity;
    };
    using Value  = std::function<double(const StepData &)>;
    using Values = std::function<std::vector<double>(const StepData &)>;

    void
    clear();
    void
    add(const std::string            &name,
        const PhysicalUnits::Quantity quantity,
        Value                         value);
    /// Columns whose values one call of `values` gives, in their order.
    void
    add(const std::vector<Column> &columns, Values values);

    const std::vector<Column> &
    columns() const;
    /// The column names, shared by the rows of these columns.
    const std::shared_ptr<const std::vector<std::string>> &
    names() const;
    /// The row of a step, in the solver's units (collective).
    HistoryRow
    row_at(const StepData &step) const;

  private:
    std::vector<Column> list;
    /// Each group's first column and its values.
    std::vector<std::pair<unsigned int, Values>>    groups;
    std::shared_ptr<const std::vector<std::string>> shared_names =
      std::make_shared<const std::vector<std::string>>();
  };
} // namespace liftoff
