#include <liftoff/base/number_text.h>

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
  joined(const std::vector<std::string> &names, const std::string &separator)
  {
    std::string text;
    for (const auto &name : names)
      text += (text.empty() ? "" : separator) + name;
    return text;
  }
} // namespace liftoff
