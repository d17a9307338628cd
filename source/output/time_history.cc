#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/located_maximum.h>
#include <liftoff/base/number_text.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/joint_springs.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/time/plate_state.h>

#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/stress_resultants.h>
#include <liftoff/output/time_history.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include <iomanip>
#include <limits>
#include <sstream>
#include <tuple>

namespace liftoff
{
  namespace
  {
    /// The w the bed's springs act on (the base's under a base of its
    /// own), whose uplift max_uplift is.
    ComponentMask
    bed_w_mask(const Discretization &disc)
    {
      const FiniteElement<2> &fe = disc.dof_handler.get_fe();
      return PlateFields::component_mask(fe, PlateFields::bed_component(fe));
    }


    std::vector<Point<2>>
    parse_points(const std::string &text)
    {
      std::vector<Point<2>> points;
      for (const auto &entry : Utilities::split_string_list(text, ';'))
        {
          const auto xy = Utilities::string_to_double(
            Utilities::split_string_list(entry, ','));
          points.emplace_back(xy[0], xy[1]);
        }
      return points;
    }


    /// The kind of the unit of w or a stress resultant.
    PhysicalUnits::Quantity
    quantity_of(const std::string &field)
    {
      return field == "w" ? PhysicalUnits::Quantity::deflection
                          : StressResultants::quantities().at(field);
    }


    /// "M_xx(0.25; 0), Q_x(0.5; 0)" as the quantities and points it names.
    std::vector<std::pair<std::string, Point<2>>>
    parse_quantity_list(const std::string &text)
    {
      std::vector<std::pair<std::string, Point<2>>> probes;
      // Commas inside the parentheses (a point written x, y) belong to
      // their entry, which then says what it should be.
      std::vector<std::string> entries(1);
      int                      depth = 0;
      for (const char c : text)
        {
          depth += (c == '(') - (c == ')');
          if (c == ',' && depth == 0)
            entries.emplace_back();
          else
            entries.back() += c;
        }
      for (std::string entry : entries)
        {
          entry = Utilities::trim(entry);
          if (entry.empty() && entries.size() == 1)
            break;
          const auto refuse = [&](const std::string &why) {
            AssertThrow(false,
                        ExcMessage("Output/Probe quantities: <" + entry + "> "
                                   + why));
          };
          const auto open = entry.find('('), close = entry.rfind(')');
          if (open == std::string::npos || close != entry.size() - 1)
            refuse("is not of the form NAME(x; y).");
          const std::string name = Utilities::trim(entry.substr(0, open));
          const auto        xy   = Utilities::split_string_list(
            entry.substr(open + 1, close - open - 1), ';');
          if (xy.size() != 2 || !Patterns::Double().match(xy[0])
              || !Patterns::Double().match(xy[1]))
            refuse("does not name a point x; y.");
          const auto &fields = StressResultants::field_names();
          if (std::find(fields.begin(), fields.end(), name) == fields.end())
            refuse("names no field; allowed are " + joined(fields, ", ") + ".");
          const Point<2> p(Utilities::string_to_double(xy[0]),
                           Utilities::string_to_double(xy[1]));
          for (const auto &[other, q] : probes)
            if (other == name && q == p)
              refuse("is given twice.");
          probes.emplace_back(name, p);
        }
      return probes;
    }


    /// "w@patch_load_1, M_xx@vehicle_1" as its entries; the loads are
    /// looked up once the moving loads are known (TimeHistory::follow()).
    std::vector<std::pair<std::string, std::string>>
    parse_riding_probes(const std::string &text)
    {
      std::vector<std::pair<std::string, std::string>> probes;
      const auto &fields = StressResultants::field_names();
      for (const auto &entry : Utilities::split_string_list(text, ','))
        {
          const auto parts = Utilities::split_string_list(entry, '@');
          AssertThrow(parts.size() == 2
                        && (parts[0] == "w"
                            || std::find(fields.begin(), fields.end(), parts[0])
                                 != fields.end()),
                      ExcMessage("Output/Riding probes: <" + entry
                                 + "> is not QUANTITY@LOAD with QUANTITY w "
                                   "or one of "
                                 + joined(fields, ", ")
                                 + " and LOAD a moving load's name, e.g. "
                                   "w@patch_load_1."));
          const std::pair<std::string, std::string> probe(parts[0], parts[1]);
          AssertThrow(std::find(probes.begin(), probes.end(), probe)
                        == probes.end(),
                      ExcMessage("Output/Riding probes: <" + entry
                                 + "> is given twice."));
          probes.push_back(probe);
        }
      return probes;
    }


    void
    declare_riding_probes(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Riding probes",
        "",
        Patterns::Anything(),
        "Probes that ride with moving loads, written to history.csv at every "
        "step: a comma-separated list of QUANTITY@LOAD, QUANTITY w or a field "
        "of `Probe quantities`, LOAD a moving load's name as in its history "
        "columns (point_load_N, patch_load_N, vehicle_N: the path's point), "
        "e.g. `w@patch_load_1, M_xx@patch_load_1`; the column is so named. "
        "The value is taken at the load's position of the row; 0 while it is "
        "off the plate (its `_on` column says when)."
          + quantity("text"));
    }


    /// The sign a field takes at a point of a mirrored part from its value
    /// at the point's image: odd are the shear force normal to the plane,
    /// the twisting moment and the angle.
    double
    mirror_sign(const std::string &quantity,
                const Point<2>    &point,
                const Point<2>    &image)
    {
      double sign = 1;
      for (unsigned int axis = 0; axis < 2; ++axis)
        if (image[axis] != point[axis])
          for (const std::string &odd : {std::string(axis == 0 ? "Q_x" : "Q_y"),
                                         std::string("M_xy"),
                                         std::string("sigma_xy"),
                                         std::string("M_1_angle")})
            if (quantity == odd)
              sign = -sign;
      return sign;
    }


    /// w or a stress resultant at a unit point of a cell.
    double
    value_in_cell(const Discretization                      &disc,
                  const StressResultants                    &resultants,
                  const LA::MPI::Vector                     &ghosted_u,
                  const std::string                         &quantity,
                  const DoFHandler<2>::active_cell_iterator &cell,
                  const Point<2>                            &unit_point)
    {
      FEValues<2> fe_values(disc.mapping(),
                            disc.dof_handler.get_fe(),
                            Quadrature<2>(unit_point),
                            update_values | update_gradients
                              | update_quadrature_points);
      fe_values.reinit(cell);
      if (quantity == "w")
        {
          std::vector<double> w(1);
          fe_values[PlateFields::w_extractor()].get_function_values(ghosted_u,
                                                                    w);
          return w[0];
        }
      std::vector<Vector<double>> fields;
      resultants.evaluate(cell, fe_values, fields);
      return fields[0][StressResultants::field_index(quantity)];
    }


    /// w or a stress resultant at a point, from the cells around it (the
    /// holder's, PointFunctional::holder_cells()). w is continuous: the
    /// first cell's value, as a probe point takes it. A stress resultant
    /// jumps across the edges of the cells (its derivatives of the
    /// solution are continuous only inside a cell), so a point on an edge
    /// or a vertex has one value on each side, and no side is the right
    /// one: the mean of the sides', in the order of the cells' CellId,
    /// which the exact, continuous field's value approaches as the mesh
    /// is refined, and which does not depend on the order of the cells.
    double
    value_at(const Discretization   &disc,
             const StressResultants &resultants,
             const LA::MPI::Vector  &ghosted_u,
             const std::string      &quantity,
             const PointCells       &cells)
    {
      const unsigned int n   = quantity == "w" ? 1 : cells.size();
      double             sum = 0;
      for (unsigned int c = 0; c < n; ++c)
        sum += value_in_cell(disc,
                             resultants,
                             ghosted_u,
                             quantity,
                             cells[c].first,
                             cells[c].second);
      return sum / n;
    }
  } // namespace


  void
  TimeHistory::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Probe points",
      "0, 0",
      Patterns::List(Patterns::List(Patterns::Double(), 2, 2, ","),
                     0,
                     Patterns::List::max_int_value,
                     ";"),
      "Points x, y of the full plate, separated by ';', whose "
      "deflection w is written to history.csv at every step. On an "
      "annulus the point 0, 0 lies in the hole and gives no probe (the "
      "run says so), so that the default needs no change there."
        + quantity("position"));
    prm.declare_entry("Write energies",
                      "true",
                      Patterns::Bool(),
                      "Write the kinetic energy, the energy each term of the "
                      "system stores (strain, foundation, and on a jointed "
                      "plate joint_springs and dowels), the work of the "
                      "loads and the balance error to history.csv (costs "
                      "two matrix-vector products per step).");
    prm.declare_entry(
      "Write foundation resultant",
      "false",
      Patterns::Bool(),
      "Write the bed's normal reaction on the full plate to history.csv: "
      "`resultant`, the force of the springs and dashpots int_S (Gamma "
      "(w - g) + c w_dot) over the contact region S (the shear layer adds "
      "no force), its centre `resultant_x`, `resultant_y` (the point about "
      "which it has no moment; 0, 0 without a force) and `contact_area`, "
      "in full plate units also on a half or quarter model; and the largest "
      "bearing pressure at a Gauss point in contact, `max_pressure` (0 "
      "without contact), at `max_pressure_x`, `max_pressure_y` (a point of "
      "the meshed part) (costs a pass over the Gauss points per step).");
    prm.declare_entry(
      "Probe quantities",
      "",
      Patterns::Anything(),
      "Stress resultants at points of the full plate, written to "
      "history.csv at every step: a comma-separated list of NAME(x; y) with "
      "NAME one of M_xx, M_yy, M_xy, Q_x, Q_y, M_1, M_2, M_1_angle, "
      "sigma_xx, sigma_yy, sigma_xy, sigma_max (the fields of `Moment "
      "fields`, doc/model.md), e.g. `M_xx(0.25; 0), Q_x(0.5; 0)`. The "
      "fields jump across cell edges: at a point on an edge or a vertex the "
      "value is the mean of the cells that meet there."
        + quantity("position"));
    prm.declare_entry(
      "Write moment extremes",
      "false",
      Patterns::Bool(),
      "Write the extremes over the plate of the principal moments and of "
      "the shear force's magnitude to history.csv: `max_M_1`, the largest "
      "M_1, and `min_M_2`, the smallest M_2 (a positive moment puts the "
      "bed-side face in tension: doc/model.md), and `max_Q`, the largest "
      "|Q|, each with its point `_x`, `_y` (of the meshed part), over the "
      "output points of the field files (costs a pass over those points "
      "per step).");
    declare_riding_probes(prm);
  }


  void
  TimeHistory::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    other_columns.clear();
    plate        = scene.plate;
    probe_points = parse_points(prm.get("Probe points"));
    for (unsigned int i = 0; i < probe_points.size(); ++i)
      for (unsigned int j = 0; j < i; ++j)
        AssertThrow(probe_points[i] != probe_points[j],
                    ExcMessage(
                      "Output/Probe points: the point "
                      + format_point(probe_points[i][0], probe_points[i][1])
                      + " is given twice."));
    write_energies        = prm.get_bool("Write energies");
    write_resultant       = prm.get_bool("Write foundation resultant");
    write_moment_extremes = prm.get_bool("Write moment extremes");
    quantity_probes.clear();
    for (const auto &[quantity, point] :
         parse_quantity_list(prm.get("Probe quantities")))
      quantity_probes.push_back({quantity, point, {}});
    riding_probes.clear();
    for (const auto &[quantity, load] :
         parse_riding_probes(prm.get("Riding probes")))
      riding_probes.push_back({quantity + "@" + load, quantity, load});
    if (drop_default_probe_off(scene.discretization.geometry()))
      scene.notes << "liftoff: no probe: 0, 0 lies in the annulus's hole.\n";
    // Only a scene with dashpots dissipates.
    write_dissipated     = scene.bed.law().has_damping();
    has_interface        = scene.interface != nullptr;
    const LoadSet &loads = scene.loads;
    follow(loads.moving_load_names(), [&loads](const double tau) {
      return loads.moving_load_positions(tau);
    });
  }


  void
  TimeHistory::check(const SceneView &scene) const
  {
    const Discretization &disc = scene.discretization;
    for (const auto &p : probe_points)
      AssertThrow(disc.geometry().is_on_plate(p),
                  ExcMessage("Output/Probe points: the point "
                             + format_point(p[0], p[1]) + " lies outside "
                             + disc.geometry().plate_description() + "."));
    for (const auto &probe : quantity_probes)
      AssertThrow(disc.geometry().is_on_plate(probe.point),
                  ExcMessage("Output/Probe quantities: the point "
                             + format_point(probe.point[0], probe.point[1])
                             + " of " + probe.quantity + " lies outside "
                             + disc.geometry().plate_description() + "."));
    // The base's faces exist with a base only.
    std::vector<std::string> quantities;
    for (const auto &probe : quantity_probes)
      quantities.push_back(probe.quantity);
    for (const auto &probe : riding_probes)
      quantities.push_back(probe.quantity);
    for (const std::string &quantity : quantities)
      AssertThrow(scene.plate.base.present()
                    || quantity.rfind("sigma_1_base", 0) != 0,
                  ExcMessage("Output/Probe quantities, Riding probes: "
                             + quantity
                             + " is a stress of the base's face, and the "
                               "scene has no base (Base/Interface = none)."));
  }


  bool
  TimeHistory::drop_default_probe_off(const PlateGeometry &geometry)
  {
    if (probe_points != std::vector<Point<2>>{Point<2>()}
        || geometry.is_on_plate(Point<2>()))
      return false;
    probe_points.clear();
    return true;
  }


  std::vector<std::string>
  TimeHistory::probe_column_names(const std::vector<std::string> &quantities,
                                  const std::vector<Point<2>>    &points) const
  {
    // Six digits name most points briefly; points that six digits do not
    // tell apart (0.333333 and 0.3333334) get as many as they need.
    for (int digits = 6;; ++digits)
      {
        std::vector<std::string> names;
        // In the scene's units: metres in an SI scene.
        const double length = units.scale(PhysicalUnits::Quantity::length);
        for (unsigned int k = 0; k < points.size(); ++k)
          {
            std::ostringstream name;
            name << std::setprecision(digits) << quantities[k] << "("
                 << length * points[k][0] << ";" << length * points[k][1]
                 << ")";
            names.push_back(name.str());
          }
        std::vector<std::string> sorted = names;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()
            || digits == std::numeric_limits<double>::max_digits10)
          return names;
      }
  }


  bool
  TimeHistory::wants_energies() const
  {
    return write_energies;
  }


  void
  TimeHistory::follow(
    const std::vector<std::string>                         &names,
    const std::function<std::vector<double>(const double)> &positions)
  {
    moving_load_names     = names;
    moving_load_positions = positions;
    for (auto &probe : riding_probes)
      {
        const auto found = std::find(names.begin(), names.end(), probe.load);
        AssertThrow(found != names.end(),
                    ExcMessage("Output/Riding probes: <" + probe.name
                               + "> names no moving load; the scene's are <"
                               + joined(names, ", ") + ">."));
        probe.index = found - names.begin();
      }
  }


  void
  TimeHistory::add_columns(const std::vector<HistoryColumns::Column> &group,
                           HistoryColumns::Values                     values)
  {
    if (group.empty())
      return;
    other_columns.emplace_back(group, std::move(values));
  }


  void
  TimeHistory::add_step_sizes(
    const std::function<std::vector<double>()> &values)
  {
    add_columns({{"dt_min", PhysicalUnits::Quantity::time},
                 {"substeps", PhysicalUnits::Quantity::number},
                 {"local_error", PhysicalUnits::Quantity::deflection}},
                [values](const StepData &) { return values(); });
  }


  void
  TimeHistory::make_columns()
  {
    using Quantity = PhysicalUnits::Quantity;
    columns.clear();
    columns.add("tau", Quantity::time, [](const StepData &step) {
      return step.state.clock.tau();
    });
    add_probe_columns();
    columns.add("contact_fraction", Quantity::number, [](const StepData &step) {
      return step.contact_fraction;
    });
    columns.add("max_uplift", Quantity::deflection, [this](const StepData &s) {
      return largest_uplift(s);
    });
    columns.add("active_set_iterations",
                Quantity::number,
                [](const StepData &step) -> double {
                  return step.iteration.iterations;
                });
    columns.add("active_set_cycle",
                Quantity::number,
                [](const StepData &step) -> double {
                  return step.iteration.cycle_length;
                });
    columns.add("cells", Quantity::number, [](const StepData &step) -> double {
      return step.scene.discretization.triangulation.n_global_active_cells();
    });
    columns.add("dofs", Quantity::number, [](const StepData &step) -> double {
      return step.scene.discretization.dof_handler.n_dofs();
    });
    if (write_energies)
      add_energy_columns();
    if (write_resultant)
      add_resultant_columns();
    if (has_interface)
      add_interface_columns();
    add_quantity_probe_columns();
    if (write_moment_extremes)
      columns.add({{"max_M_1", Quantity::moment},
                   {"max_M_1_x", Quantity::length},
                   {"max_M_1_y", Quantity::length},
                   {"min_M_2", Quantity::moment},
                   {"min_M_2_x", Quantity::length},
                   {"min_M_2_y", Quantity::length},
                   {"max_Q", Quantity::force_per_length},
                   {"max_Q_x", Quantity::length},
                   {"max_Q_y", Quantity::length}},
                  [this](const StepData &step) {
                    return moment_extremes(step);
                  });
    add_moving_load_columns();
    for (const auto &[group, values] : other_columns)
      columns.add(group, values);
    add_joint_columns();
    scales.clear();
    for (const auto &column : columns.columns())
      scales.push_back(units.scale(column.quantity));
  }


  void
  TimeHistory::add_probe_columns()
  {
    const std::vector<std::string> names =
      probe_column_names(std::vector<std::string>(probe_points.size(), "w"),
                         probe_points);
    std::vector<HistoryColumns::Column> group;
    for (const std::string &name : names)
      group.push_back({name, PhysicalUnits::Quantity::deflection});
    columns.add(group, [this](const StepData &step) {
      std::vector<double> w;
      for (const auto &probe : probes)
        w.push_back(probe.local_value(step.state.ghosted_u));
      Utilities::MPI::sum(w, discretization->mpi_communicator, w);
      return w;
    });
  }


  void
  TimeHistory::add_energy_columns()
  {
    using Quantity = PhysicalUnits::Quantity;
    // Each term's energy under its own name, between the kinetic energy
    // and the work: HistoryRow::energies() sums them back.
    std::vector<HistoryColumns::Column> group = {{"kinetic", Quantity::energy}};
    for (const std::string &name : energy_columns)
      group.push_back({name, Quantity::energy});
    group.push_back({"work", Quantity::energy});
    if (write_dissipated)
      group.push_back({"dissipated_energy", Quantity::energy});
    group.push_back({"balance_error", Quantity::energy});
    const bool         dissipated = write_dissipated;
    const unsigned int n_terms    = energy_columns.size();
    columns.add(group, [dissipated, n_terms](const StepData &step) {
      const EnergyBalance &e = step.state.energies;
      std::vector<double>  values{e.kinetic};
      values.insert(values.end(), e.by_term.begin(), e.by_term.end());
      values.resize(1 + n_terms, 0.0);
      values.push_back(e.work);
      if (dissipated)
        values.push_back(e.dissipated);
      values.push_back(e.error(step.state.initial_energies));
      return values;
    });
  }


  void
  TimeHistory::add_joint_columns()
  {
    if (joints.empty())
      return;
    std::vector<HistoryColumns::Column> group;
    for (const auto &[index, name] : joints)
      {
        group.push_back({"shear_" + name, PhysicalUnits::Quantity::force});
        group.push_back({"lte_" + name, PhysicalUnits::Quantity::number});
      }
    columns.add(group, [this](const StepData &step) {
      const auto transfer = step.scene.joints.transfer(step.state.ghosted_u,
                                                       step.state.ghosted_rest);
      std::vector<double> values;
      for (const auto &joint : joints)
        {
          values.push_back(transfer[joint.first].shear_force);
          values.push_back(transfer[joint.first].efficiency);
        }
      return values;
    });
  }


  void
  TimeHistory::add_resultant_columns()
  {
    using Quantity = PhysicalUnits::Quantity;
    columns.add({{"resultant", Quantity::force},
                 {"resultant_x", Quantity::length},
                 {"resultant_y", Quantity::length},
                 {"contact_area", Quantity::area},
                 {"max_pressure", Quantity::pressure},
                 {"max_pressure_x", Quantity::length},
                 {"max_pressure_y", Quantity::length}},
                [this](const StepData &step) {
                  const auto r =
                    step.scene.bed.diagnostics().resultant(step.state.ghosted_u,
                                                           ghosted_velocity);
                  return std::vector<double>{r.force,
                                             r.centre[0],
                                             r.centre[1],
                                             r.contact_area,
                                             r.largest_pressure,
                                             r.largest_pressure_at[0],
                                             r.largest_pressure_at[1]};
                });
  }


  void
  TimeHistory::add_interface_columns()
  {
    using Quantity = PhysicalUnits::Quantity;
    columns.add({{"interface_contact_fraction", Quantity::number},
                 {"interface_resultant", Quantity::force},
                 {"interface_max_pressure", Quantity::pressure}},
                [this](const StepData &step) {
                  const Bed &springs = *step.scene.interface;
                  const auto r =
                    springs.diagnostics().resultant(step.state.ghosted_u,
                                                    ghosted_velocity);
                  return std::vector<double>{
                    springs.diagnostics().contact_area_fraction(),
                    r.force,
                    r.largest_pressure};
                });
  }


  void
  TimeHistory::add_quantity_probe_columns()
  {
    std::vector<std::string> quantities;
    std::vector<Point<2>>    points;
    for (const auto &probe : quantity_probes)
      {
        quantities.push_back(probe.quantity);
        points.push_back(probe.point);
      }
    const std::vector<std::string> names =
      probe_column_names(quantities, points);
    std::vector<HistoryColumns::Column> group;
    for (unsigned int k = 0; k < names.size(); ++k)
      group.push_back({names[k], quantity_of(quantity_probes[k].quantity)});
    columns.add(group, [this](const StepData &step) {
      return values_at(step, quantity_probes);
    });
  }


  void
  TimeHistory::add_moving_load_columns()
  {
    std::vector<HistoryColumns::Column> group;
    for (unsigned int k = 0; k < 3 * moving_load_names.size(); ++k)
      group.push_back(
        {moving_load_names[k / 3] + std::array{"_x", "_y", "_on"}[k % 3],
         k % 3 == 2 ? PhysicalUnits::Quantity::number
                    : PhysicalUnits::Quantity::length});
    columns.add(group, [this](const StepData &step) {
      return moving_load_positions(step.state.clock.tau());
    });
    group.clear();
    for (const RidingProbe &probe : riding_probes)
      group.push_back({probe.name, quantity_of(probe.quantity)});
    columns.add(group, [this](const StepData &step) {
      return riding_probe_values(step);
    });
  }


  std::vector<std::string>
  TimeHistory::column_names() const
  {
    std::vector<std::string> names;
    for (const auto &column : columns.columns())
      names.push_back((column.name == "tau" && units.is_physical()
                         ? std::string("t")
                         : column.name)
                      + units.unit(column.quantity));
    return names;
  }


  void
  TimeHistory::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  void
  TimeHistory::setup(const SceneView &scene, const std::string &directory)
  {
    const Discretization &disc = scene.discretization;
    energy_columns             = scene.energy_columns;
    joints.clear();
    for (unsigned int j = 0; j < disc.geometry().slabs().joints().size(); ++j)
      if (!disc.geometry().slabs().joints()[j].tied)
        joints.emplace_back(j, disc.geometry().slabs().joints()[j].name);
    // Every part has told its columns by now; they are fixed for the run.
    make_columns();
    mesh_changed(scene);
    history.clear();

    // No directory: keep the rows in memory only (tests). The file
    // appears with the first rows.
    file.open(directory.empty() ? "" : directory + "/history.csv",
              rewrite_interval,
              disc.mpi_communicator);
    write_header();
  }


  void
  TimeHistory::mesh_changed(const SceneView &scene)
  {
    const Discretization &disc = scene.discretization;
    discretization             = &disc;
    probes.clear();
    for (const auto &p : probe_points)
      probes.emplace_back(disc, disc.geometry().to_modelled_part(p));
    for (auto &probe : quantity_probes)
      {
        const Point<2> image = disc.geometry().to_modelled_part(probe.point);
        probe.cells          = PointFunctional::holder_cells(disc, image);
        // A point of a mirrored part takes the value at its image, with
        // the sign the reflection gives the field.
        probe.sign = mirror_sign(probe.quantity, probe.point, image);
      }
    w_dofs = DoFTools::extract_dofs(disc.dof_handler, bed_w_mask(disc));
    gap_at_w_dofs.clear();
    if (write_resultant)
      disc.reinit_ghosted_vector(ghosted_velocity);
  }


  void
  TimeHistory::find_gap_at_w_dofs(const StepData &step)
  {
    if (!step.scene.bed.law().has_initial_gap() || !gap_at_w_dofs.empty())
      return;
    const Discretization &disc = step.scene.discretization;
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(disc.mapping(),
                                         disc.dof_handler,
                                         points,
                                         bed_w_mask(disc));
    for (const auto i : w_dofs)
      gap_at_w_dofs.push_back(step.scene.bed.law().gap_at(points.at(i)));
  }


  void
  TimeHistory::write_header()
  {
    std::ostream                  &out   = file.stream();
    const std::vector<std::string> names = column_names();
    for (unsigned int c = 0; c < names.size(); ++c)
      out << (c > 0 ? "," : "") << names[c];
    out << '\n';
  }


  double
  TimeHistory::largest_uplift(const StepData &step) const
  {
    const LA::MPI::Vector &u = step.state.ghosted_u;
    // (g - w)^+ as the uplift field; g = 0 takes the plain path.
    double uplift = 0;
    if (gap_at_w_dofs.empty())
      for (const auto i : w_dofs)
        uplift = std::max(uplift, -u(i));
    else
      {
        unsigned int k = 0;
        for (const auto i : w_dofs)
          uplift = std::max(uplift, gap_at_w_dofs[k++] - u(i));
      }
    return Utilities::MPI::max(uplift, discretization->mpi_communicator);
  }


  std::vector<double>
  TimeHistory::riding_probe_values(const StepData &step) const
  {
    if (riding_probes.empty())
      return {};
    const Discretization     &disc = *discretization;
    const std::vector<double> positions =
      moving_load_positions(step.state.clock.tau());
    std::vector<QuantityProbe> probes;
    for (const RidingProbe &rider : riding_probes)
      {
        QuantityProbe probe{rider.quantity,
                            Point<2>(positions[3 * rider.index],
                                     positions[3 * rider.index + 1]),
                            {}};
        // Every rank decides alike, so holder_cell() (collective) is
        // called by all or none; off the plate the cell stays invalid.
        if (disc.geometry().is_on_plate(probe.point))
          {
            const Point<2> image =
              disc.geometry().to_modelled_part(probe.point);
            probe.cells = PointFunctional::holder_cells(disc, image);
            probe.sign  = mirror_sign(probe.quantity, probe.point, image);
          }
        probes.push_back(probe);
      }
    return values_at(step, probes);
  }


  std::vector<double>
  TimeHistory::values_at(const StepData                   &step,
                         const std::vector<QuantityProbe> &probes) const
  {
    if (probes.empty())
      return {};
    const Discretization  &disc = *discretization;
    const StressResultants resultants(plate,
                                      disc.mapping(),
                                      disc.element().shear_integration(),
                                      step.state.ghosted_u,
                                      step.resultants.free_bending());
    std::vector<double>    values(probes.size(), 0.0);
    for (unsigned int k = 0; k < probes.size(); ++k)
      {
        const QuantityProbe &probe = probes[k];
        if (!probe.cells.empty())
          values[k] = probe.sign
                      * value_at(disc,
                                 resultants,
                                 step.state.ghosted_u,
                                 probe.quantity,
                                 probe.cells);
      }
    Utilities::MPI::sum(values, disc.mpi_communicator, values);
    return values;
  }


  std::vector<double>
  TimeHistory::moment_extremes(const StepData &step) const
  {
    LocatedMaximum largest_m_1, smallest_m_2, largest_q;
    const auto    &points = step.resultants.points();
    const auto    &values = step.resultants.values();
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        largest_m_1.consider(values[k].m_1, points[k]);
        smallest_m_2.consider(-values[k].m_2, points[k]);
        largest_q.consider(values[k].shear, points[k]);
      }
    const MPI_Comm comm = discretization->mpi_communicator;
    largest_m_1         = largest_m_1.over_ranks(comm);
    smallest_m_2        = smallest_m_2.over_ranks(comm);
    largest_q           = largest_q.over_ranks(comm);
    return {largest_m_1.value,
            largest_m_1.point[0],
            largest_m_1.point[1],
            -smallest_m_2.value,
            smallest_m_2.point[0],
            smallest_m_2.point[1],
            largest_q.value,
            largest_q.point[0],
            largest_q.point[1]};
  }


  void
  TimeHistory::execute(const StepData &step)
  {
    find_gap_at_w_dofs(step);
    if (write_resultant && step.scene.bed.law().has_damping())
      ghosted_velocity = step.state.v;
    history.push_back(columns.row_at(step));
    write_row(history.back());
    file.write_if_due();
  }


  namespace
  {
    /// `value` as a stream of precision 12 writes it (printf's %.12g), by
    /// std::to_chars: the stream's formatting took 7 % of the Example 2
    /// pulse's run (20 000 rows).
    void
    put(std::ostream &out, const double value)
    {
      // NaN: not defined at this row (a joint's load transfer with the
      // load far from it), an empty cell.
      if (std::isnan(value))
        return;
      char       text[32];
      const auto end = std::to_chars(std::begin(text),
                                     std::end(text),
                                     value,
                                     std::chars_format::general,
                                     12)
                         .ptr;
      out.write(text, end - text);
    }

  } // namespace


  void
  TimeHistory::write_row(const HistoryRow &row)
  {
    // Integer columns are exact in a double and written alike below 1e12.
    std::ostream              &out    = file.stream();
    const std::vector<double> &values = row.values();
    for (unsigned int c = 0; c < values.size(); ++c)
      {
        if (c > 0)
          out << ',';
        put(out, scales[c] * values[c]);
      }
    out << '\n';
  }


  void
  TimeHistory::flush()
  {
    file.flush();
  }


  void
  TimeHistory::save(OutputArchive &archive) const
  {
    std::vector<std::vector<double>> values;
    for (const HistoryRow &row : history)
      values.push_back(row.values());
    archive << column_names() << values;
  }


  void
  TimeHistory::load(InputArchive &archive)
  {
    // history.csv is a function of the rows: they are written again as
    // they were, and those of steps after the checkpoint are gone once the
    // file is rewritten. A checkpoint of other columns is refused before
    // its rows are read.
    std::vector<std::string> saved;
    archive >> saved;
    AssertThrow(saved == column_names(),
                ExcMessage("The checkpoint's time history has the columns "
                           + joined(saved) + ", this run writes "
                           + joined(column_names())
                           + ": it was written by another version of liftoff "
                             "or for other outputs; resume with that "
                             "version, or start the scene anew."));
    std::vector<std::vector<double>> values;
    archive >> values;
    history.clear();
    for (auto &row : values)
      history.emplace_back(std::move(row), columns.names());
    file.hold();
    for (const HistoryRow &row : history)
      write_row(row);
  }


  void
  TimeHistory::add_to(RunSummary &summary) const
  {
    unsigned int total = 0, n = 0, largest = 0, n_cycled = 0;
    for (const HistoryRow &row : history)
      {
        const auto iterations =
          static_cast<unsigned int>(row["active_set_iterations"]);
        if (iterations == 0)
          continue;
        total += iterations;
        largest = std::max(largest, iterations);
        ++n;
        n_cycled += (row["active_set_cycle"] > 0);
      }
    summary.add("active-set iterations per step, mean",
                n > 0 ? double(total) / n : 0.0);
    summary.add("active-set iterations per step, max", double(largest));
    summary.add("steps whose active set cycled", double(n_cycled));
  }


  const std::vector<HistoryRow> &
  TimeHistory::rows() const
  {
    return history;
  }
} // namespace liftoff
