#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace liftoff
{
  /// Write a whole file under a temporary name and rename it into place, so
  /// that a reader (or a run that dies) never leaves a half-written file.
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write);
} // namespace liftoff
