#include <liftoff/base/section_timer.h>

namespace liftoff
{
  void
  WallClock::start()
  {
    started = std::chrono::steady_clock::now();
  }


  void
  WallClock::stop()
  {
    total += std::chrono::steady_clock::now() - started;
  }


  double
  WallClock::wall_time() const
  {
    return std::chrono::duration<double>(total).count();
  }


  SectionTimer::Scope::Scope(SectionTimer &timer, const std::string &section)
      : clock(&timer.sections[section])
  {
    clock->start();
  }


  SectionTimer::Scope::~Scope()
  {
    stop();
  }


  void
  SectionTimer::Scope::stop()
  {
    if (clock != nullptr)
      clock->stop();
    clock = nullptr;
  }


  std::map<std::string, double>
  SectionTimer::wall_times() const
  {
    std::map<std::string, double> times;
    for (const auto &[name, clock] : sections)
      times[name] = clock.wall_time();
    return times;
  }
} // namespace liftoff
