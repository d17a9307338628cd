#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <ostream>
#include <sstream>
#include <string>

namespace liftoff
{
  /// Write a whole file under a temporary name and rename it into place, so
  /// that a reader (or a run that dies) never leaves a half-written file.
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write);

  /// The message of an exception without deal.II's stack trace, for
  /// passing an error on in a message of its own.
  std::string
  message_of(const std::exception &e);

  /**
   * The one rule for everything that can fail on some ranks only (a file
   * that rank 0 alone writes, a rank's own checkpoint file, a folder rank 0
   * creates): every rank runs `attempt` (which does nothing on the ranks it
   * does not concern), and if it threw on any rank, all ranks throw the
   * message of the lowest such rank, prefixed by `what` unless that is
   * empty. Without it, the ranks that did not fail would go on and wait for
   * ever in their next collective call. Collective; costs one reduction
   * when nothing fails.
   */
  void
  collective_attempt(const MPI_Comm               comm,
                     const std::string           &what,
                     const std::function<void()> &attempt);

  /// Whether something written every `interval` steps (0: never) is due
  /// after `step`; the last step always is, so a run ends with it.
  inline bool
  is_due_every(const unsigned int interval,
               const unsigned int step,
               const bool         is_last_step)
  {
    return interval > 0 && (step % interval == 0 || is_last_step);
  }

  /// How often, in seconds of wall time, a file that is replaced whole as
  /// it grows (history.csv, profiles.csv, solution.pvd) is rewritten at most
  /// before the run ends: often enough to watch a run, seldom enough that
  /// the rewrites cost nothing next to the steps.
  constexpr double rewrite_interval = 1.0;

  /**
   * A text file that grows (a CSV table) but is only ever replaced whole:
   * rows are kept in memory and the file is rewritten atomically at most
   * every `interval` seconds of wall time and on flush(), so a reader never
   * sees a half-written row. Rank 0 keeps the text and writes the file;
   * what other ranks add is discarded, but they call write_if_due() and
   * flush() as well, so that a failed write stops all ranks. An empty path
   * keeps the rows in memory only.
   */
  class GrowingTextFile
  {
  public:
    /// Nothing is written yet: the file appears at the first write.
    void
    open(const std::string &path,
         const double       interval_seconds,
         const MPI_Comm     comm);

    /// Add text; the file follows when the interval has passed.
    std::ostream &
    stream();
    /// Collective.
    void
    write_if_due();

    /// Write the file now (collective).
    void
    flush();

    /// Write nothing until the next flush(): a resumed run holds back the
    /// rows of its checkpoint until it has a step of its own to add.
    void
    hold();

    /// Everything added so far, and a replacement for it (a resumed run
    /// continues the file of its checkpoint).
    std::string
    text() const;
    void
    replace(const std::string &text);

  private:
    std::string        path;
    double             interval  = 1.0;
    MPI_Comm           comm      = MPI_COMM_SELF;
    bool               is_writer = false;
    bool               is_held   = false;
    std::ostringstream contents;
    /// Where the other ranks' text goes: a stream without a buffer.
    std::ostream  discarded{nullptr};
    dealii::Timer since_written;

    /// Write the file if `is_due` on rank 0 (collective).
    void
    write(const bool is_due);
  };
} // namespace liftoff
