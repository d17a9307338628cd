#pragma once

namespace liftoff
{
  /// How the active-set iteration of one solve ended
  /// (ActiveSetIteration::Result); what the outputs see of it.
  struct ActiveSetResult
  {
    unsigned int iterations = 0;
    bool         converged  = false;
    /// Only when nothing but the foundation holds the plate: the set
    /// emptied or the system was singular.
    bool lost_contact = false;
    /// Length of the cycle the set fell into (0: none): the number of
    /// distinct sets it went round.
    unsigned int cycle_length = 0;
  };
} // namespace liftoff
