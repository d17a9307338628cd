#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/archive_types.h>

#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class NewmarkIntegrator;

  /**
   * `Time step control = error`: the size of each time step from an
   * estimate of its local error. A step has a level k in [0, Finest step
   * level] and the size Time step / 2^k, so that only a few sizes occur and
   * every Time step ends on a step: the history's rows stay at the
   * multiples of Time step, as in a fixed-step run. The local error of a
   * Newmark step is Zienkiewicz and Xie's (1991)
   *   e = (beta - 1/6) dt^2 (a_{n+1} - a_n)
   *     = (beta - 1/6) / beta (u_{n+1} - u_n - dt v_n - dt^2/2 a_n),
   * measured as its largest w entry, relative to the largest |w| of the run
   * so far (including the step's). A step above Error tolerance is taken
   * again smaller; the next step is dt Safety factor (tolerance /
   * error)^(1/3), rounded down to a level, at most twice the last one, and
   * only where the larger step starts on its own grid (a multiple of its
   * size from the last multiple of Time step). The event rule: a step over
   * which the contact area changes by more than Event share of the plate
   * is taken again at the finest level, where the estimate, blind to the
   * switch's velocity error, would pass it. The class decides; the
   * TimeStepper takes the steps.
   */
  class StepSizeController
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    /// `time_step`: Time step, the largest step.
    void
    parse_parameters(ParameterHandler &prm, const double time_step);
    /// Refuse the control where it cannot work: a static analysis, or a
    /// scheme whose estimate vanishes (Beta = 1/6) or that is only
    /// conditionally stable.
    void
    check_against(const NewmarkIntegrator &newmark,
                  const bool               is_dynamic) const;

    bool
    is_enabled() const;
    /// The finest level K: a Time step is 2^K units of the finest step.
    unsigned int
    finest_level() const;

    /// The relative error of a step from the largest |w| entry of its error
    /// estimate and of its new displacement (both over all ranks).
    double
    relative_error(const double largest_error, const double largest_w);

    /// Judge a step of level `level()` with relative error `error`, over
    /// which the contact area changed by `contact_change` (a share of the
    /// plate's), that starts `position` finest units after the last
    /// multiple of Time step; returns whether it is accepted, and sets the
    /// level of the next try or step. At the finest level every step is
    /// accepted.
    bool
    judge(const double       error,
          const double       contact_change,
          const unsigned int position);

    /// The level of the next step.
    unsigned int
    level() const;

    /// Start a new Time step (a history row): the counts of substeps.
    void
    start_interval();
    /// Counts of the last Time step: accepted steps, and its finest level.
    unsigned int
    substeps_in_interval() const;
    unsigned int
    finest_level_in_interval() const;
    /// The history's columns dt_min, substeps and local_error of the last
    /// Time step: its smallest step (0 before the first), the number of its
    /// steps, and the sum of their local error estimates (the largest |e|
    /// over the nodes' w, in units of w; summed over the rows, an estimate
    /// of the global error).
    std::vector<double>
    interval_columns() const;
    /// Over the run: accepted, rejected steps, and changes of level.
    unsigned long n_accepted = 0, n_rejected = 0, n_level_changes = 0;
    /// Steps accepted above the tolerance at the finest level.
    unsigned long n_at_finest_above_tolerance = 0;

    /// Everything the next step depends on, for a checkpoint.
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int);

  private:
    bool         enabled   = false;
    double       base_step = 0;
    double       tolerance = 1e-4;
    unsigned int finest    = 6;
    double       safety    = 0.8;
    double       event     = 1;

    unsigned int current = 0;
    /// The largest |w| of the run so far.
    double       largest_w         = 0;
    unsigned int interval_substeps = 0;
    unsigned int interval_finest   = 0;
    /// The largest |e| of the step last measured (relative_error()), and
    /// the sum of the accepted steps' since the last row.
    double step_error     = 0;
    double interval_error = 0;

    /// The level whose step is the largest at most dt (tolerance /
    /// error)^(1/3) Safety factor, dt that of `level`.
    unsigned int
    proposed_level(const double error, const unsigned int level) const;
  };
} // namespace liftoff
