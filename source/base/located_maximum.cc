#include <liftoff/base/located_maximum.h>

#include <array>
#include <tuple>

namespace liftoff
{
  void
  LocatedMaximum::consider(const double    v,
                           const Point<2> &at,
                           const double    when)
  {
    const bool first = std::make_tuple(at[0], at[1], when)
                       < std::make_tuple(point[0], point[1], time);
    if (!found || v > value || (v == value && first))
      {
        value = v;
        point = at;
        time  = when;
        found = true;
      }
  }


  LocatedMaximum
  LocatedMaximum::over_ranks(const MPI_Comm comm) const
  {
    const auto all = Utilities::MPI::all_gather(
      comm,
      std::array<double, 5>{{double(found), value, point[0], point[1], time}});
    LocatedMaximum result;
    for (const auto &[is_found, v, x, y, t] : all)
      if (is_found != 0)
        result.consider(v, Point<2>(x, y), t);
    return result;
  }
} // namespace liftoff
