#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/stress_extremes.h>
#include <liftoff/output/time_history.h>
#include <liftoff/time/plate_state.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace liftoff
{
  namespace
  {
    /// A number with 3 significant digits and no exponent between 1e-3
    /// and 1e6, for the summary's line: 1.19, 1509, 0.004.
    std::string
    short_number(const double x)
    {
      std::ostringstream text;
      const double       size = std::abs(x);
      if (size < 1e-3 || size >= 1e6)
        {
          text << std::setprecision(3) << x;
          return text.str();
        }
      const int decimals = std::max(0, 2 - int(std::floor(std::log10(size))));
      text << std::fixed << std::setprecision(decimals) << x;
      std::string digits = text.str();
      if (decimals > 0)
        digits.erase(digits.find_last_not_of('0') + 1);
      if (digits.back() == '.')
        digits.pop_back();
      return digits;
    }
  } // namespace


  void
  StressExtremes::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Write stress extremes",
      "false",
      Patterns::Bool(),
      "Write to the summary (and summary.json) the largest principal "
      "stress of the run at each face, the face away from the bed (top: "
      "top-down cracking) and the bed-side face (bottom: bottom-up), with "
      "its point (of the meshed part), slab and time, in MPa in an SI "
      "scene (F0/L^2 in a dimensionless one); each slab's stress with its "
      "own thickness and with a temperature profile's stress of the face "
      "(costs a pass over the output points of the field files per step). "
      "On by default in an SI scene: the design quantity of a pavement."
        + si_default("true"));
    prm.declare_entry(
      "Write stress history",
      "false",
      Patterns::Bool(),
      "Write the step's largest principal stress of each face to "
      "history.csv: `max_sigma_1_top` and `max_sigma_1_bottom` (Pa in an "
      "SI scene), each with its point `_x`, `_y` (of the meshed part) and "
      "`_slab` (1, 2, ...).");
  }


  void
  StressExtremes::parse_parameters(ParameterHandler &prm,
                                   const SceneView  &scene)
  {
    writes_summary = prm.get_bool("Write stress extremes");
    writes_history = prm.get_bool("Write stress history");
    n_faces        = FaceStresses::count(scene.plate.base.present());
    run_maxima.assign(n_faces, {});
  }


  void
  StressExtremes::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  bool
  StressExtremes::needs_face_stresses() const
  {
    return writes_summary || writes_history;
  }


  void
  StressExtremes::add_columns_to(TimeHistory &history) const
  {
    if (!writes_history)
      return;
    using Quantity = PhysicalUnits::Quantity;
    std::vector<HistoryColumns::Column> group;
    for (unsigned int face = 0; face < n_faces; ++face)
      {
        const std::string name =
          std::string("max_sigma_1_") + FaceStresses::name(face);
        group.push_back({name, Quantity::pressure});
        group.push_back({name + "_x", Quantity::length});
        group.push_back({name + "_y", Quantity::length});
        group.push_back({name + "_slab", Quantity::number});
      }
    history.add_columns(group, [faces = n_faces](const StepData &step) {
      const unsigned int n_slabs =
        step.scene.discretization.geometry().slabs().n_slabs();
      Maxima step_maxima(faces, std::vector<LocatedMaximum>(n_slabs));
      consider_step(step, step_maxima);
      std::vector<double> values;
      for (const auto &of_slab : step_maxima)
        {
          const Extreme e =
            reduce(of_slab, step.scene.discretization.mpi_communicator);
          values.insert(values.end(),
                        {e.where.value,
                         e.where.point[0],
                         e.where.point[1],
                         double(e.slab + 1)});
        }
      return values;
    });
  }


  void
  StressExtremes::setup(const SceneView &scene, const std::string &)
  {
    comm       = scene.discretization.mpi_communicator;
    is_dynamic = scene.dynamic;
    for (auto &of_slab : run_maxima)
      of_slab.assign(scene.discretization.geometry().slabs().n_slabs(), {});
  }


  void
  StressExtremes::consider_step(const StepData &step, Maxima &maxima)
  {
    const auto  &points = step.resultants.points();
    const auto  &values = step.resultants.values();
    const double tau    = step.state.clock.tau();
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const ResultantSweep::Values &v = values[k];
        for (unsigned int face = 0; face < maxima.size(); ++face)
          {
            AssertIndexRange(v.slab, maxima[face].size());
            maxima[face][v.slab].consider(v.faces.of(face), points[k], tau);
          }
      }
  }


  void
  StressExtremes::execute(const StepData &step)
  {
    if (writes_summary)
      consider_step(step, run_maxima);
  }


  StressExtremes::Extreme
  StressExtremes::reduce(const std::vector<LocatedMaximum> &of_slab,
                         const MPI_Comm                     comm)
  {
    Extreme largest;
    for (unsigned int s = 0; s < of_slab.size(); ++s)
      {
        const LocatedMaximum m = of_slab[s].over_ranks(comm);
        if (!m.found)
          continue;
        LocatedMaximum trial = largest.where;
        trial.consider(m.value, m.point, m.time);
        if (!largest.where.found || trial.value != largest.where.value
            || trial.point != largest.where.point
            || trial.time != largest.where.time)
          largest = {trial, s};
      }
    return largest;
  }


  StressExtremes::Extreme
  StressExtremes::largest(const unsigned int face) const
  {
    return reduce(run_maxima[face], comm);
  }


  void
  StressExtremes::add_to(RunSummary &summary) const
  {
    if (!writes_summary)
      return;
    using Quantity = PhysicalUnits::Quantity;
    // MPa in an SI scene: the unit pavement design reads.
    const bool   si           = units.is_physical();
    const double stress_scale = si ? 1e-6 * units.scale(Quantity::pressure) : 1;
    const std::string stress_unit =
      si ? "MPa" : units.unit_symbol(Quantity::pressure);
    const double         length = units.scale(Quantity::length);
    const double         time   = units.scale(Quantity::time);
    std::vector<Extreme> faces;
    // Of equal values, the later face (the bottom before the top), as the
    // slab alone has always chosen.
    unsigned int larger = 0;
    for (unsigned int face = 0; face < n_faces; ++face)
      {
        faces.push_back(largest(face));
        if (faces[face].where.value >= faces[larger].where.value)
          larger = face;
      }
    const Extreme &e    = faces[larger];
    std::string    line = short_number(stress_scale * e.where.value) + " "
                       + stress_unit + ", " + FaceStresses::text(larger)
                       + " face, slab " + std::to_string(e.slab + 1) + ", at ("
                       + short_number(length * e.where.point[0]) + ", "
                       + short_number(length * e.where.point[1]) + ")";
    if (si)
      line += " m";
    if (is_dynamic)
      line += ", t = " + short_number(time * e.where.time) + (si ? " s" : "");
    summary.add("largest tension", line);
    for (unsigned int face = 0; face < n_faces; ++face)
      {
        const Extreme &f = faces[face];
        summary.add(
          "largest tension, " + FaceStresses::text(face) + " face",
          RunSummary::Section{
            {"sigma_1" + (si ? std::string(" [MPa]") : std::string()),
             stress_scale * f.where.value},
            {"x" + units.unit(Quantity::length), length * f.where.point[0]},
            {"y" + units.unit(Quantity::length), length * f.where.point[1]},
            {"slab", double(f.slab + 1)},
            {"time" + units.unit(Quantity::time), time * f.where.time}});
      }
  }


  void
  StressExtremes::save(OutputArchive &archive) const
  {
    for (const auto &of_slab : run_maxima)
      {
        archive << of_slab.size();
        for (const LocatedMaximum &m : of_slab)
          archive << m.found << m.value << m.point[0] << m.point[1] << m.time;
      }
  }


  void
  StressExtremes::load(InputArchive &archive)
  {
    for (auto &of_slab : run_maxima)
      {
        std::size_t n_slabs = 0;
        archive >> n_slabs;
        AssertThrow(n_slabs == of_slab.size(),
                    ExcMessage("The checkpoint's stress extremes are of "
                               + std::to_string(n_slabs)
                               + " slabs, this scene has "
                               + std::to_string(of_slab.size()) + "."));
        for (LocatedMaximum &m : of_slab)
          archive >> m.found >> m.value >> m.point[0] >> m.point[1] >> m.time;
      }
  }
} // namespace liftoff
