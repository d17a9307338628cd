#include <liftoff/contact/dowel_law.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  DowelLaw::DowelLaw(const double stiffness, const double looseness)
      : c(stiffness)
      , g(looseness)
  {}


  unsigned char
  DowelLaw::initial_status() const
  {
    return g > 0 ? slack : both;
  }


  double
  DowelLaw::offset_sign(const unsigned char status)
  {
    return status == lower ? 1.0 : (status == upper ? -1.0 : 0.0);
  }


  bool
  DowelLaw::switches() const
  {
    return g > 0;
  }


  double
  DowelLaw::band(const double largest) const
  {
    // The same relative band as the bed's contact rule would take: round-off
    // of the solution, not a physical width.
    return 1e-10 * std::max(largest, g);
  }


  unsigned char
  DowelLaw::next_status(const unsigned char status,
                        const double        jump,
                        const double        band) const
  {
    if (jump > g + band)
      return lower;
    if (jump < -g - band)
      return upper;
    if (std::abs(jump) < g - band)
      return slack;
    // In the band: an engaged dowel pressed the other way lets go.
    const unsigned char side = jump > 0 ? lower : upper;
    return status != slack && status != side ? static_cast<unsigned char>(slack)
                                             : status;
  }


  bool
  DowelLaw::may_keep(const unsigned char earlier,
                     const double        jump,
                     const double        band) const
  {
    const bool in_band = std::abs(std::abs(jump) - g) <= band;
    return in_band
           && (earlier == slack || earlier == (jump > 0 ? lower : upper));
  }


  double
  DowelLaw::stiffness(const double) const
  {
    return c;
  }


  bool
  DowelLaw::has_offset() const
  {
    return g > 0;
  }


  double
  DowelLaw::offset_stiffness() const
  {
    return c;
  }


  double
  DowelLaw::offset(const unsigned int, const unsigned char status) const
  {
    return g * offset_sign(status);
  }
} // namespace liftoff
