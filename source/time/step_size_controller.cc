#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/selection.h>
#include <liftoff/time/newmark_integrator.h>
#include <liftoff/time/step_size_controller.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace
  {
    // true: error.
    const Selection<bool> controls = {{"fixed", false}, {"error", true}};
  } // namespace


  void
  StepSizeController::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry(
      "Time step control",
      "fixed",
      controls.pattern(),
      "fixed: every step is Time step. error: each step is Time step / 2^k, "
      "0 <= k <= Finest step level, chosen so that its local error estimate "
      "(Zienkiewicz and Xie: (Beta - 1/6) dtau^2 (a_{n+1} - a_n), largest "
      "over the nodes' w) stays below Error tolerance; a step above it is "
      "taken again smaller. The history keeps its rows at the multiples of "
      "Time step. Dynamic analyses with Scheme = newmark, unconditionally "
      "stable, and Beta != 1/6 only.");
    prm.declare_entry("Error tolerance",
                      "1e-4",
                      Patterns::Double(0.0),
                      "With Time step control = error: the largest local "
                      "error of a step, relative to the largest |w| of the "
                      "run so far (> 0)."
                        + quantity("number"));
    prm.declare_entry("Finest step level",
                      "6",
                      Patterns::Integer(0, 20),
                      "With Time step control = error: the smallest step is "
                      "Time step / 2^(this level)."
                        + quantity("number"));
    prm.declare_entry("Event share",
                      "1",
                      Patterns::Double(0.0, 1.0),
                      "With Time step control = error: a step over which "
                      "the contact area changes by more than this share of "
                      "the plate's area is taken again at the finest level "
                      "(a lift-off or a landing); 1: no such rule."
                        + quantity("number"));
    prm.declare_entry("Safety factor",
                      "0.8",
                      Patterns::Double(0.0, 1.0),
                      "With Time step control = error: the next step is "
                      "dtau (Error tolerance / error)^(1/3) times this "
                      "factor, in (0, 1], rounded down to a level."
                        + quantity("number"));
    prm.leave_subsection();
  }


  void
  StepSizeController::parse_parameters(ParameterHandler &prm,
                                       const double      time_step)
  {
    base_step = time_step;
    prm.enter_subsection("Time integration");
    enabled   = controls.parse(prm.get("Time step control"),
                             "Time integration/Time step control");
    tolerance = prm.get_double("Error tolerance");
    finest    = prm.get_integer("Finest step level");
    safety    = prm.get_double("Safety factor");
    event     = prm.get_double("Event share");
    prm.leave_subsection();
    // A NaN fails the comparison and is refused too.
    AssertThrow(tolerance > 0 && std::isfinite(tolerance),
                ExcMessage("Time integration/Error tolerance = "
                           + format_number(tolerance)
                           + " must be a finite number > 0."));
    AssertThrow(safety > 0,
                ExcMessage("Time integration/Safety factor = "
                           + format_number(safety) + " must lie in (0, 1]."));
  }


  void
  StepSizeController::check_against(const NewmarkIntegrator &newmark,
                                    const bool               is_dynamic) const
  {
    if (!enabled)
      return;
    AssertThrow(is_dynamic,
                ExcMessage("Time integration/Time step control = error "
                           "needs Analysis/Type = dynamic: a static analysis "
                           "has no time steps."));
    AssertThrow(newmark.alpha_m == 0 && newmark.alpha_f == 0,
                ExcMessage("Time integration/Time step control = error with "
                           "Scheme = generalized-alpha: the error estimate is "
                           "Newmark's (its accelerations at the steps' ends, "
                           "where generalized-alpha's are not). Use Scheme = "
                           "newmark."));
    AssertThrow(std::abs(newmark.beta - 1.0 / 6.0) > 1e-3,
                ExcMessage("Time integration/Time step control = error with "
                           "Beta = "
                           + format_number(newmark.beta)
                           + ": the error estimate (Beta - 1/6) dtau^2 "
                             "(a_{n+1} - a_n) vanishes near Beta = 1/6. Use "
                             "Beta = 0.25."));
    AssertThrow(!newmark.is_conditionally_stable(),
                ExcMessage("Time integration/Time step control = error "
                           "needs an unconditionally stable scheme; Beta = "
                           + format_number(newmark.beta) + " < Gamma/2 = "
                           + format_number(0.5 * newmark.gamma)
                           + " is not. Use Beta >= Gamma/2."));
  }


  bool
  StepSizeController::is_enabled() const
  {
    return enabled;
  }


  unsigned int
  StepSizeController::finest_level() const
  {
    return enabled ? finest : 0;
  }


  double
  StepSizeController::relative_error(const double largest_error,
                                     const double largest_w_of_step)
  {
    largest_w  = std::max(largest_w, largest_w_of_step);
    step_error = largest_error;
    return largest_w > 0 ? largest_error / largest_w : 0.0;
  }


  unsigned int
  StepSizeController::proposed_level(const double       error,
                                     const unsigned int level) const
  {
    if (!(error >= 0) || std::isinf(error))
      return finest;
    if (error == 0)
      return 0;
    const double ratio = safety * std::cbrt(tolerance / error);
    // The step dt / 2^j is at most dt ratio.
    const double j = std::ceil(-std::log2(ratio));
    const double level_wanted =
      std::clamp(level + j, 0.0, static_cast<double>(finest));
    return static_cast<unsigned int>(level_wanted);
  }


  bool
  StepSizeController::judge(const double       error,
                            const double       contact_change,
                            const unsigned int position)
  {
    const unsigned int before   = current;
    const bool         is_event = contact_change > event;
    if ((!(error <= tolerance) || is_event) && current < finest)
      {
        ++n_rejected;
        current = is_event
                    ? finest
                    : std::max(current + 1, proposed_level(error, current));
        ++n_level_changes;
        return false;
      }
    if (!(error <= tolerance))
      ++n_at_finest_above_tolerance;
    ++n_accepted;
    ++interval_substeps;
    interval_error += step_error;
    interval_finest = std::max(interval_finest, current);

    // At most twice the step, and a step of level k starts on a multiple
    // of its size: every multiple of Time step ends a step.
    const unsigned int next_position = position + (1u << (finest - current));
    unsigned int       next =
      std::max(proposed_level(error, current), current > 0 ? current - 1 : 0);
    while (next < current && next_position % (1u << (finest - next)) != 0)
      ++next;
    current = next;
    n_level_changes += (current != before);
    return true;
  }


  unsigned int
  StepSizeController::level() const
  {
    return current;
  }


  void
  StepSizeController::start_interval()
  {
    interval_substeps = 0;
    interval_finest   = 0;
    interval_error    = 0;
  }


  unsigned int
  StepSizeController::substeps_in_interval() const
  {
    return interval_substeps;
  }


  unsigned int
  StepSizeController::finest_level_in_interval() const
  {
    return interval_finest;
  }


  std::vector<double>
  StepSizeController::interval_columns() const
  {
    if (interval_substeps == 0)
      return {0.0, 0.0, 0.0};
    return {std::ldexp(base_step, -static_cast<int>(interval_finest)),
            static_cast<double>(interval_substeps),
            interval_error};
  }


  template <class Archive>
  void
  StepSizeController::serialize(Archive &archive, const unsigned int)
  {
    archive &current &largest_w &interval_substeps &interval_finest;
    archive &n_accepted &n_rejected &n_level_changes
      &n_at_finest_above_tolerance;
  }


  template void
  StepSizeController::serialize(InputArchive &, const unsigned int);
  template void
  StepSizeController::serialize(OutputArchive &, const unsigned int);
} // namespace liftoff
