#pragma once

#include <string>

namespace liftoff
{
  /// `x` with 8 significant digits, as messages and the summary quote
  /// parameters and figures (a time step, a limit, a ratio).
  std::string
  format_number(const double x);
} // namespace liftoff
