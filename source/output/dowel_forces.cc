#include <liftoff/base/archives.h>
#include <liftoff/contact/joint_dowels.h>
#include <liftoff/output/dowel_forces.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/time_history.h>
#include <liftoff/time/plate_state.h>

#include <deal.II/base/data_out_base.h>

#include <liftoff/output/vtu_pieces.h>

#include <cmath>

namespace liftoff
{
  namespace
  {
    /// Points with their data, as DataOutBase writes them.
    class PointPatches : public DataOutInterface<0, 2>
    {
    public:
      std::vector<DataOutBase::Patch<0, 2>> patches;
      std::vector<std::string>              names;

    private:
      const std::vector<DataOutBase::Patch<0, 2>> &
      get_patches() const override
      {
        return patches;
      }
      std::vector<std::string>
      get_dataset_names() const override
      {
        return names;
      }
    };
  } // namespace


  void
  write_dowel_points(const std::string     &directory,
                     const JointDowels     &dowels,
                     const LA::MPI::Vector &ghosted_u,
                     const PhysicalUnits   &units,
                     const MPI_Comm         comm,
                     const double           time,
                     const std::string     &stem)
  {
    using Quantity                  = PhysicalUnits::Quantity;
    const std::vector<double> force = dowels.forces(ghosted_u);
    const DowelBar           *bar   = dowels.bar();
    PointPatches              points;
    points.names = {"force"};
    if (bar != nullptr)
      points.names.emplace_back("bearing_stress");
    std::map<std::string, std::string> symbols = {
      {"force", units.unit_symbol(Quantity::force)},
      {"bearing_stress", units.unit_symbol(Quantity::pressure)}};
    for (unsigned int d = 0;
         d < force.size() && Utilities::MPI::this_mpi_process(comm) == 0;
         ++d)
      {
        DataOutBase::Patch<0, 2> patch;
        patch.vertices[0] =
          dowels.sites()[d].location * units.scale(Quantity::length);
        patch.patch_index = d;
        patch.data.reinit(points.names.size(), 1);
        patch.data(0, 0) = force[d] * units.scale(Quantity::force);
        if (bar != nullptr)
          patch.data(1, 0) = bar->bearing_stress(std::abs(force[d]))
                             * units.scale(Quantity::pressure);
        points.patches.push_back(patch);
      }
    DataOutBase::VtkFlags flags;
    flags.time           = time;
    flags.physical_units = symbols;
    points.set_flags(flags);
    write_points_file(directory, points, comm, time, stem + ".vtu");
  }


  void
  DowelForces::parse_parameters(ParameterHandler &, const SceneView &scene)
  {
    dowels = &scene.dowels;
  }


  void
  DowelForces::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  void
  DowelForces::add_columns_to(TimeHistory &history) const
  {
    std::vector<HistoryColumns::Column> group;
    for (const DowelSite &site : dowels->sites())
      group.push_back({site.name, PhysicalUnits::Quantity::force});
    history.add_columns(group, [this](const StepData &step) {
      return dowels->forces(step.state.ghosted_u);
    });
  }


  void
  DowelForces::setup(const SceneView &, const std::string &)
  {
    largest      = 0;
    largest_of   = 0;
    largest_time = 0;
  }


  void
  DowelForces::execute(const StepData &step)
  {
    if (dowels->sites().empty())
      return;
    const std::vector<double> force = dowels->forces(step.state.ghosted_u);
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
    if (dowels->sites().empty())
      return;
    using Quantity = PhysicalUnits::Quantity;
    // C is a force per unit deflection.
    const double stiffness_scale =
      units.scale(Quantity::force) / units.scale(Quantity::deflection);
    RunSummary::Section section{
      {"dowels", double(dowels->sites().size())},
      {"stiffness C" + (units.is_physical() ? std::string(" [N/m]") : ""),
       dowels->stiffness() * stiffness_scale},
      {"largest force, " + dowels->sites()[largest_of].name
         + units.unit(Quantity::force),
       largest * units.scale(Quantity::force)},
      {"its time" + units.unit(Quantity::time),
       largest_time * units.scale(Quantity::time)}};
    if (dowels->bar() != nullptr)
      section.emplace_back("largest bearing stress"
                             + units.unit(Quantity::pressure),
                           dowels->bar()->bearing_stress(largest)
                             * units.scale(Quantity::pressure));
    summary.add("dowels", section);
  }
} // namespace liftoff
