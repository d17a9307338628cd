#pragma once

#include <liftoff/base/linear_algebra.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/output/output.h>

#include <string>
#include <vector>

namespace liftoff
{
  class JointDowels;
  class TimeHistory;

  /// The dowels' forces at ghosted_u as points of a field file, stem.vtu
  /// (from rank 0, which has them all): at each dowel's
  /// point its `force` (from the lower slab to the upper one) and, for
  /// Friberg's bars, the `bearing_stress` under it, in `units`; named by
  /// `dowel` (its column in history.csv, less the prefix). Collective.
  void
  write_dowel_points(const std::string     &directory,
                     const JointDowels     &dowels,
                     const LA::MPI::Vector &ghosted_u,
                     const PhysicalUnits   &units,
                     const MPI_Comm         comm,
                     const double           time,
                     const std::string     &stem);

  /**
   * The dowels' forces (Slabs/Dowels): each dowel's force in history.csv
   * (columns dowel_<joint>_<k>, from the lower slab to the upper one), and
   * in the summary the dowels' stiffness and the largest force of the run
   * with its dowel and time, and, for bars of Friberg's analysis, the
   * bearing stress on the concrete under it. A scene without dowels writes
   * none of these.
   */
  class DowelForces : public Output
  {
  public:
    /// The scene's dowels (none: nothing is written).
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;

    void
    write_in_units_of(const PhysicalUnits &scene_units) override;
    /// Adds the dowels' columns to `history`.
    void
    add_columns_to(TimeHistory &history) const override;
    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &) override
    {}
    void
    execute(const StepData &step) override;
    void
    flush() override
    {}
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;
    void
    add_to(RunSummary &summary) const override;

  private:
    const JointDowels *dowels = nullptr;
    PhysicalUnits      units;
    /// The largest |force| so far (solver's units), its dowel and time.
    double       largest      = 0;
    unsigned int largest_of   = 0;
    double       largest_time = 0;
  };
} // namespace liftoff
