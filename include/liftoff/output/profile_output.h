#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/archive_types.h>
#include <liftoff/base/output_files.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/point_functional.h>
#include <liftoff/output/output.h>

#include <fstream>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * Profiles of w along a straight line of the full plate at chosen times,
   * in one long-format CSV (tau, s, x, y, w) that plots grouped by tau.
   * Each requested time is written at the step nearest to it.
   */
  class ProfileOutput : public Output
  {
  public:
    /// Entries of the `Output` subsection.
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Write profiles.csv in the scene's units (TimeHistory's rule).
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;

    void
    check_against(const Discretization &discretization) const;

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
    setup(const Discretization &discretization,
          const std::string    &directory) override;
    void
    mesh_changed(const Discretization &discretization) override;

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
    Point<2>                     start, end;
    unsigned int                 n_points = 0;
    std::vector<double>          times;
    PhysicalUnits                units;
    std::vector<bool>            is_written;
    std::vector<PointFunctional> points;
    const Discretization        *discretization = nullptr;
    GrowingTextFile              file;

    Point<2>
    point(const unsigned int i) const;
  };
} // namespace liftoff
