#pragma once

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

  /// Remove what write_file_atomically() leaves behind when a run is killed
  /// while writing: `*.tmp` files in `directory` and its subfolders.
  void
  remove_temporary_files(const std::string &directory);

  /// The message of an exception without deal.II's stack trace, for
  /// passing an error on in a message of its own.
  std::string
  message_of(const std::exception &e);

  /// Whether something written every `interval` steps (0: never) is due
  /// after `step`; the last step always is, so a run ends with it.
  inline bool
  is_due_every(const unsigned int interval,
               const unsigned int step,
               const bool         is_last_step)
  {
    return interval > 0 && (step % interval == 0 || is_last_step);
  }

  /**
   * A text file that grows (a CSV table) but is only ever replaced whole:
   * rows are kept in memory and the file is rewritten atomically at most
   * every `interval` seconds of wall time and on flush(), so a reader never
   * sees a half-written row. An empty path keeps the rows in memory only.
   */
  class GrowingTextFile
  {
  public:
    void
    open(const std::string &path, const double interval_seconds);

    /// Add text; the file follows when the interval has passed.
    std::ostream &
    stream();
    void
    write_if_due();

    /// Write the file now.
    void
    flush();

    /// Everything added so far, and a replacement for it (a resumed run
    /// continues the file of its checkpoint).
    std::string
    text() const;
    void
    replace(const std::string &text);

  private:
    std::string        path;
    double             interval = 1.0;
    std::ostringstream contents;
    dealii::Timer      since_written;
  };
} // namespace liftoff
