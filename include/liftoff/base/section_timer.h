#pragma once

#include <chrono>
#include <map>
#include <string>

namespace liftoff
{
  /// A stopwatch of wall time only (std::chrono::steady_clock).
  class WallClock
  {
  public:
    void
    start();
    void
    stop();
    /// Seconds between starts and stops so far.
    double
    wall_time() const;

  private:
    std::chrono::steady_clock::time_point started;
    std::chrono::steady_clock::duration   total{0};
  };

  /**
   * The wall time of named sections of the run, for the summary: what
   * deal.II's TimerOutput with `wall_times` and `never` reports there, at a
   * fraction of its cost. TimerOutput's timers also read the CPU time
   * (getrusage, a system call) and reduce over their communicator at
   * every enter and leave, which took a fifth of a step of the 246-unknown
   * beam (doc/performance.md, "Outputs and other per-step work"). Times
   * are this rank's, as TimerOutput's summary data are.
   */
  class SectionTimer
  {
  public:
    /// Times a section from construction to destruction.
    class Scope
    {
    public:
      Scope(SectionTimer &timer, const std::string &section);
      ~Scope();
      Scope(const Scope &) = delete;
      Scope &
      operator=(const Scope &) = delete;
      /// Leave the section before the scope ends.
      void
      stop();

    private:
      WallClock *clock;
    };

    /// Seconds spent in each section so far, by name.
    std::map<std::string, double>
    wall_times() const;

  private:
    std::map<std::string, WallClock> sections;
  };
} // namespace liftoff
