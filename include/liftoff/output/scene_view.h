#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <liftoff/base/physical_units.h>
#include <liftoff/contact/bed.h>
#include <liftoff/contact/joint_dowels.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/joint_springs.h>
#include <liftoff/fem/mesh_refinement.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/loads/load_set.h>
#include <liftoff/time/clock.h>

namespace liftoff
{
  /**
   * What the outputs read of a scene, each part by the role it plays: the
   * plate and its mesh, the bed it rests on, what the joints pass, the
   * loads, the mesh's adaptation, the units the scene is written in and
   * the run's clock. Output::parse_parameters() checks an output's entries
   * against it; StepData hands it to every step. Outputs see the parts
   * only through here, so a part changing its class or a scene gaining a
   * part (a base layer) touches this one place.
   */
  struct SceneView
  {
    const MindlinPlate   &plate;
    const Discretization &discretization;
    /// The foundation under the plate: its law (gap, dashpots, pressure)
    /// and its diagnostics (resultant, contact).
    const Bed &bed;
    /// The springs between the slab and a base it can lift off (Base/
    /// Interface = tensionless), with the bed's law and diagnostics; none:
    /// nullptr.
    const Bed *interface;
    /// The springs along the joints between slabs and the dowels across
    /// them (a plate of one slab has neither).
    const JointSprings   &joints;
    const JointDowels    &dowels;
    const LoadSet        &loads;
    const MeshRefinement &mesh_refinement;
    const PhysicalUnits  &units;
    /// The run's clock at step 0, and whether it is a time integration.
    Clock clock;
    bool  dynamic;
    /// The columns of the energies the system's terms store, in the
    /// order of EnergyBalance::by_term.
    std::vector<std::string> energy_columns;
    /// Rank 0's start-up notes (a dropped default, a time not reached).
    const ConditionalOStream &notes;
  };
} // namespace liftoff
