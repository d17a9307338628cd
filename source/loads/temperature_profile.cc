#include <deal.II/base/exceptions.h>

#include <liftoff/loads/temperature_profile.h>

#include <cmath>

namespace liftoff
{
  TemperatureProfile::TemperatureProfile(const std::vector<double> &values,
                                         const std::string         &entry)
      : values(values)
  {
    AssertThrow(values.size() >= 2,
                dealii::ExcMessage(
                  entry
                  + " must hold at least two numbers: the temperatures at "
                    "equally spaced depths from the top face to the bed-side "
                    "face, per unit of Magnitude."));
    // T is linear on each interval, so Simpson's rule is exact for T and
    // for T (s - 1/2).
    const unsigned int n = values.size() - 1;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double s0 = double(k) / n, s1 = double(k + 1) / n,
                     sm = (s0 + s1) / 2, h = s1 - s0;
        const double t0 = values[k], t1 = values[k + 1], tm = (t0 + t1) / 2;
        mean_value += h / 6 * (t0 + 4 * tm + t1);
        difference_value +=
          -12 * h / 6
          * (t0 * (s0 - 0.5) + 4 * tm * (sm - 0.5) + t1 * (s1 - 0.5));
      }
    for (const double v : values)
      AssertThrow(std::isfinite(v),
                  dealii::ExcMessage(entry
                                     + " holds a number that is not "
                                       "finite."));
  }


  double
  TemperatureProfile::mean() const
  {
    return mean_value;
  }


  double
  TemperatureProfile::equivalent_difference() const
  {
    return difference_value;
  }


  double
  TemperatureProfile::at(const double s) const
  {
    const unsigned int n = values.size() - 1;
    const unsigned int k = std::min<unsigned int>(n - 1, s * n);
    const double       f = s * n - k;
    return (1 - f) * values[k] + f * values[k + 1];
  }


  double
  TemperatureProfile::self_equilibrating_at(const double s) const
  {
    return at(s) - mean_value + difference_value * (s - 0.5);
  }
} // namespace liftoff
