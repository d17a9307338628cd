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
} // namespace liftoff
