#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/time/energy_balance.h>

#include <string>

namespace liftoff
{
  using namespace dealii;

  /**
   * The energy balance as a check of the run. Newmark's average
   * acceleration rule conserves the energy of a linear system exactly, and
   * the switching of contact and the transfers between meshes leave a
   * balance error of a small share of the energies (at most 3.2e-3 in the
   * scenes of prm/, 2.9e-9 on a quarter plate under a point load). A
   * time step too long for the bed, a loose solver tolerance or
   * parameters beyond what double precision resolves give errors of the
   * order of the energies themselves (0.96 to 1.66 in the scenes of
   * doc/reliability.md). The error is compared with the run's energy
   * scale: the largest stored energy, initial energy, work or dissipated
   * energy seen so far, so that a run at rest is not judged by round-off
   * and a balance is not judged against an energy that has not appeared.
   */
  class EnergyCheck
  {
  public:
    enum class Mode
    {
      off,
      warn,
      fail
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    bool
    is_enabled() const;
    Mode
    mode() const;

    /// Take the energies of `step`; true at the first step whose balance
    /// error exceeds the tolerance (once per run). A scheme that dissipates
    /// energy by design loses some of it: then only a gain counts.
    bool
    exceeds(const unsigned int   step,
            const EnergyBalance &energies,
            const EnergyBalance &initial,
            const bool           scheme_dissipates);

    /// "the balance error at step 12 (-0.049) is 0.96 of the run's energy
    /// scale 0.051, above Energy check/Tolerance = 0.01", of the first
    /// step that exceeded it.
    std::string
    describe_violation() const;

    /// Largest |error| / scale of the run and its step (for the summary).
    double
    largest_relative_error() const;
    unsigned int
    step_of_largest_error() const;
    bool
    was_exceeded() const;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &scale &largest &largest_step &first_step &first_error
        &first_scale &exceeded;
    }

  private:
    Mode   check_mode = Mode::warn;
    double tolerance  = 1e-2;

    double       scale        = 0;
    double       largest      = 0;
    unsigned int largest_step = 0;
    unsigned int first_step   = 0;
    double       first_error  = 0;
    double       first_scale  = 0;
    bool         exceeded     = false;
  };
} // namespace liftoff
