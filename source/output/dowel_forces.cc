#include <liftoff/base/archives.h>
#include <liftoff/contact/joint_dowels.h>
#include <liftoff/output/dowel_forces.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/time_history.h>
#include <liftoff/time/plate_state.h>

#include <cmath>

namespace liftoff
{
  DowelForces::DowelForces(const JointDowels &dowels)
      : dowels(dowels)
  {}


  void
  DowelForces::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  void
  DowelForces::add_columns_to(TimeHistory &history) const
  {
    std::vector<HistoryColumns::Column> group;
    for (const std::string &name : dowels.names())
      group.push_back({name, PhysicalUnits::Quantity::force});
    history.add_columns(group, [this](const StepData &step) {
      return dowels.forces(step.state.ghosted_u);
    });
  }


  void
  DowelForces::setup(const Discretization &, const std::string &)
  {
    largest      = 0;
    largest_of   = 0;
    largest_time = 0;
  }


  void
  DowelForces::execute(const StepData &step)
  {
    if (dowels.names().empty())
      return;
    const std::vector<double> force = dowels.forces(step.state.ghosted_u);
    for (unsigned int d = 0; d < force.size(); ++d)
      if (std::abs(force[d]) > largest)
        {
          largest      = std::abs(force[d]);
          largest_of   = d;
          largest_time = step.state.clock.tau();
        }
  }


  void
  DowelForces::save(OutputArchive &archive) const
  {
    archive << largest << largest_of << largest_time;
  }


  void
  DowelForces::load(InputArchive &archive)
  {
    archive >> largest >> largest_of >> largest_time;
  }


  void
  DowelForces::add_to(RunSummary &summary) const
  {
    if (dowels.names().empty())
      return;
    using Quantity = PhysicalUnits::Quantity;
    // C is a force per unit deflection.
    const double stiffness_scale =
      units.scale(Quantity::force) / units.scale(Quantity::deflection);
    RunSummary::Section section{
      {"dowels", double(dowels.names().size())},
      {"stiffness C" + (units.is_physical() ? std::string(" [N/m]") : ""),
       dowels.stiffness() * stiffness_scale},
      {"largest force, " + dowels.names()[largest_of]
         + units.unit(Quantity::force),
       largest * units.scale(Quantity::force)},
      {"its time" + units.unit(Quantity::time),
       largest_time * units.scale(Quantity::time)}};
    if (dowels.bar() != nullptr)
      section.emplace_back("largest bearing stress"
                             + units.unit(Quantity::pressure),
                           dowels.bar()->bearing_stress(largest)
                             * units.scale(Quantity::pressure));
    summary.add("dowels", section);
  }
} // namespace liftoff
