#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/numerics/data_out.h>

#include <liftoff/base/archives.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mesh_refinement.h>
#include <liftoff/output/envelopes.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/vtu_pieces.h>
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

    const std::array<Kind, 7> kinds = {
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
        Quantity::pressure}}};
  } // namespace


  void
  Envelopes::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Write envelopes",
      "false",
      Patterns::Bool(),
      "Keep, at every output point of the field files, the largest and "
      "smallest w, the largest bed pressure, the largest M_1, the "
      "smallest M_2 and the largest principal stress at the top face "
      "(sigma_1_top_max) and at the bed-side face (sigma_1_bottom_max) "
      "over all steps with the time of each, and write them "
      "to envelope.pvtu at the end (and at each checkpoint) and their "
      "extremes over the plate to the summary (costs a pass over the "
      "output points per step). Not with adaptive refinement.");
  }


  void
  Envelopes::parse_parameters(ParameterHandler &prm, const SceneView &)
  {
    enabled = prm.get_bool("Write envelopes");
    envelopes.clear();
    for (const Kind &kind : kinds)
      envelopes.push_back({kind.name, {}, {}});
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
    for (unsigned int e = 0; e < kinds.size(); ++e)
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
    const Discretization &disc = *discretization;
    const FE_DGQ<2>       element(disc.element().degree());
    DoFHandler<2>         point_dofs(disc.triangulation);
    point_dofs.distribute_dofs(element);
    // The order of ResultantSweep::points(): this rank's cells, and in each
    // the support points of FE_DGQ(p), which are the output points.
    std::vector<LA::MPI::Vector> fields(2 * kinds.size());
    for (auto &field : fields)
      field.reinit(point_dofs.locally_owned_dofs(), disc.mpi_communicator);
    std::vector<types::global_dof_index> indices(element.n_dofs_per_cell());
    unsigned int                         i = 0;
    for (const auto &owned : disc.locally_owned_cells())
      {
        const DoFHandler<2>::active_cell_iterator cell(&disc.triangulation,
                                                       owned->level(),
                                                       owned->index(),
                                                       &point_dofs);
        cell->get_dof_indices(indices);
        for (const auto index : indices)
          {
            for (unsigned int e = 0; e < kinds.size(); ++e)
              {
                fields[2 * e][index] = kinds[e].sign * envelopes[e].extreme[i];
                fields[2 * e + 1][index] = envelopes[e].time[i];
              }
            ++i;
          }
      }
    FieldDataOut                                   data_out;
    std::map<std::string, PhysicalUnits::Quantity> quantities;
    data_out.attach_dof_handler(point_dofs);
    for (unsigned int e = 0; e < kinds.size(); ++e)
      {
        fields[2 * e].compress(VectorOperation::insert);
        fields[2 * e + 1].compress(VectorOperation::insert);
        const std::string name = kinds[e].name;
        data_out.add_data_vector(fields[2 * e], name);
        data_out.add_data_vector(fields[2 * e + 1], name + "_time");
        quantities[name]           = kinds[e].quantity;
        quantities[name + "_time"] = PhysicalUnits::Quantity::time;
      }
    data_out.build_patches(disc.mapping(), element.degree);
    const double time = units.scale(PhysicalUnits::Quantity::time) * last_time;
    DataOutBase::VtkFlags flags;
    flags.time              = time;
    flags.physical_units    = data_out.put_in_units_of(units, quantities);
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    write_vtu_pieces(
      directory, data_out, disc.mpi_communicator, time, "envelope", true);
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
    for (unsigned int e = 0; e < kinds.size(); ++e)
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
      if (name == kinds[e].name)
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
    for (unsigned int e = 0; e < kinds.size(); ++e)
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
