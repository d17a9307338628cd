#pragma once

#include <liftoff/base/archive_types.h>

#include <vector>

namespace liftoff
{
  /**
   * Rainflow counting of one stress history as it comes, value by value:
   * ASTM E1049-85 (reapproved 2017), section 5.4.4, the counting
   * scripts/liftoff_fatigue.py's rainflow() makes of a whole series, so
   * that a run keeps per point only what is not yet counted (the residue,
   * a few reversals), not its history.
   *
   * The values are reduced to their reversals first (a run of equal values
   * counts once, a value on a slope is no reversal): the first value is
   * one, and a value is one once the next differs from it with the other
   * sign of slope. Each reversal goes on the stack and the standard's
   * steps run: with X the range of the two most recent points and Y the
   * one before, X < Y waits for the next reversal; else if Y holds the
   * starting point S (the oldest point kept), Y is a half cycle and S
   * leaves the stack; else Y is a full cycle and its two points leave.
   * residue() ends the history: the last value is a reversal, its steps
   * run on a copy, and each range left is a half cycle.
   */
  class Rainflow
  {
  public:
    /// A counted cycle: between the stresses `from` and `to`, a full
    /// (count 1) or a half cycle (0.5).
    struct Cycle
    {
      double from  = 0;
      double to    = 0;
      double count = 0;

      double
      range() const;
      double
      mean() const;
      /// The largest stress of the cycle (mean + range / 2, exactly).
      double
      peak() const;
    };

    /// Appends to `counted` the cycles the value `stress` closes.
    void
    add(const double stress, std::vector<Cycle> &counted);

    /// The cycles still open if the history ended now: the last value's
    /// cycles and the half cycles of the residue (the stack is unchanged).
    std::vector<Cycle>
    residue() const;

    /// The reversals kept, oldest first (without the last value).
    const std::vector<double> &
    stack() const;

    void
    save(OutputArchive &archive) const;
    void
    load(InputArchive &archive);

  private:
    /// The reversals not yet counted, oldest (S) first.
    std::vector<double> reversals;
    /// The most recent value; a reversal if the next one turns back.
    double last = 0;
    /// The sign of the slope into `last` (0: one value or none so far).
    int  slope      = 0;
    bool has_values = false;

    /// `point` onto the stack `on` and the standard's steps.
    static void
    push_reversal(const double         point,
                  std::vector<double> &on,
                  std::vector<Cycle>  &counted);
  };
} // namespace liftoff
