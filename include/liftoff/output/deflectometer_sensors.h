#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/physical_units.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/point_functional.h>
#include <liftoff/loads/deflectometer.h>
#include <liftoff/output/history_columns.h>
#include <liftoff/output/output.h>

#include <optional>
#include <string>
#include <vector>

namespace liftoff
{
  class RunSummary;
  class TimeHistory;

  /**
   * A deflectometer test's sensors (Loads/Deflectometer n): the deflection
   * at each one (in a time integration from the plate at rest at tau = 0,
   * settled under its permanent loads) in history.csv (columns "d(offset)"),
   * and each one's peak and its time, the basin, in the summary and in
   * basin.csv, all in the scene's units.
   */
  class DeflectometerSensors : public Output
  {
  public:
    /// Reads the deflectometer of the scene's Loads, if one is on; refuses
    /// two.
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;
    /// The offsets: an SI scene's default is the SHRP set; a dimensionless
    /// scene must give them.
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;
    /// Sensors on the plate (needs no mesh).
    void
    check(const SceneView &scene) const override;
    /// Adds the sensors' columns to `history`.
    void
    add_columns_to(TimeHistory &history) const override;

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

    /// The basin: each sensor's peak deflection and its time.
    void
    add_to(RunSummary &summary) const override;
    /// The peaks (solver's units), in the order of the offsets.
    const std::vector<double> &
    peaks() const;

  private:
    /// The deflections at the sensors from the rest state (collective).
    std::vector<double>
    deflections(const StepData &step) const;
    double
    rest_at(const unsigned int k) const;
    std::string
    column_name(const unsigned int k) const;

    std::optional<Deflectometer> test;
    PhysicalUnits                units;
    /// Offsets in the solver's units, and the sensors' points.
    std::vector<double>          offsets;
    std::vector<Point<2>>        points;
    std::vector<PointFunctional> probes;
    const Discretization        *discretization = nullptr;
    std::string                  directory;
    std::vector<double>          peak;
    std::vector<double>          peak_time;
    /// w at the sensors at tau = 0 of a time integration (empty: none
    /// yet, or a static analysis); set by whichever first asks for the
    /// deflections at tau = 0 (the history's columns or execute()).
    mutable std::vector<double> rest;
  };
} // namespace liftoff
