#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/selection.h>
#include <liftoff/time/energy_check.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace liftoff
{
  namespace
  {
    const Selection<EnergyCheck::Mode> modes = {
      {"warn", EnergyCheck::Mode::warn},
      {"fail", EnergyCheck::Mode::fail},
      {"off", EnergyCheck::Mode::off}};
  }


  void
  EnergyCheck::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Energy check");
    prm.declare_entry(
      "Mode",
      "warn",
      modes.pattern(),
      "What a dynamic run does when its energy balance error (total energy "
      "minus initial energy, work of the loads and dissipated energy) "
      "exceeds Tolerance times the run's energy scale (the largest energy, "
      "work or dissipation seen so far; with a scheme that damps high "
      "frequencies, Gamma > 1/2 or generalized-alpha with Spectral radius "
      "< 1, only a gain of energy counts; Beta != 1/4 with Gamma = 1/2 "
      "conserves another energy and is not checked): warn, say so with the "
      "step and the "
      "likely cause and end with the status `completed with warnings`; "
      "fail, stop there with an error; off, do not check (and do not "
      "compute the energies unless Output/Write energies asks for them: "
      "two matrix-vector products per step).");
    prm.declare_entry(
      "Tolerance",
      "0.01",
      Patterns::Double(1e-12, 1.0),
      "Largest balance error allowed, as a share of the run's energy "
      "scale. Contact switching and mesh transfers leave up to about 3e-3 "
      "in the scenes of prm/; a time step too long for the bed or a loose "
      "solver tolerance leave errors of the order of the energies."
        + quantity("number"));
    prm.leave_subsection();
  }


  void
  EnergyCheck::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Energy check");
    check_mode = modes.parse(prm.get("Mode"), "Energy check/Mode");
    tolerance  = prm.get_double("Tolerance");
    prm.leave_subsection();
  }


  bool
  EnergyCheck::is_enabled() const
  {
    return check_mode != Mode::off;
  }


  EnergyCheck::Mode
  EnergyCheck::mode() const
  {
    return check_mode;
  }


  bool
  EnergyCheck::exceeds(const unsigned int   step,
                       const EnergyBalance &energies,
                       const EnergyBalance &initial,
                       const bool           scheme_dissipates)
  {
    if (!is_enabled())
      return false;
    const auto stored = [](const EnergyBalance &e) {
      return e.kinetic + e.strain + e.supports;
    };
    scale              = std::max({scale,
                                   std::abs(stored(energies)),
                                   std::abs(stored(initial)),
                                   std::abs(energies.work),
                                   std::abs(energies.dissipated)});
    const double error = energies.error(initial);
    // A NaN compares false with everything: it counts as exceeding.
    const double counted =
      scheme_dissipates ? std::max(error, 0.0) : std::abs(error);
    const double relative = scale > 0 ? counted / scale : 0.0;
    if (!(relative <= largest))
      {
        largest      = relative;
        largest_step = step;
      }
    if (exceeded || relative <= tolerance)
      return false;
    exceeded    = true;
    first_step  = step;
    first_error = error;
    first_scale = scale;
    return true;
  }


  std::string
  EnergyCheck::describe_violation() const
  {
    // Three digits, each energy tagged with its unit for the scene's.
    const auto number = [](const double x) {
      std::ostringstream text;
      text.precision(3);
      text << x;
      return text.str();
    };
    return "the energy balance error at step " + std::to_string(first_step)
           + " (" + tagged(number(first_error), Quantity::energy) + ") is "
           + number(std::abs(first_error) / first_scale)
           + " of the run's energy scale "
           + tagged(number(first_scale), Quantity::energy)
           + ", above Energy check/Tolerance = " + number(tolerance);
  }


  double
  EnergyCheck::largest_relative_error() const
  {
    return largest;
  }


  unsigned int
  EnergyCheck::step_of_largest_error() const
  {
    return largest_step;
  }


  bool
  EnergyCheck::was_exceeded() const
  {
    return exceeded;
  }
} // namespace liftoff
