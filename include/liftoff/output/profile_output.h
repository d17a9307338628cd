#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/archive_types.h>
#include <liftoff/base/output_files.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/point_functional.h>
#include <liftoff/output/output.h>
#include <liftoff/output/profile_times.h>

#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * Profiles of w along a straight line of the full plate at chosen times,
   * in one long-format CSV (tau, s, x, y, w) that plots grouped by tau.
   * Each requested time is written at the step nearest to it.
   *
   * A profile may ride with a moving load (`Profile follows`): its line is
   * then given relative to the load's point and placed where the load is
   * at each profile time, so the profiles are the deflection basin around
   * the load, in the load's frame, at chosen times. Its points off the
   * plate at that time are left out of the file.
   */
  class ProfileOutput : public Output
  {
  public:
    /// Entries of the `Output` subsection.
    static void
    declare_parameters(ParameterHandler &prm);
    /// Also finds the moving load a riding profile follows, refusing a
    /// `Profile follows` that names none of the scene's.
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;

    /// Write profiles.csv in the scene's units (TimeHistory's rule).
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;

    /// The line on the plate; a warning of the times a time integration
    /// does not reach.
    void
    check(const SceneView &scene) const override;

    /// The requested times that a time integration with step `dt` to
    /// `end_time` does not reach (nearer to no step than dt/2).
    std::vector<double>
    times_not_reached(const double end_time, const double dt) const;
    /// A shortened run (a try, or a resume to a later end) may skip
    /// profiles: a warning on rank 0 names them rather than drop them
    /// unnoticed.
    void
    warn_of_times_not_reached(const double   end_time,
                              const double   dt,
                              const MPI_Comm comm) const;

    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &scene) override;

    /// Write the profiles requested for times within dt/2 of tau; in a
    /// static analysis (time step 0) write one profile unconditionally.
    void
    execute(const StepData &step) override;

    /// The profiles written so far and which times they were for; after
    /// load(), profiles.csv is left as it is until the next flush().
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

    /// Write profiles.csv now (collective; nothing without profiles).
    void
    flush() override;

  private:
    /// The moving loads' names and their points at tau (LoadSet's
    /// moving_load_names() and moving_load_positions()).
    void
    follow(const std::vector<std::string>                         &names,
           const std::function<std::vector<double>(const double)> &positions);

    Point<2>     start, end;
    unsigned int n_points = 0;
    /// The moving load the line rides with ("": the line stands), its
    /// index among the moving loads and their positions.
    std::string                                      rider;
    unsigned int                                     rider_index = 0;
    std::function<std::vector<double>(const double)> load_positions;
    ProfileTimes                                     times;
    PhysicalUnits                                    units;
    std::vector<PointFunctional>                     points;
    const Discretization                            *discretization = nullptr;
    GrowingTextFile                                  file;

    /// The i-th point of the line as the scene gives it (relative to the
    /// load for a riding profile) ...
    Point<2>
    point(const unsigned int i) const;
    /// ... and where the line's points are on the plate at tau.
    std::vector<Point<2>>
    line_at(const double tau) const;
    /// The functionals of the points on the plate at tau (all of them for
    /// a standing line), which points they are and where the line is.
    void
                              locate_points(const double tau);
    std::vector<unsigned int> located;
    std::vector<Point<2>>     line;
  };
} // namespace liftoff
