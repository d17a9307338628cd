#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/number_text.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mesh_refinement.h>
#include <liftoff/output/fatigue_damage.h>
#include <liftoff/output/point_fields.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/stress_extremes.h>
#include <liftoff/time/plate_state.h>

namespace liftoff
{
  namespace
  {
    const std::string                 damage_section = "Output/Fatigue damage";
    const std::array<const char *, 2> damage_face_names = {{"top", "bottom"}};
  } // namespace


  void
  FatigueDamage::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fatigue damage");
    prm.declare_entry(
      "Enable",
      "false",
      Patterns::Bool(),
      "Count, at every output point of the field files and at each face "
      "(top: away from the bed; bottom: bed-side), the largest principal "
      "stress's cycles by rainflow (ASTM E1049) and sum their damage by "
      "Miner's rule under the Law; write the damage to damage.pvtu "
      "(damage_top, damage_bottom) and the largest, with its point, face "
      "and slab, to the summary. A cycle's damage is count / N(sigma) at "
      "its peak sigma if that is a tension, none otherwise; the residue's "
      "half cycles count at the end. Dynamic runs on a mesh that does not "
      "adapt (costs the face stresses at every output point per step).");
    FatigueLaw::declare_parameters(prm);
    prm.leave_subsection();
  }


  void
  FatigueDamage::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    prm.enter_subsection("Fatigue damage");
    enabled = prm.get_bool("Enable");
    if (enabled)
      law.parse_parameters(prm,
                           damage_section,
                           scene.units.scale(
                             PhysicalUnits::Quantity::pressure));
    else
      FatigueLaw::parsed_expression(prm, damage_section);
    prm.leave_subsection();
  }


  void
  FatigueDamage::check(const SceneView &scene) const
  {
    AssertThrow(!enabled || !scene.mesh_refinement.is_enabled(),
                ExcMessage(damage_section
                           + "/Enable = true keeps a rainflow residue per "
                             "output point of a mesh that does not change: "
                             "it cannot be used with Mesh refinement/Adaptive "
                             "= true. Switch one of them off."));
    AssertThrow(!enabled || scene.dynamic,
                ExcMessage(damage_section
                           + "/Enable = true counts the stress cycles of a "
                             "time integration: a static analysis (Analysis/"
                             "Type = static) has none. Switch it off."));
  }


  void
  FatigueDamage::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  bool
  FatigueDamage::needs_face_stresses() const
  {
    return enabled;
  }


  void
  FatigueDamage::setup(const SceneView &scene, const std::string &folder)
  {
    directory = folder;
    n_slabs   = scene.discretization.geometry().slabs().n_slabs();
    mesh_changed(scene);
  }


  void
  FatigueDamage::mesh_changed(const SceneView &scene)
  {
    discretization = &scene.discretization;
  }


  void
  FatigueDamage::execute(const StepData &step)
  {
    if (!enabled)
      return;
    const auto &values = step.resultants.values();
    if (n_steps_seen == 0)
      {
        points = step.resultants.points();
        slabs.resize(values.size());
        for (unsigned int i = 0; i < values.size(); ++i)
          slabs[i] = values[i].slab;
        for (auto &of_face : counters)
          of_face.assign(values.size(), {});
      }
    // One counter per output point of this mesh: the run refuses a
    // changing mesh with them (check()).
    AssertThrow(values.size() == counters[top].size(), ExcInternalError());
    for (unsigned int i = 0; i < values.size(); ++i)
      for (const Face face : {top, bottom})
        {
          Counter &counter = counters[face][i];
          closed.clear();
          counter.cycles.add(face == top ? values[i].faces.top
                                         : values[i].faces.bottom,
                             closed);
          for (const Rainflow::Cycle &cycle : closed)
            counter.counted += law.damage(cycle);
        }
    ++n_steps_seen;
    last_time = step.state.clock.tau();
  }


  double
  FatigueDamage::damage_of(const Counter &counter) const
  {
    double damage = counter.counted;
    for (const Rainflow::Cycle &cycle : counter.cycles.residue())
      damage += law.damage(cycle);
    return damage;
  }


  std::vector<double>
  FatigueDamage::local_field(const Face face) const
  {
    std::vector<double> field;
    field.reserve(counters[face].size());
    for (const Counter &counter : counters[face])
      field.push_back(damage_of(counter));
    return field;
  }


  void
  FatigueDamage::flush()
  {
    if (!enabled || directory.empty() || n_steps_seen == 0)
      return;
    using Quantity = PhysicalUnits::Quantity;
    write_point_fields(
      directory,
      *discretization,
      {{"damage_top", Quantity::number, local_field(top)},
       {"damage_bottom", Quantity::number, local_field(bottom)}},
      units,
      last_time,
      "damage",
      false);
  }


  void
  FatigueDamage::add_to(RunSummary &summary) const
  {
    // A run that failed before its first step has no damage to report.
    if (!enabled || n_steps_seen == 0)
      return;
    using Quantity = PhysicalUnits::Quantity;
    std::array<StressExtremes::Extreme, 2> faces;
    for (const Face face : {top, bottom})
      {
        std::vector<LocatedMaximum> of_slab(n_slabs);
        const std::vector<double>   damage = local_field(face);
        for (unsigned int i = 0; i < damage.size(); ++i)
          of_slab[slabs[i]].consider(damage[i], points[i]);
        faces[face] =
          StressExtremes::reduce(of_slab, discretization->mpi_communicator);
      }
    const Face larger =
      faces[bottom].where.value >= faces[top].where.value ? bottom : top;
    const double                   length = units.scale(Quantity::length);
    const StressExtremes::Extreme &e      = faces[larger];
    summary.add("fatigue law",
                law.describe(units.unit_symbol(Quantity::pressure)));
    summary.add("largest fatigue damage",
                format_number(e.where.value) + ", " + damage_face_names[larger]
                  + " face, slab " + std::to_string(e.slab + 1) + ", at ("
                  + format_number(length * e.where.point[0]) + ", "
                  + format_number(length * e.where.point[1]) + ")"
                  + (units.is_physical() ? " m" : ""));
    for (const Face face : {top, bottom})
      summary.add(std::string("largest fatigue damage, ")
                    + damage_face_names[face] + " face",
                  RunSummary::Section{{"damage", faces[face].where.value},
                                      {"x" + units.unit(Quantity::length),
                                       length * faces[face].where.point[0]},
                                      {"y" + units.unit(Quantity::length),
                                       length * faces[face].where.point[1]},
                                      {"slab", double(faces[face].slab + 1)}});
  }


  void
  FatigueDamage::save(OutputArchive &archive) const
  {
    archive << n_steps_seen << last_time << slabs << counters[top].size();
    for (const Point<2> &p : points)
      archive << p[0] << p[1];
    for (const auto &of_face : counters)
      for (const Counter &counter : of_face)
        {
          counter.cycles.save(archive);
          archive << counter.counted;
        }
  }


  void
  FatigueDamage::load(InputArchive &archive)
  {
    std::size_t n_points = 0;
    archive >> n_steps_seen >> last_time >> slabs >> n_points;
    points.resize(n_points);
    for (Point<2> &p : points)
      archive >> p[0] >> p[1];
    for (auto &of_face : counters)
      {
        of_face.resize(n_points);
        for (Counter &counter : of_face)
          {
            counter.cycles.load(archive);
            archive >> counter.counted;
          }
      }
  }
} // namespace liftoff
