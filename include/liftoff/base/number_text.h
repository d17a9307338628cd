#pragma once

#include <string>
#include <vector>

namespace liftoff
{
  /// `x` with 8 significant digits, as messages and the summary quote
  /// parameters and figures (a time step, a limit, a ratio).
  std::string
  format_number(const double x);

  /// The names one after the other, `separator` between them: the lists
  /// of allowed names that messages quote.
  std::string
  joined(const std::vector<std::string> &names,
         const std::string              &separator = ",");
} // namespace liftoff
