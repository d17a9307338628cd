#include <liftoff/base/scene_input.h>
#include <liftoff/loads/load_history.h>

#include <iomanip>
#include <regex>
#include <sstream>

namespace liftoff
{
  bool
  names_tau(const std::string &expression)
  {
    static const std::regex tau("(^|[^A-Za-z0-9_])tau([^A-Za-z0-9_]|$)");
    return std::regex_search(expression, tau);
  }


  std::string
  time_text(const double tau)
  {
    std::ostringstream text;
    text << std::setprecision(8) << tau;
    return text.str();
  }


  LoadHistory::LoadHistory(const std::string &expression,
                           const std::string &parameter)
      : text(expression)
      , function(parse_expression<1>(parameter, expression, 1, "tau", false))
  {}


  LoadHistory
  LoadHistory::read(ParameterHandler &prm, const std::string &owner)
  {
    return LoadHistory(prm.get("Time history"), owner + "/Time history");
  }


  double
  LoadHistory::at(const double tau) const
  {
    return function->value(Point<1>(tau));
  }


  const std::string &
  LoadHistory::expression() const
  {
    return text;
  }
} // namespace liftoff
