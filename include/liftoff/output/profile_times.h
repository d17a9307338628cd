#pragma once

#include <liftoff/base/archive_types.h>

#include <string>
#include <vector>

namespace liftoff
{
  /**
   * The times at which profiles are written (Output/Profile times), each
   * at the step nearest to it: the profiles along a line (ProfileOutput)
   * and along the joints (JointProfiles) share them, so that their rows
   * belong to the same steps.
   */
  class ProfileTimes
  {
  public:
    /// The entry's value; a time given twice is refused.
    void
    parse(const std::string &text);
    /// None written yet.
    void
    reset();
    /// Whether a profile is due at the step that ends at tau with step dt
    /// (a static analysis, dt = 0: always); the times it is for count as
    /// written from now on.
    bool
    is_due(const double tau, const double dt);
    /// The times a time integration with step dt to end_time does not
    /// reach (nearer to no step than dt/2).
    std::vector<double>
    not_reached(const double end_time, const double dt) const;
    bool
    empty() const;
    void
    save(OutputArchive &archive) const;
    void
    load(InputArchive &archive);

  private:
    std::vector<double> times;
    std::vector<bool>   is_written;
  };
} // namespace liftoff
