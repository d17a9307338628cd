#pragma once

#include <string>
#include <vector>

namespace liftoff
{
  /// `x` with 8 significant digits, as messages and the summary quote
  /// parameters and figures (a time step, a limit, a ratio).
  std::string
  format_number(const double x);

  /// The shortest text that reads back as `x` exactly: a point or value
  /// the user wrote, quoted in a message, must not look like another
  /// (0.500000001 is not 0.5).
  std::string
  format_exact(const double x);

  /// "x, y" of a point, each by format_exact().
  std::string
  format_point(const double x, const double y);

  /// The names one after the other, `separator` between them: the lists
  /// of allowed names that messages quote.
  std::string
  joined(const std::vector<std::string> &names,
         const std::string              &separator = ",");
} // namespace liftoff
