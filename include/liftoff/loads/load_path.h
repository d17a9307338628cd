#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <memory>
#include <optional>
#include <string>

namespace liftoff
{
  using namespace dealii;

  /**
   * The path (x(tau), y(tau)) of a moving load on the full plate, shared by
   * the wheels of a vehicle.
   */
  class LoadPath
  {
  public:
    /// The entry "Path" of the current subsection.
    static void
    declare_parameters(ParameterHandler &prm, const std::string &default_value);

    /// The Path of the current subsection, which belongs to `owner`;
    /// nullptr if it is empty (the load stands).
    static std::shared_ptr<const LoadPath>
    read(ParameterHandler &prm, const std::string &owner);
    /// A path that stands at `point` (a load whose entry is a position).
    static std::shared_ptr<const LoadPath>
    standing_at(const std::string &owner, const Point<2> &point);

    Point<2>
    at(const double tau) const;

    /// The direction of travel at tau, a unit vector; none where the path
    /// stands (at tau and just after it).
    std::optional<Tensor<1, 2>>
    heading_at(const double tau) const;

    /// "(x, y)" of a heading for messages, rounded: a quarter turn's
    /// round-off (0.9999999999999999) is not news.
    static std::string
    heading_text(const Tensor<1, 2> &heading);

    /// Whether it names tau (otherwise the load stands at its one point).
    bool
    moves() const;

    /// The subsection of the Path entry and its text, for messages.
    const std::string &
    owner() const;
    const std::string &
    expression() const;

  private:
    LoadPath(const std::string &owner, const std::string &expression);

    std::string                        owner_name;
    std::string                        text;
    std::unique_ptr<FunctionParser<1>> function;
    bool                               names_tau_ = false;
  };
} // namespace liftoff
