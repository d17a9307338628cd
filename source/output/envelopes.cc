#include <liftoff/base/archives.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mesh_refinement.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/output/envelopes.h>
#include <liftoff/output/point_fields.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/time/plate_state.h>

#include <array>

namespace liftoff
{
  namespace
  {
    /// An envelope's quantity: its name in the files, the sign that makes
    /// its extreme a largest value (-1 for a smallest one), the value at a
    /// point and what it is, for its unit (doc/model.md).
    struct Kind
    {
      const char *name;
      double      sign;
      double (*value)(const ResultantSweep::Values &);
      PhysicalUnits::Quantity quantity;
    };

    using Values   = ResultantSweep::Values;
    using Quantity = PhysicalUnits::Quantity;

    // The face stresses' are the last four, the base's last of all.
    const std::array<Kind, 9> kinds = {
      {{"w_max", 1, [](const Values &v) { return v.w; }, Quantity::deflection},
       {"w_min", -1, [](const Values &v) { return v.w; }, Quantity::deflection},
       {"foundation_pressure_max",
        1,
        [](const Values &v) { return v.pressure; },
        Quantity::pressure},
       {"M_1_max", 1, [](const Values &v) { return v.m_1; }, Quantity::moment},
       {"M_2_min", -1, [](const Values &v) { return v.m_2; }, Quantity::moment},
       {"sigma_1_top_max",
        1,
        [](const Values &v) { return v.faces.top; },
        Quantity::pressure},
       {"sigma_1_bottom_max",
        1,
        [](const Values &v) { return v.faces.bottom; },
        Quantity::pressure},
       {"sigma_1_base_top_max",
        1,
        [](const Values &v) { return v.faces.base_top; },
        Quantity::pressure},
       {"sigma_1_base_bottom_max",
        1,
        [](const Values &v) { return v.faces.base_bottom; },
        Quantity::pressure}}};
    constexpr unsigned int n_kinds_without_faces = 5;
  } // namespace


  void
  Envelopes::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Write envelopes",
      "false",
      Patterns::Bool(),
      "Keep, at every output point of the field files, the largest and "
      "smallest w, the largest bed pressure, the largest M_1 and the "
      "smallest M_2 over all steps with the time of each, and write them "
      "to envelope.pvtu at the end (and at each checkpoint) and their "
      "extremes over the plate to the summary (costs a pass over the "
      "output points per step). Not with adaptive refinement.");
    prm.declare_entry(
      "Write stress envelopes",
      "false",
      Patterns::Bool(),
      "With Write envelopes, also the largest principal stress at the top "
      "face (sigma_1_top_max) and at the bed-side face (sigma_1_bottom_max), "
      "and with a base at its faces (sigma_1_base_top_max, "
      "sigma_1_base_bottom_max), at every output point, with their times "
      "(costs the face stresses at every output point per step).");
  }


  void
  Envelopes::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    enabled           = prm.get_bool("Write envelopes");
    const bool stress = prm.get_bool("Write stress envelopes");
    AssertThrow(enabled || !stress,
                ExcMessage("Output/Write stress envelopes = true adds the face "
                           "stresses to the envelopes: it needs Output/Write "
                           "envelopes = true."));
    const unsigned int n_kinds =
      n_kinds_without_faces
      + (stress ? FaceStresses::count(scene.plate.base.present()) : 0);
    envelopes.clear();
    for (unsigned int e = 0; e < n_kinds; ++e)
      envelopes.push_back({kinds[e].name, {}, {}});
  }


  bool
  Envelopes::needs_face_stresses() const
  {
    return enabled && envelopes.size() > n_kinds_without_faces;
  }


  void
  Envelopes::check(const SceneView &scene) const
  {
    AssertThrow(!enabled || !scene.mesh_refinement.is_enabled(),
                ExcMessage("Output/Write envelopes = true keeps one value per "
                           "output point of a mesh that does not change: it "
                           "cannot be used with Mesh refinement/Adaptive "
                           "(not yet implemented). Switch one of them off."));
  }


  void
  Envelopes::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  void
  Envelopes::setup(const SceneView &scene, const std::string &folder)
  {
    directory = folder;
    mesh_changed(scene);
  }


  void
  Envelopes::mesh_changed(const SceneView &scene)
  {
    const Discretization &disc = scene.discretization;
    discretization             = &disc;
  }


  void
  Envelopes::execute(const StepData &step)
  {
    if (!enabled)
      return;
    const auto &values = step.resultants.values();
    const bool  first  = (n_steps_seen == 0);
    points             = step.resultants.points();
    for (unsigned int e = 0; e < envelopes.size(); ++e)
      {
        Envelope &envelope = envelopes[e];
        if (first)
          {
            envelope.extreme.assign(values.size(), 0.0);
            envelope.time.assign(values.size(), step.state.clock.tau());
          }
        const double sign  = kinds[e].sign;
        const auto   value = kinds[e].value;
        for (unsigned int i = 0; i < values.size(); ++i)
          {
            const double v = sign * value(values[i]);
            if (first || v > envelope.extreme[i])
              {
                envelope.extreme[i] = v;
                envelope.time[i]    = step.state.clock.tau();
              }
          }
      }
    // The envelopes hold one value per output point of this mesh: the run
    // refuses a changing mesh with them (SceneParts).
    AssertThrow(points.size() == envelopes[0].extreme.size(),
                ExcInternalError());
    ++n_steps_seen;
    last_time = step.state.clock.tau();
  }


  void
  Envelopes::write() const
  {
    std::vector<PointField> fields;
    for (unsigned int e = 0; e < envelopes.size(); ++e)
      {
        std::vector<double> extreme = envelopes[e].extreme;
        for (double &value : extreme)
          value *= kinds[e].sign;
        fields.push_back({kinds[e].name, kinds[e].quantity, extreme});
        fields.push_back({std::string(kinds[e].name) + "_time",
                          Quantity::time,
                          envelopes[e].time});
      }
    write_point_fields(
      directory, *discretization, fields, units, last_time, "envelope", true);
  }


  void
  Envelopes::flush()
  {
    if (enabled && !directory.empty() && n_steps_seen > 0)
      write();
  }


  std::vector<std::string>
  Envelopes::names()
  {
    std::vector<std::string> all;
    for (const Kind &kind : kinds)
      all.emplace_back(kind.name);
    return all;
  }


  std::vector<LocatedMaximum>
  Envelopes::extremes() const
  {
    std::vector<LocatedMaximum> all;
    for (unsigned int e = 0; e < envelopes.size(); ++e)
      {
        LocatedMaximum extreme;
        for (unsigned int i = 0; i < points.size(); ++i)
          extreme.consider(envelopes[e].extreme[i],
                           points[i],
                           envelopes[e].time[i]);
        extreme = extreme.over_ranks(discretization->mpi_communicator);
        extreme.value *= kinds[e].sign;
        all.push_back(extreme);
      }
    return all;
  }


  std::vector<double>
  Envelopes::local_field(const std::string &name) const
  {
    for (unsigned int e = 0; e < kinds.size(); ++e)
      if (e >= envelopes.size())
        {
          // A face stress envelope without Write stress envelopes.
          if (name.rfind(kinds[e].name, 0) == 0)
            return {};
        }
      else if (name == kinds[e].name)
        {
          std::vector<double> values = envelopes[e].extreme;
          for (double &value : values)
            value *= kinds[e].sign;
          return values;
        }
      else if (name == std::string(kinds[e].name) + "_time")
        return envelopes[e].time;
    AssertThrow(false, ExcMessage("No envelope is named " + name + "."));
    return {};
  }


  void
  Envelopes::add_to(RunSummary &summary) const
  {
    if (!enabled)
      return;
    RunSummary::Section               section;
    const std::vector<LocatedMaximum> all = extremes();
    for (unsigned int e = 0; e < envelopes.size(); ++e)
      {
        const std::string name   = kinds[e].name;
        const double      length = units.scale(Quantity::length);
        section.emplace_back(name + units.unit(kinds[e].quantity),
                             units.scale(kinds[e].quantity) * all[e].value);
        section.emplace_back(name + " x" + units.unit(Quantity::length),
                             length * all[e].point[0]);
        section.emplace_back(name + " y" + units.unit(Quantity::length),
                             length * all[e].point[1]);
        section.emplace_back(name + " time" + units.unit(Quantity::time),
                             units.scale(Quantity::time) * all[e].time);
      }
    summary.add("envelope extremes (points of the meshed part)", section);
  }


  void
  Envelopes::save(OutputArchive &archive) const
  {
    archive << n_steps_seen << last_time;
    for (const Envelope &envelope : envelopes)
      archive << envelope.name << envelope.extreme << envelope.time;
  }


  void
  Envelopes::load(InputArchive &archive)
  {
    archive >> n_steps_seen >> last_time;
    for (Envelope &envelope : envelopes)
      {
        std::string name;
        archive >> name >> envelope.extreme >> envelope.time;
        AssertThrow(name == envelope.name,
                    ExcMessage("The checkpoint's envelopes hold " + name
                               + " where this liftoff keeps " + envelope.name
                               + ": resume with the liftoff that wrote it."));
      }
  }
} // namespace liftoff
