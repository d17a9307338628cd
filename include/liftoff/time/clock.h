#pragma once

#include <cmath>

namespace liftoff
{
  /**
   * The time of a run: the step n, the time step dt and tau = n dt (always
   * the product, never a sum of steps, so that a resumed run's times are
   * the uninterrupted run's to the bit), and the last step, at End time.
   * NewmarkIntegrator makes it from the scene; the TimeStepper carries it in
   * its PlateState, and whoever needs the time asks that clock. A static
   * analysis has the default clock: step 0 of 0, dt = 0.
   */
  class Clock
  {
  public:
    Clock() = default;
    /// At step 0. `end_time` a whole number of steps to 1e-9
    /// (NewmarkIntegrator::check_end_time()).
    Clock(const double time_step, const double end_time)
        : dt(time_step)
        , end(end_time)
        , last(static_cast<unsigned int>(std::round(end_time / time_step)))
    {}

    unsigned int
    step() const
    {
      return n;
    }
    double
    tau() const
    {
      return tau_at(n);
    }
    /// The time of `step`: the loads of the next step are taken there.
    double
    tau_at(const unsigned int step) const
    {
      return step * dt;
    }
    double
    time_step() const
    {
      return dt;
    }
    /// End time as the scene gives it.
    double
    end_time() const
    {
      return end;
    }
    /// The number of steps to End time.
    unsigned int
    n_steps() const
    {
      return last;
    }
    bool
    is_at_end() const
    {
      return n == last;
    }
    void
    set_step(const unsigned int step)
    {
      n = step;
    }

    /// The step only: dt and the end are the scene's.
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &n;
    }

  private:
    unsigned int n    = 0;
    double       dt   = 0;
    double       end  = 0;
    unsigned int last = 0;
  };
} // namespace liftoff
