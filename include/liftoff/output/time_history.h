#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/output_files.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/point_functional.h>
#include <liftoff/output/history_columns.h>
#include <liftoff/output/output.h>

#include <functional>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The CSV time history a user plots, one row per step: tau, w at the
   * scene's probe points, contact area fraction, the largest uplift,
   * active-set iterations, the length of an active-set cycle resolved by the
   * cycle rule (0: none), the cells and dofs of the mesh and, when asked for,
   * the energies and their balance and the foundation's resultant. The rows are
   * kept (tests and the summary read them; a checkpoint saves them); the file
   * is replaced whole (atomically) at most once a second and at the end, so a
   * reader never sees a half-written row.
   *
   * A new column is one call of HistoryColumns::add() in make_columns():
   * its name, its quantity and its value at a step; the columns are made
   * once, at setup(), when every output has added its own. A checkpoint keeps
   * the column names with the rows, so one of other columns is refused by name
   * instead of misread.
   */
  class RunSummary;

  class TimeHistory : public Output
  {
  public:
    TimeHistory() = default;
    /// The columns' values refer to this object.
    TimeHistory(const TimeHistory &) = delete;
    TimeHistory &
    operator=(const TimeHistory &) = delete;

    /// Entries of the `Output` subsection.
    static void
    declare_parameters(ParameterHandler &prm);
    /// Also follows the scene's moving loads (columns <name>_x, <name>_y,
    /// <name>_on per load) and shows the dashpots' dissipated energy (a
    /// column after `work`, with the energies) where the bed has dashpots.
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;

    /// Probes inside the plate (full plate coordinates); needs no mesh.
    void
    check(const SceneView &scene) const override;

    bool
    wants_energies() const;

    /// Columns another output computes (a deflectometer's sensors), after
    /// the others.
    void
    add_columns(const std::vector<HistoryColumns::Column> &group,
                HistoryColumns::Values                     values);

    /// With Time step control = error: the columns dt_min, substeps and
    /// local_error, the smallest step, the number of steps and the sum of
    /// their local error estimates since the last row, which `values`
    /// gives.
    void
    add_step_sizes(const std::function<std::vector<double>()> &values);

    /// Write the columns in the scene's units: an SI scene's names carry
    /// their unit ("t [s]", "w(2.5;0) [m]") and its values are in SI; a
    /// dimensionless scene's columns are as they were.
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

    const std::vector<HistoryRow> &
    rows() const;

    /// The active-set iterations per step, mean and largest, and the steps
    /// whose set cycled, over the rows that solved something (not tau = 0
    /// of a dynamic run), as lines of the summary.
    void
    add_to(RunSummary &summary) const override;

    /// Names "quantity(x;y)" of points of the full plate in the scene's
    /// units, with as many digits as tell the points apart.
    std::vector<std::string>
    probe_column_names(const std::vector<std::string> &quantities,
                       const std::vector<Point<2>>    &points) const;

  private:
    /// The default probe is the plate's centre, which an annulus lacks
    /// (it lies in the hole): there the default gives no probe. Returns
    /// whether it was dropped.
    bool
    drop_default_probe_off(const PlateGeometry &geometry);
    /// The columns of the moving loads, their values at tau in that order
    /// from `positions`.
    void
    follow(const std::vector<std::string>                         &names,
           const std::function<std::vector<double>(const double)> &positions);

    /// A probe of a stress resultant: its field, its point and, on the
    /// rank that holds the point, the cells around it with the point's
    /// unit coordinates (PointFunctional::holder_cells()).
    struct QuantityProbe
    {
      std::string quantity;
      Point<2>    point;
      PointCells  cells;
      double      sign = 1;
    };
    std::vector<QuantityProbe> quantity_probes;

    /// A probe that rides with a moving load: w or a stress resultant at
    /// the load's current position (0 while the load is off the plate).
    struct RidingProbe
    {
      std::string  name; // "quantity@load", the column's name
      std::string  quantity;
      std::string  load;
      unsigned int index = 0; // of the load in moving_load_names
    };
    std::vector<RidingProbe> riding_probes;

    std::vector<double>
    riding_probe_values(const StepData &step) const;

    /// The probes' values (0 where no rank holds a cell), collective.
    std::vector<double>
    values_at(const StepData                   &step,
              const std::vector<QuantityProbe> &probes) const;
    /// The largest M_1, the smallest M_2 and the largest |Q| with their
    /// points (collective).
    std::vector<double>
    moment_extremes(const StepData &step) const;
    /// max(0, g - w) over the nodes of w (g the initial gap there, 0
    /// without one): how far the plate has lifted off its bed at the
    /// highest point (w > 0 is into the foundation), as the `uplift` field.
    double
    largest_uplift(const StepData &step) const;

    /// The columns of this run, in the file's order; made anew whenever a
    /// parameter that chooses them is set.
    HistoryColumns columns;
    /// Each column's factor to the scene's units.
    std::vector<double> scales;
    void
    add_probe_columns();
    void
    add_energy_columns();
    /// The names of the terms' energies (SceneView::energy_columns).
    std::vector<std::string> energy_columns;
    void
    add_resultant_columns();
    void
    add_interface_columns();
    void
    add_quantity_probe_columns();
    void
    add_moving_load_columns();
    /// shear_<joint> and lte_<joint> of each joint that is not tied.
    void
    add_joint_columns();
    void
    make_columns();
    /// The header's names: in an SI scene "t" for tau, each with its unit.
    std::vector<std::string>
    column_names() const;

    PhysicalUnits units;
    /// The groups of add_columns().
    std::vector<
      std::pair<std::vector<HistoryColumns::Column>, HistoryColumns::Values>>
                          other_columns;
    std::vector<Point<2>> probe_points;
    bool                  write_energies   = true;
    bool                  write_dissipated = false;
    bool                  write_resultant  = false;
    /// A base the slab can lift off: its interface's contact, resultant
    /// and largest pressure.
    bool                         has_interface         = false;
    bool                         write_moment_extremes = false;
    MindlinPlate                 plate;
    std::vector<PointFunctional> probes;
    std::vector<std::string>     moving_load_names;
    /// The joints that are not tied, by their index in the layout.
    std::vector<std::pair<unsigned int, std::string>> joints;
    std::function<std::vector<double>(const double)>  moving_load_positions;
    /// This rank's degrees of freedom of the w the bed acts on.
    IndexSet w_dofs;
    /// The initial gap at them, in the order of w_dofs (filled at the first
    /// step on a mesh, only on a gap).
    std::vector<double> gap_at_w_dofs;
    /// The velocity with ghosts, for the dashpots' part of the resultant.
    LA::MPI::Vector         ghosted_velocity;
    const Discretization   *discretization = nullptr;
    GrowingTextFile         file;
    std::vector<HistoryRow> history;

    /// g at the w dofs of this mesh, if not yet known.
    void
    find_gap_at_w_dofs(const StepData &step);
    void
    write_header();
    void
    write_row(const HistoryRow &row);
  };
} // namespace liftoff
