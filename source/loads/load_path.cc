#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/loads/load_history.h>
#include <liftoff/loads/load_path.h>

#include <cmath>
#include <sstream>

namespace liftoff
{
  void
  LoadPath::declare_parameters(ParameterHandler  &prm,
                               const std::string &default_value)
  {
    prm.declare_entry(
      "Path",
      default_value,
      Patterns::Anything(),
      std::string(
        "x(tau); y(tau): two muParser expressions in tau separated by ';', "
        "the position on the full plate at time tau (e.g. -0.7 + 0.5*tau; 0, "
        "a constant speed 0.5 along y = 0). The load vector is built at the "
        "current position at every step; whatever is off the plate carries "
        "nothing, and a path that never brings the load onto the plate at a "
        "step time is refused.")
        + quantity("length"));
  }


  std::shared_ptr<const LoadPath>
  LoadPath::read(ParameterHandler &prm, const std::string &owner)
  {
    const std::string expression = prm.get("Path");
    if (expression.empty())
      return nullptr;
    return std::shared_ptr<const LoadPath>(new LoadPath(owner, expression));
  }


  std::shared_ptr<const LoadPath>
  LoadPath::standing_at(const std::string &owner, const Point<2> &point)
  {
    std::ostringstream text;
    text.precision(17);
    text << point[0] << "; " << point[1];
    return std::shared_ptr<const LoadPath>(new LoadPath(owner, text.str()));
  }


  LoadPath::LoadPath(const std::string &owner, const std::string &expression)
      : owner_name(owner)
      , text(expression)
      , function(
          parse_expression<1>(owner + "/Path", expression, 2, "tau", false))
      , names_tau_(names_tau(expression))
  {}


  Point<2>
  LoadPath::at(const double tau) const
  {
    return Point<2>(function->value(Point<1>(tau), 0),
                    function->value(Point<1>(tau), 1));
  }


  std::optional<Tensor<1, 2>>
  LoadPath::heading_at(const double tau) const
  {
    if (!names_tau_)
      return std::nullopt;
    // The secant over a step of the order of a time step: exact on a
    // straight path, whose round-off it divides by its length (a tangent
    // by a step near round-off would turn a diagonal by 1e-9), and a path
    // that starts from rest (x = a tau^2) still heads somewhere.
    const double       h     = 1e-3;
    const Point<2>     here  = at(tau);
    const Tensor<1, 2> ahead = at(tau + h) - here;
    if (!(ahead.norm() > 1e-13 * (1 + here.norm())))
      return std::nullopt;
    return ahead / ahead.norm();
  }


  std::string
  LoadPath::heading_text(const Tensor<1, 2> &heading)
  {
    return "(" + format_number(heading[0]) + ", " + format_number(heading[1])
           + ")";
  }


  bool
  LoadPath::moves() const
  {
    return names_tau_;
  }


  const std::string &
  LoadPath::owner() const
  {
    return owner_name;
  }


  const std::string &
  LoadPath::expression() const
  {
    return text;
  }
} // namespace liftoff
