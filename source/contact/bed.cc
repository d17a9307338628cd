#include <liftoff/contact/bed.h>

namespace liftoff
{
  Bed &
  Bed::of(const std::vector<SystemTerm *> &terms)
  {
    for (SystemTerm *term : terms)
      if (Bed *bed = dynamic_cast<Bed *>(term))
        return *bed;
    AssertThrow(false,
                ExcMessage("The plate's system has no term for the bed it "
                           "rests on (a scene's parts must list one)."));
    return *static_cast<Bed *>(nullptr);
  }
} // namespace liftoff
