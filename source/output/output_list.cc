#include <liftoff/output/deflectometer_sensors.h>
#include <liftoff/output/dowel_forces.h>
#include <liftoff/output/envelopes.h>
#include <liftoff/output/fatigue_damage.h>
#include <liftoff/output/field_output.h>
#include <liftoff/output/joint_probes.h>
#include <liftoff/output/joint_profiles.h>
#include <liftoff/output/output_list.h>
#include <liftoff/output/profile_output.h>
#include <liftoff/output/progress_line.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/small_deflection_check.h>
#include <liftoff/output/stress_extremes.h>

#include <functional>
#include <iostream>

namespace liftoff
{
  namespace
  {
    // A kind of output: its entries and how to make one.
    struct OutputKind
    {
      void (*declare_parameters)(ParameterHandler &);
      std::function<std::unique_ptr<Output>()> make;
    };

    template <class T>
    OutputKind
    kind()
    {
      return {&T::declare_parameters, []() { return std::make_unique<T>(); }};
    }

    // Every output, in the order it is written after each step. The time
    // history comes first: the others add their columns to it.
    const std::vector<OutputKind> &
    output_kinds()
    {
      static const std::vector<OutputKind> kinds = {
        kind<TimeHistory>(),
        kind<ProfileOutput>(),
        kind<JointProfiles>(),
        kind<FieldOutput>(),
        kind<Envelopes>(),
        kind<StressExtremes>(),
        kind<FatigueDamage>(),
        kind<DeflectometerSensors>(),
        kind<DowelForces>(),
        kind<JointProbes>(),
        kind<SmallDeflectionCheck>(),
      };
      return kinds;
    }
  } // namespace


  OutputList::OutputList(const MPI_Comm comm, const bool show_progress)
  {
    for (const OutputKind &kind : output_kinds())
      outputs.push_back(kind.make());
    if (show_progress)
      outputs.push_back(std::make_unique<ProgressLine>(comm, std::cout));
  }


  void
  OutputList::declare_parameters(ParameterHandler &prm)
  {
    for (const OutputKind &kind : output_kinds())
      kind.declare_parameters(prm);
  }


  void
  OutputList::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    prm.enter_subsection("Output");
    for (const auto &output : outputs)
      output->parse_parameters(prm, scene);
    prm.leave_subsection();
    for (const auto &output : outputs)
      output->write_in_units_of(scene.units);
    for (const auto &output : outputs)
      output->add_columns_to(history());
  }


  bool
  OutputList::needs_face_stresses() const
  {
    for (const auto &output : outputs)
      if (output->needs_face_stresses())
        return true;
    return false;
  }


  void
  OutputList::check(const SceneView &scene) const
  {
    for (const auto &output : outputs)
      output->check(scene);
  }


  void
  OutputList::setup(const SceneView &scene, const std::string &directory)
  {
    for (const auto &output : outputs)
      output->setup(scene, directory);
  }


  void
  OutputList::mesh_changed(const SceneView &scene)
  {
    for (const auto &output : outputs)
      output->mesh_changed(scene);
  }


  void
  OutputList::execute(const StepData &step)
  {
    for (const auto &output : outputs)
      output->execute(step);
  }


  void
  OutputList::flush(const bool keep_first_error)
  {
    for (const auto &output : outputs)
      try
        {
          output->flush();
        }
      catch (...)
        {
          if (!keep_first_error)
            throw;
        }
  }


  void
  OutputList::add_to(RunSummary &summary) const
  {
    for (const auto &output : outputs)
      output->add_to(summary);
  }


  std::string
  OutputList::warnings() const
  {
    std::string text;
    for (const auto &output : outputs)
      if (const std::string w = output->warning(); !w.empty())
        text += (text.empty() ? "" : " ") + w;
    return text;
  }


  void
  OutputList::save(OutputArchive &archive) const
  {
    for (const auto &output : outputs)
      output->save(archive);
  }


  void
  OutputList::load(InputArchive &archive)
  {
    for (const auto &output : outputs)
      output->load(archive);
  }


  TimeHistory &
  OutputList::history()
  {
    return static_cast<TimeHistory &>(*outputs.front());
  }


  const TimeHistory &
  OutputList::history() const
  {
    return static_cast<const TimeHistory &>(*outputs.front());
  }
} // namespace liftoff
