#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/physical_units.h>
#include <liftoff/base/section_timer.h>
#include <liftoff/contact/active_set_iteration.h>
#include <liftoff/contact/interface_springs.h>
#include <liftoff/contact/joint_dowels.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/initial_conditions.h>
#include <liftoff/fem/joint_springs.h>
#include <liftoff/fem/mesh_refinement.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_matrices.h>
#include <liftoff/fem/plate_term.h>
#include <liftoff/loads/load_set.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/time/energy_check.h>
#include <liftoff/time/newmark_integrator.h>
#include <liftoff/time/time_stepper.h>

namespace liftoff
{
  using namespace dealii;

  /**
   * The physical and numerical parts of a scene, as step-69's OfflineData
   * groups what the time stepping works on: each reads its own parameters;
   * here they are declared and parsed together and checked against each
   * other. The Simulator owns one and hands its parts to the TimeStepper;
   * the outputs, the folder and the checkpoint are the Simulator's.
   */
  struct SceneParts
  {
    SceneParts(const MPI_Comm comm, SectionTimer &timer);

    /// The parameters of every part below (not the outputs' and the
    /// checkpoint's).
    static void
    declare_parameters(ParameterHandler &prm);
    /// Read them from the dimensionless scene `prm` (the solver's), whose
    /// scene as written is in `units`; throws with a message naming the
    /// offending parameter.
    void
    parse_parameters(ParameterHandler &prm, const PhysicalUnits &units);
    /// What the parts that own the plate's and the bed's entries tell the
    /// SI conversion of the scene as written (PhysicalUnits::SceneOutline).
    static PhysicalUnits::SceneOutline
    outline_for_units(ParameterHandler &scene);
    /// The checks across parts that need no mesh.
    void
    check() const;

    /// The mesh of the scene, refined around its point loads, with the
    /// checks of the loads against it.
    void
    setup_mesh();
    /// Refuse a scene whose solution is u = 0 (no load, no precompressed
    /// bed, at rest); after the foundation's setup.
    void
    check_not_trivial() const;

    bool
    is_dynamic() const;
    /// The run's clock at step 0: the scene's for a time integration, the
    /// default (no step, dt = 0) for a static analysis.
    Clock
    clock() const;
    /// What the outputs read, by role; `units` the scene's, `notes` rank
    /// 0's start-up lines.
    SceneView
    view(const PhysicalUnits &units, const ConditionalOStream &notes) const;

    /// What the TimeStepper works on.
    TimeStepper::Parts
    for_stepper();

    InitialConditions            initial_conditions;
    MindlinPlate                 plate;
    Discretization               discretization;
    PlateMatrices                matrices;
    PlateTerm                    plate_term{matrices, plate};
    TensionlessWinklerFoundation foundation;
    /// Between the slab and a base it can lift off (Base/Interface =
    /// tensionless); in the term list only then.
    InterfaceSprings   interface_springs;
    JointSprings       joint_springs;
    JointDowels        joint_dowels;
    LoadSet            loads;
    NewmarkIntegrator  newmark;
    EnergyCheck        energy_check;
    MeshRefinement     mesh_refinement;
    ActiveSetIteration active_set;

  private:
    /// `Analysis/Type = dynamic` (else static).
    bool dynamic = true;
    /// The terms of the plate's system, the plate first: a coupling (a
    /// joint's springs) is one more line here.
    std::vector<const SystemTerm *>
    system_terms() const;
    /// The same list, to be driven.
    std::vector<SystemTerm *>
    system_terms();
  };
} // namespace liftoff
