#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <liftoff/base/number_text.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/output/run_summary.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/small_deflection_check.h>
#include <liftoff/time/plate_state.h>

#include <cmath>
#include <iostream>

namespace liftoff
{
  void
  SmallDeflectionCheck::write_in_units_of(const PhysicalUnits &units)
  {
    using Quantity = PhysicalUnits::Quantity;
    is_checked     = units.is_physical();
    w_scale        = units.scale(Quantity::deflection);
    time_scale     = units.scale(Quantity::time);
    for (const auto &[group, value] : units.groups())
      if (group == "Delta")
        thickness = value * units.scale(Quantity::length);
  }


  void
  SmallDeflectionCheck::setup(const SceneView &scene, const std::string &)
  {
    mesh_changed(scene);
  }


  void
  SmallDeflectionCheck::mesh_changed(const SceneView &scene)
  {
    const Discretization &discretization = scene.discretization;
    w_entries.clear();
    if (!is_checked)
      return;
    const IndexSet w_dofs =
      DoFTools::extract_dofs(discretization.dof_handler,
                             PlateFields::w_mask(
                               discretization.dof_handler.get_fe()));
    for (const types::global_dof_index i : w_dofs)
      w_entries.push_back(
        discretization.locally_owned_dofs.index_within_set(i));
  }


  void
  SmallDeflectionCheck::execute(const StepData &step)
  {
    if (!is_checked)
      return;
    // This rank's entries in the order of its locally owned unknowns.
    const double *const u     = step.state.u.begin();
    double              local = 0;
    for (const unsigned int k : w_entries)
      local = std::max(local, std::abs(u[k]));
    const double largest =
      Utilities::MPI::max(local, step.scene.discretization.mpi_communicator);
    if (largest > largest_w || !std::isfinite(largest))
      {
        largest_w       = largest;
        time_of_largest = step.state.clock.tau();
      }
    if (!has_warned && !warning().empty())
      {
        has_warned = true;
        if (Utilities::MPI::this_mpi_process(
              step.scene.discretization.mpi_communicator)
            == 0)
          std::cerr << "liftoff: warning: " << warning() << std::endl;
      }
  }


  double
  SmallDeflectionCheck::largest_ratio() const
  {
    return is_checked ? w_scale * largest_w / thickness : -1;
  }


  std::string
  SmallDeflectionCheck::warning() const
  {
    if (!is_checked || !(largest_ratio() > largest_share))
      return "";
    return "The largest deflection, |w| = " + format_number(w_scale * largest_w)
           + " m at t = " + format_number(time_scale * time_of_largest)
           + " s, is " + format_number(largest_ratio())
           + " times Units/Thickness = " + format_number(thickness)
           + " m (accepted: " + format_number(largest_share)
           + "): beyond the small deflections of linear plate theory, "
             "which leaves out the membrane stretching. Check the loads' "
             "magnitudes, Units/Young's modulus and Units/Subgrade "
             "modulus.";
  }


  void
  SmallDeflectionCheck::add_to(RunSummary &summary) const
  {
    if (is_checked)
      summary.add("largest |w| / thickness", largest_ratio());
  }


  void
  SmallDeflectionCheck::save(OutputArchive &archive) const
  {
    archive << largest_w << time_of_largest << has_warned;
  }


  void
  SmallDeflectionCheck::load(InputArchive &archive)
  {
    archive >> largest_w >> time_of_largest >> has_warned;
  }
} // namespace liftoff
