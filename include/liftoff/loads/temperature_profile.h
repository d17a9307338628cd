#pragma once

#include <string>
#include <vector>

namespace liftoff
{
  /**
   * A temperature through the thickness, piecewise linear between values at
   * equally spaced depths from the top face (s = 0, z = -H/2) to the
   * bed-side face (s = 1, z = +H/2), split into its three parts: the mean
   * (expansion in the plane, no bending), the equivalent linear part,
   * whose top-minus-bottom difference bends the plate as a linear profile
   * would, and the self-equilibrating rest, which has no resultant and no
   * moment over the thickness and so adds stress but no deflection.
   */
  class TemperatureProfile
  {
  public:
    /// `values` top first, at least two; `entry` names them in a refusal.
    TemperatureProfile(const std::vector<double> &values,
                       const std::string         &entry);

    /// The mean over the thickness, int_0^1 T ds.
    double
    mean() const;
    /// The top-minus-bottom difference of the linear profile with the same
    /// moment, -12 int_0^1 T (s - 1/2) ds.
    double
    equivalent_difference() const;
    /// The self-equilibrating part T - mean + difference (s - 1/2) at depth
    /// s (0: top, 1: bottom).
    double
    self_equilibrating_at(const double s) const;

  private:
    std::vector<double> values;
    double              mean_value       = 0;
    double              difference_value = 0;

    /// T at depth s, by linear interpolation.
    double
    at(const double s) const;
  };
} // namespace liftoff
