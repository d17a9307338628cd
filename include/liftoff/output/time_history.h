#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/output_files.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/point_functional.h>
#include <liftoff/output/output.h>
#include <liftoff/time/energy_balance.h>

#include <functional>
#include <string>
#include <tuple>
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
   * A new column is a change of this class alone: a member of Row, its
   * value in row_of(), its name and value in make_columns(), and its place
   * in Row::serialize(). A checkpoint keeps the column names, so one of
   * other columns is refused by name instead of misread.
   */
  class TimeHistory : public Output
  {
  public:
    struct Row
    {
      double       tau              = 0;
      unsigned int iterations       = 0;
      unsigned int cycle_length     = 0;
      double       contact_fraction = 0;
      /// max(0, g - w) over the nodes of w (g the initial gap there, 0
      /// without one): how far the plate has lifted off its bed at the
      /// highest point (w > 0 is into the foundation), as the `uplift`
      /// field.
      double max_uplift = 0;
      /// The mesh of the step (it changes with Mesh refinement).
      unsigned long       n_cells = 0;
      unsigned long       n_dofs  = 0;
      std::vector<double> probe_w;
      EnergyBalance       energies;
      /// EnergyBalance::error() against the state at tau = 0.
      double balance_error = 0;
      /// TensionlessWinklerFoundation::resultant() of the full plate (if
      /// asked for): force, centre and area in contact.
      double resultant    = 0;
      double resultant_x  = 0;
      double resultant_y  = 0;
      double contact_area = 0;
      /// The largest bearing pressure and its point (in the meshed part),
      /// with the resultant.
      double max_pressure   = 0;
      double max_pressure_x = 0;
      double max_pressure_y = 0;
      /// The stress resultants of `Probe quantities`, in its order.
      std::vector<double> probe_quantities;
      /// With `Write moment extremes`: the largest M_1, the smallest M_2
      /// and the largest |Q| over the output points, each at its point.
      double max_m_1   = 0;
      double max_m_1_x = 0;
      double max_m_1_y = 0;
      double min_m_2   = 0;
      double min_m_2_x = 0;
      double min_m_2_y = 0;
      double max_q     = 0;
      double max_q_x   = 0;
      double max_q_y   = 0;
      /// x, y and the loads on the plate of each moving load (follow()).
      std::vector<double> moving_loads;
      std::vector<double> riding_values;

      /// The members serialize() archives, in its order: a checkpoint
      /// keeps them, and one of another layout is refused by name before
      /// its rows are read. A new member goes into both.
      static std::vector<std::string>
      layout()
      {
        return {"tau",
                "iterations",
                "cycle_length",
                "contact_fraction",
                "max_uplift",
                "n_cells",
                "n_dofs",
                "probe_w",
                "energies",
                "balance_error",
                "resultant",
                "resultant_x",
                "resultant_y",
                "contact_area",
                "max_pressure",
                "max_pressure_x",
                "max_pressure_y",
                "probe_quantities",
                "max_m_1",
                "max_m_1_x",
                "max_m_1_y",
                "min_m_2",
                "min_m_2_x",
                "min_m_2_y",
                "max_q",
                "max_q_x",
                "max_q_y",
                "moving_loads",
                "riding_probes"};
      }

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &tau &iterations &cycle_length &contact_fraction &max_uplift
          &n_cells &n_dofs &probe_w &energies &balance_error &resultant
            &resultant_x &resultant_y &contact_area &max_pressure
              &max_pressure_x &max_pressure_y &probe_quantities &max_m_1
                &max_m_1_x &max_m_1_y &min_m_2 &min_m_2_x &min_m_2_y &max_q
                  &max_q_x &max_q_y &moving_loads &riding_values;
      }
    };

    /// Entries of the `Output` subsection.
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const MindlinPlate &plate);

    /// The default probe is the plate's centre, which an annulus lacks
    /// (it lies in the hole): there the default gives no probe. Returns
    /// whether it was dropped.
    bool
    drop_default_probe_off(const PlateGeometry &geometry);


    /// Probes inside the plate (full plate coordinates); needs no mesh.
    void
    check_against(const Discretization &discretization) const;

    bool
    wants_energies() const;
    /// Columns <name>_x, <name>_y, <name>_on per moving load, their values
    /// at tau in that order from `positions` (LoadSet's moving loads).
    void
    follow(const std::vector<std::string>                         &names,
           const std::function<std::vector<double>(const double)> &positions);

    /// Write the dashpots' dissipated energy (a column `dissipated_energy`
    /// after `work`, with the energies): only a scene with dashpots has it.
    void
    show_dissipated_energy(const bool show);

    /// Write the columns in the scene's units: an SI scene's names carry
    /// their unit ("t [s]", "w(2.5;0) [m]") and its values are in SI; a
    /// dimensionless scene's columns are as they were.
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;

    void
    setup(const Discretization &discretization,
          const std::string    &directory) override;
    void
    mesh_changed(const Discretization &discretization) override;
    void
    execute(const StepData &step) override;
    void
    flush() override;
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

    const std::vector<Row> &
    rows() const;

    /// Over the rows that solved something (not tau = 0 of a dynamic run).
    struct IterationStatistics
    {
      double       mean     = 0;
      unsigned int max      = 0;
      unsigned int n_cycled = 0;
    };
    IterationStatistics
    iteration_statistics() const;

  private:
    /// The history's column names of the probes, "w(x;y)", with enough
    /// digits to tell every two points apart.
    /// Names "quantity(x;y)" with as many digits as tell the points apart.
    std::vector<std::string>
    probe_column_names(const std::vector<std::string> &quantities,
                       const std::vector<Point<2>>    &points) const;

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
    std::vector<double>
    probe_quantities(const StepData &step) const;

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
    riding_probe_values(const StepData &step, const Row &row) const;

    /// The probes' values (0 where no rank holds a cell), collective.
    std::vector<double>
    values_at(const StepData                   &step,
              const std::vector<QuantityProbe> &probes) const;
    void
    add_moment_extremes(const StepData &step, Row &row) const;

    /// One column of history.csv: its name in the header and its value in
    /// a row (integers are exact in a double).
    struct Column
    {
      std::string                        name;
      std::function<double(const Row &)> value;
    };
    /// The columns of this run, in the file's order; made anew whenever a
    /// parameter that chooses them is set.
    std::vector<Column> columns;
    using Member =
      std::tuple<std::string, double Row::*, PhysicalUnits::Quantity>;
    /// The columns of `members`, in their order.
    void
    add_members(const std::vector<Member> &members);
    void
    add_probe_columns();
    void
    add_energy_columns();
    void
    add_quantity_probe_columns();
    void
    make_columns();
    /// Appends the column `name` of `value`, a `quantity` of the solver,
    /// in the scene's units.
    void
    add_column(const std::string                 &name,
               std::function<double(const Row &)> value,
               const PhysicalUnits::Quantity      quantity);
    std::vector<std::string>
    column_names() const;

    PhysicalUnits                units;
    std::vector<Point<2>>        probe_points;
    bool                         write_energies        = true;
    bool                         write_dissipated      = false;
    bool                         write_resultant       = false;
    bool                         write_moment_extremes = false;
    MindlinPlate                 plate;
    std::vector<PointFunctional> probes;
    std::vector<std::string>     moving_load_names;
    std::function<std::vector<double>(const double)> moving_load_positions;
    /// This rank's degrees of freedom of w.
    IndexSet w_dofs;
    /// The initial gap at them, in the order of w_dofs (filled at the first
    /// step on a mesh, only on a gap).
    std::vector<double> gap_at_w_dofs;
    /// The velocity with ghosts, for the dashpots' part of the resultant.
    LA::MPI::Vector       ghosted_velocity;
    const Discretization *discretization = nullptr;
    GrowingTextFile       file;
    std::vector<Row>      history;

    Row
    row_of(const StepData &step) const;
    /// g at the w dofs of this mesh, if not yet known.
    void
    find_gap_at_w_dofs(const StepData &step);
    void
    write_header();
    void
    write_row(const Row &row);
  };
} // namespace liftoff
