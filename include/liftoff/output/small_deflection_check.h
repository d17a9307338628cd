#pragma once

#include <liftoff/output/output.h>

#include <string>
#include <vector>

namespace liftoff
{
  class RunSummary;

  /**
   * Whether the answer stays within the plate theory that computed it: a
   * linear Mindlin plate holds while the deflection is small against the
   * thickness, since the membrane stretching it leaves out grows like
   * (w / H)^2. Over all steps it keeps the largest nodal |w| and its time;
   * in an SI scene, whose force scale is physical, the run warns by name
   * once |w| exceeds `largest_share` of the thickness. A dimensionless
   * scene's force scale F0 is free, so its w / H is not known and not
   * checked.
   */
  class SmallDeflectionCheck : public Output
  {
  public:
    /// The largest |w| / H accepted without a warning. At 0.2 the cubic
    /// membrane term of a clamped disc under pressure, w/H + 0.488
    /// (w/H)^3 = (linear w)/H (Timoshenko and Woinowsky-Krieger, Theory of
    /// Plates and Shells, section 97), changes w by 2 %.
    static constexpr double largest_share = 0.2;

    void
    write_in_units_of(const PhysicalUnits &units) override;
    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &scene) override;
    void
    execute(const StepData &step) override;
    void
    flush() override
    {}
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

    /// The largest |w| / H met so far (SI scenes; -1 in a dimensionless
    /// one).
    double
    largest_ratio() const;

    /// Empty while the deflection is small or not checked, else a
    /// sentence naming the largest |w|, its time and the thickness.
    std::string
    warning() const override;

    /// The largest |w| / H as an entry of the summary (SI scenes only).
    void
    add_to(RunSummary &summary) const override;

  private:
    bool is_checked = false;
    // One solver unit of w and of time, and H, in the scene's units.
    double w_scale = 1, time_scale = 1, thickness = 0;
    // Positions within this rank's vectors of its w unknowns.
    std::vector<unsigned int> w_entries;
    double                    largest_w = 0, time_of_largest = 0;
    bool                      has_warned = false;
  };
} // namespace liftoff
