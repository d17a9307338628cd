#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/output_files.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/output/output.h>
#include <liftoff/output/profile_times.h>

#include <string>

namespace liftoff
{
  using namespace dealii;

  class Discretization;
  class PlateGeometry;

  /**
   * Profiles along the joints at the Profile times (`Output/Joint
   * profiles`): joints.csv, in long format, one row per Gauss point of
   * each joint that is not tied, ordered by joint and by s, the distance
   * along it from its lower end: w on the lower
   * (left, bottom) and the upper slab, the load transfer there (the
   * smaller side's w over the larger's) and the shear force per length
   * the aggregate interlock passes from the lower slab to the upper one
   * (dowels pass point forces: their columns of history.csv). The points
   * are those the joint's springs are integrated at, so the profile's
   * shear integrates to the history's shear_<joint>.
   */
  class JointProfiles : public Output
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    /// Refuses profiles of a plate without joints that are not tied.
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;
    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &scene) override;
    void
    execute(const StepData &step) override;
    void
    flush() override;
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

  private:
    bool                  is_on = false;
    ProfileTimes          times;
    PhysicalUnits         units;
    const Discretization *discretization = nullptr;
    GrowingTextFile       file;
  };
} // namespace liftoff
