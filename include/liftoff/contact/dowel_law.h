#pragma once

#include <liftoff/contact/status_law.h>

namespace liftoff
{
  /**
   * A dowel's play as a status law: a spring of stiffness C between the
   * two slabs' w at its point, loose by g: no force while the jump
   * [w] = w_lower - w_upper lies within g, F = C ([w] - g s) beyond, s the
   * side it is pressed to. A dowel is slack, engaged with [w] > g
   * (`lower`), with [w] < -g (`upper`), or `both`: a spring without play
   * (g = 0, or the union of a cycle).
   */
  class DowelLaw : public StatusLaw
  {
  public:
    enum : unsigned char
    {
      slack = 0,
      lower = 1,
      upper = 2,
      both  = 3
    };

    DowelLaw() = default;
    DowelLaw(const double stiffness, const double looseness);

    /// The status every dowel starts with: slack with play, else `both`.
    unsigned char
    initial_status() const;

    /// The sign s of the play in the force of `status`.
    static double
    offset_sign(const unsigned char status);

    bool
    switches() const override;
    double
    band(const double largest) const override;
    unsigned char
    next_status(const unsigned char status,
                const double        jump,
                const double        band) const override;
    bool
    may_keep(const unsigned char earlier,
             const double        jump,
             const double        band) const override;
    double
    stiffness(const double velocity_factor) const override;
    bool
    has_offset() const override;
    double
    offset_stiffness() const override;
    double
    offset(const unsigned int i, const unsigned char status) const override;

  private:
    double c = 0, g = 0;
  };
} // namespace liftoff
