#include <deal.II/base/mpi.h>

#include <liftoff/base/archives.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/joint_springs.h>
#include <liftoff/fem/plate_geometry.h>
#include <liftoff/output/joint_profiles.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/time/plate_state.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace liftoff
{
  void
  JointProfiles::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Joint profiles",
      "false",
      Patterns::Bool(),
      "Write joints.csv at the Profile times (once in a static analysis): "
      "along each joint that is not tied, at the Gauss points its springs "
      "are integrated at, the distance s along it from its lower end (on "
      "the rectangle the plate's edge), w of the lower (left, bottom) and the "
      "upper "
      "slab, the load transfer of the load's part (the smaller change of w "
      "since the plate at rest over the larger: since tau = 0 in a time "
      "integration, since the equilibrium under the weight and the "
      "temperature loads alone in a static analysis; empty where the "
      "larger moves by less than a tenth of the plate's largest change, "
      "the load being far) and the shear force per length the aggregate "
      "interlock passes from the lower slab to the upper one.");
  }


  void
  JointProfiles::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    const PlateGeometry &geometry = scene.discretization.geometry();
    is_on                         = prm.get_bool("Joint profiles");
    times.parse(prm.get("Profile times"));
    if (!is_on)
      return;
    const auto &joints = geometry.slabs().joints();
    AssertThrow(std::any_of(joints.begin(),
                            joints.end(),
                            [](const Joint &j) { return !j.tied; }),
                ExcMessage("Output/Joint profiles = true: the modelled plate "
                           "has no joint that is not tied (Slabs)."));
  }


  void
  JointProfiles::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  void
  JointProfiles::setup(const SceneView &scene, const std::string &directory)
  {
    const Discretization &disc = scene.discretization;
    times.reset();
    discretization = &disc;
    if (!is_on)
      return;
    file.open(directory.empty() ? "" : directory + "/joints.csv",
              rewrite_interval,
              disc.mpi_communicator);
    using Quantity       = PhysicalUnits::Quantity;
    const auto    length = units.unit(Quantity::length);
    const auto    w      = units.unit(Quantity::deflection);
    std::ostream &out    = file.stream();
    out << (units.is_physical() ? "t" : "tau") << units.unit(Quantity::time)
        << ",joint,s" << length << ",x" << length << ",y" << length
        << ",w_lower" << w << ",w_upper" << w << ",lte,shear"
        << units.unit(Quantity::force_per_length) << '\n';
  }


  void
  JointProfiles::mesh_changed(const SceneView &scene)
  {
    const Discretization &disc = scene.discretization;
    discretization             = &disc;
  }


  // A row per joint point. The shear + 0.0: a free joint's -0 (0 times a
  // negative jump) is written as 0. An lte far from the load is NaN,
  // written empty.
  void
  JointProfiles::execute(const StepData &step)
  {
    const double tau = step.state.clock.tau();
    if (!is_on || !times.is_due(tau, step.state.clock.time_step()))
      return;
    // Rank 0 writes every rank's points: joint, x, y, w_lower, w_upper,
    // lte, shear.
    std::vector<double> mine;
    for (const auto &p :
         step.scene.joints.points_along(step.state.ghosted_u,
                                        step.state.ghosted_rest))
      mine.insert(mine.end(),
                  {double(p.joint),
                   p.x[0],
                   p.x[1],
                   p.w_lower,
                   p.w_upper,
                   p.lte,
                   p.shear});
    const MPI_Comm comm = discretization->mpi_communicator;
    // Empty on the other ranks, whose stream discards what they write.
    const auto all = Utilities::MPI::gather(comm, mine, 0);

    const auto &joints = discretization->geometry().slabs().joints();
    std::vector<std::array<double, 8>> rows;
    for (const auto &rank : all)
      for (std::size_t k = 0; k + 6 < rank.size(); k += 7)
        {
          const unsigned int j    = rank[k];
          const unsigned int axis = 1 - joints[j].normal_axis;
          rows.push_back({{rank[k],
                           rank[k + 1 + axis] - joints[j].start,
                           rank[k + 1],
                           rank[k + 2],
                           rank[k + 3],
                           rank[k + 4],
                           rank[k + 5],
                           rank[k + 6]}});
        }
    std::sort(rows.begin(), rows.end());

    using Quantity       = PhysicalUnits::Quantity;
    const double  length = units.scale(Quantity::length);
    const double  w      = units.scale(Quantity::deflection);
    const double  shear  = units.scale(Quantity::force_per_length);
    std::ostream &out    = file.stream();
    out << std::setprecision(12);
    for (const auto &r : rows)
      {
        out << units.scale(Quantity::time) * tau << ','
            << joints[static_cast<unsigned int>(r[0])].name << ','
            << length * r[1] << ',' << length * r[2] << ',' << length * r[3]
            << ',' << w * r[4] << ',' << w * r[5] << ',';
        if (!std::isnan(r[6]))
          out << r[6];
        out << ',' << (shear * r[7] + 0.0) << '\n';
      }
    file.flush();
  }


  void
  JointProfiles::flush()
  {
    if (is_on)
      file.flush();
  }


  void
  JointProfiles::save(OutputArchive &archive) const
  {
    times.save(archive);
    archive << file.text();
  }


  void
  JointProfiles::load(InputArchive &archive)
  {
    std::string text;
    times.load(archive);
    archive >> text;
    file.replace(text);
    file.hold();
  }
} // namespace liftoff
