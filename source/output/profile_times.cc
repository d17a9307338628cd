#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <liftoff/output/profile_times.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  using namespace dealii;


  void
  ProfileTimes::parse(const std::string &text)
  {
    times = Utilities::string_to_double(Utilities::split_string_list(text));
    for (unsigned int k = 0; k < times.size(); ++k)
      AssertThrow(std::count(times.begin(), times.begin() + k, times[k]) == 0,
                  ExcMessage("Output/Profile times lists "
                             + Utilities::to_string(times[k])
                             + " twice; each time gives one profile."));
    reset();
  }


  void
  ProfileTimes::reset()
  {
    is_written.assign(times.size(), false);
  }


  bool
  ProfileTimes::is_due(const double tau, const double dt)
  {
    bool due = (dt == 0.0);
    for (unsigned int k = 0; k < times.size(); ++k)
      if (!is_written[k] && std::abs(tau - times[k]) <= 0.5 * dt * (1 + 1e-12))
        is_written[k] = due = true;
    return due;
  }


  std::vector<double>
  ProfileTimes::not_reached(const double end_time, const double dt) const
  {
    std::vector<double> late;
    for (const double tau : times)
      if (tau > end_time + 0.5 * dt * (1 + 1e-12))
        late.push_back(tau);
    return late;
  }


  bool
  ProfileTimes::empty() const
  {
    return times.empty();
  }


  void
  ProfileTimes::save(OutputArchive &archive) const
  {
    archive << is_written;
  }


  void
  ProfileTimes::load(InputArchive &archive)
  {
    archive >> is_written;
  }
} // namespace liftoff
