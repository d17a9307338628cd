#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
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
    const std::string damage_section = "Output/Fatigue damage";

    /// The base's law is an expression only: the MEPDG's law of a
    /// chemically stabilised layer could not be checked against the guide
    /// (doc/model.md, "Fatigue damage").
    const FatigueLaw::Entries base_entries = {"",
                                              "",
                                              "",
                                              "Base modulus of rupture",
                                              "Base expression"};
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
    prm.declare_entry(
      "Base modulus of rupture",
      "0",
      Patterns::Double(),
      "MR_b > 0 counts the base's faces too (a scene with a Base), by the "
      "Base expression (damage_base_top, damage_base_bottom); 0: not "
      "counted. Pa in an SI scene."
        + quantity("pressure"));
    prm.declare_entry(
      "Base expression",
      "",
      Patterns::Anything(),
      "With Base modulus of rupture: the base's law, log10 N as a muParser "
      "expression in sigma (the cycle's peak tension) and MR (the base's), "
      "as (0.972-sigma/MR)/0.0825, the MEPDG's cement-treated base as "
      "usually quoted (not confirmed here: doc/model.md)."
        + quantity("text"));
    prm.leave_subsection();
  }


  void
  FatigueDamage::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    prm.enter_subsection("Fatigue damage");
    enabled            = prm.get_bool("Enable");
    const double scale = scene.units.scale(PhysicalUnits::Quantity::pressure);
    // Base modulus of rupture = 0, its default, is "not given": the scene
    // counts the slab's faces only, as before the base's law existed.
    counts_base = enabled && prm.get_double("Base modulus of rupture") != 0;
    if (enabled)
      law.parse_parameters(prm, damage_section, scale);
    else
      FatigueLaw::parsed_expression(prm, damage_section);
    // Read also where it is not used, so that a typo shows.
    const bool has_base_expression = bool(FatigueLaw::parsed_expression(
      prm, damage_section, base_entries.expression));
    AssertThrow(!enabled || counts_base || !has_base_expression,
                ExcMessage(damage_section
                           + "/Base expression is the base's law: it needs "
                           + damage_section
                           + "/Base modulus of rupture > 0 (the base's faces "
                             "are counted only with it)."));
    if (counts_base)
      {
        AssertThrow(scene.plate.base.present(),
                    ExcMessage(damage_section + "/Base modulus of rupture = "
                               + prm.get("Base modulus of rupture")
                               + " counts a base's faces: the scene has no "
                                 "base (Base/Interface = none). Leave it out "
                                 "or give the scene a base."));
        base_law.parse_parameters(prm, damage_section, scale, base_entries);
      }
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


  unsigned int
  FatigueDamage::n_faces() const
  {
    return counts_base ? 4 : 2;
  }


  const FatigueLaw &
  FatigueDamage::law_of(const Face face) const
  {
    return face < base_top ? law : base_law;
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
        for (unsigned int face = 0; face < n_faces(); ++face)
          counters[face].assign(values.size(), {});
      }
    // One counter per output point of this mesh: the run refuses a
    // changing mesh with them (check()).
    AssertThrow(values.size() == counters[top].size(), ExcInternalError());
    for (unsigned int i = 0; i < values.size(); ++i)
      for (unsigned int face = 0; face < n_faces(); ++face)
        {
          Counter &counter = counters[face][i];
          closed.clear();
          counter.cycles.add(values[i].faces.of(face), closed);
          for (const Rainflow::Cycle &cycle : closed)
            counter.counted += law_of(Face(face)).damage(cycle);
        }
    ++n_steps_seen;
    last_time = step.state.clock.tau();
  }


  double
  FatigueDamage::damage_of(const Face face, const Counter &counter) const
  {
    double damage = counter.counted;
    for (const Rainflow::Cycle &cycle : counter.cycles.residue())
      damage += law_of(face).damage(cycle);
    return damage;
  }


  std::vector<double>
  FatigueDamage::local_field(const Face face) const
  {
    std::vector<double> field;
    field.reserve(counters[face].size());
    for (const Counter &counter : counters[face])
      field.push_back(damage_of(face, counter));
    return field;
  }


  void
  FatigueDamage::flush()
  {
    if (!enabled || directory.empty() || n_steps_seen == 0)
      return;
    std::vector<PointField> fields;
    for (unsigned int face = 0; face < n_faces(); ++face)
      fields.push_back({std::string("damage_") + FaceStresses::name(face),
                        PhysicalUnits::Quantity::number,
                        local_field(Face(face))});
    write_point_fields(
      directory, *discretization, fields, units, last_time, "damage", false);
  }


  StressExtremes::Extreme
  FatigueDamage::largest(const Face face) const
  {
    std::vector<LocatedMaximum> of_slab(n_slabs);
    const std::vector<double>   damage = local_field(face);
    for (unsigned int i = 0; i < damage.size(); ++i)
      of_slab[slabs[i]].consider(damage[i], points[i]);
    return StressExtremes::reduce(of_slab, discretization->mpi_communicator);
  }


  void
  FatigueDamage::add_to(RunSummary &summary) const
  {
    // A run that failed before its first step has no damage to report.
    if (!enabled || n_steps_seen == 0)
      return;
    using Quantity = PhysicalUnits::Quantity;
    std::vector<StressExtremes::Extreme> faces;
    unsigned int                         larger = top;
    for (unsigned int face = 0; face < n_faces(); ++face)
      {
        faces.push_back(largest(Face(face)));
        // A tie goes to the later face, the bed-side one of the slab.
        if (faces[face].where.value >= faces[larger].where.value)
          larger = face;
      }
    const double                   length = units.scale(Quantity::length);
    const StressExtremes::Extreme &e      = faces[larger];
    const std::string pressure = units.unit_symbol(Quantity::pressure);
    summary.add("fatigue law", law.describe(pressure));
    if (counts_base)
      summary.add("base fatigue law", base_law.describe(pressure));
    summary.add("largest fatigue damage",
                format_number(e.where.value) + ", " + FaceStresses::text(larger)
                  + " face, slab " + std::to_string(e.slab + 1) + ", at ("
                  + format_number(length * e.where.point[0]) + ", "
                  + format_number(length * e.where.point[1]) + ")"
                  + (units.is_physical() ? " m" : ""));
    for (unsigned int face = 0; face < n_faces(); ++face)
      summary.add("largest fatigue damage, " + FaceStresses::text(face)
                    + " face",
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
    // Only the faces counted: a scene without the base's law writes the
    // checkpoint of a run before the base's faces could be counted.
    for (unsigned int face = 0; face < n_faces(); ++face)
      for (const Counter &counter : counters[face])
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
    for (unsigned int face = 0; face < n_faces(); ++face)
      {
        counters[face].resize(n_points);
        for (Counter &counter : counters[face])
          {
            counter.cycles.load(archive);
            archive >> counter.counted;
          }
      }
  }
} // namespace liftoff
