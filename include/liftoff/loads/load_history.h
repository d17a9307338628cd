#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace liftoff
{
  using namespace dealii;

  /// Whether a muParser expression names the variable tau (a path that
  /// moves, an intensity that changes in time).
  bool
  names_tau(const std::string &expression);

  /// tau as messages about loads quote it.
  std::string
  time_text(const double tau);

  /**
   * A load's amplitude h(tau), a muParser expression in tau, parsed (and so
   * checked) when read.
   */
  class LoadHistory
  {
  public:
    /// `parameter` names the expression in a message about it.
    LoadHistory(const std::string &expression, const std::string &parameter);

    /// The entry "Time history" of the current subsection, which belongs
    /// to the load `owner`.
    static LoadHistory
    read(ParameterHandler &prm, const std::string &owner);

    double
    at(const double tau) const;

    const std::string &
    expression() const;

  private:
    std::string                        text;
    std::unique_ptr<FunctionParser<1>> function;
  };
} // namespace liftoff
