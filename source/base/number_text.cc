#include <liftoff/base/number_text.h>

#include <array>
#include <charconv>
#include <iomanip>
#include <sstream>

namespace liftoff
{
  std::string
  format_number(const double x)
  {
    std::ostringstream text;
    text << std::setprecision(8) << x;
    return text.str();
  }


  std::string
  format_exact(const double x)
  {
    std::array<char, 32> text;
    const auto end = std::to_chars(text.data(), text.data() + text.size(), x);
    return std::string(text.data(), end.ptr);
  }


  std::string
  format_point(const double x, const double y)
  {
    return format_exact(x) + ", " + format_exact(y);
  }


  std::string
  joined(const std::vector<std::string> &names, const std::string &separator)
  {
    std::string text;
    for (const auto &name : names)
      text += (text.empty() ? "" : separator) + name;
    return text;
  }
} // namespace liftoff
