#include <liftoff/base/archives.h>
#include <liftoff/output/rainflow.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  double
  Rainflow::Cycle::range() const
  {
    return std::abs(to - from);
  }


  double
  Rainflow::Cycle::mean() const
  {
    return (from + to) / 2;
  }


  double
  Rainflow::Cycle::peak() const
  {
    return std::max(from, to);
  }


  void
  Rainflow::push_reversal(const double         point,
                          std::vector<double> &on,
                          std::vector<Cycle>  &counted)
  {
    on.push_back(point);
    while (on.size() >= 3)
      {
        const std::size_t n = on.size();
        const double      x = std::abs(on[n - 1] - on[n - 2]);
        const double      y = std::abs(on[n - 2] - on[n - 3]);
        if (x < y)
          break;
        if (n == 3)
          {
            counted.push_back({on[0], on[1], 0.5});
            on.erase(on.begin());
          }
        else
          {
            counted.push_back({on[n - 3], on[n - 2], 1.0});
            on.erase(on.end() - 3, on.end() - 1);
          }
      }
  }


  void
  Rainflow::add(const double stress, std::vector<Cycle> &counted)
  {
    if (!has_values)
      {
        // The first value is a reversal whatever follows.
        has_values = true;
        last       = stress;
        push_reversal(stress, reversals, counted);
        return;
      }
    if (stress == last)
      return;
    const int direction = (stress > last ? 1 : -1);
    if (slope != 0 && direction != slope)
      push_reversal(last, reversals, counted);
    slope = direction;
    last  = stress;
  }


  std::vector<Rainflow::Cycle>
  Rainflow::residue() const
  {
    std::vector<Cycle>  open;
    std::vector<double> points = reversals;
    // With one value (slope 0) it is already the stack's only point.
    if (slope != 0)
      push_reversal(last, points, open);
    for (std::size_t i = 1; i < points.size(); ++i)
      open.push_back({points[i - 1], points[i], 0.5});
    return open;
  }


  const std::vector<double> &
  Rainflow::stack() const
  {
    return reversals;
  }


  void
  Rainflow::save(OutputArchive &archive) const
  {
    archive << reversals << last << slope << has_values;
  }


  void
  Rainflow::load(InputArchive &archive)
  {
    archive >> reversals >> last >> slope >> has_values;
  }
} // namespace liftoff
