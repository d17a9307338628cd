#include <liftoff/base/selection.h>
#include <liftoff/run/scene_parts.h>

#include <utility>

namespace liftoff
{
  namespace
  {
    // Whether the analysis is a time integration.
    const Selection<bool> analyses = {{"dynamic", true}, {"static", false}};
  } // namespace


  SceneParts::SceneParts(const MPI_Comm comm, SectionTimer &timer)
      : discretization(comm)
      , active_set(discretization, timer)
  {}


  void
  SceneParts::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Analysis");
    prm.declare_entry("Type",
                      "dynamic",
                      analyses.pattern(),
                      "dynamic: Newmark time integration to the end time; "
                      "static: equilibrium under the loads at tau = 0.");
    prm.leave_subsection();

    InitialConditions::declare_parameters(prm);
    MindlinPlate::declare_parameters(prm);
    Discretization::declare_parameters(prm);
    JointSprings::declare_parameters(prm);
    JointDowels::declare_parameters(prm);
    MeshRefinement::declare_parameters(prm);
    TensionlessWinklerFoundation::declare_parameters(prm);
    LoadSet::declare_parameters(prm);
    NewmarkIntegrator::declare_parameters(prm);
    EnergyCheck::declare_parameters(prm);
    ActiveSetIteration::declare_parameters(prm);
    LinearSolver::declare_parameters(prm);
  }


  PhysicalUnits::SceneOutline
  SceneParts::outline_for_units(ParameterHandler &scene)
  {
    PhysicalUnits::SceneOutline outline;
    MindlinPlate::describe_for_units(scene, outline);
    ContactLaw::describe_for_units(scene, outline);
    describe_shape_for_units(scene, outline);
    return outline;
  }


  void
  SceneParts::parse_parameters(ParameterHandler    &prm,
                               const PhysicalUnits &units)
  {
    prm.enter_subsection("Analysis");
    dynamic = analyses.parse(prm.get("Type"), "Analysis/Type");
    prm.leave_subsection();
    initial_conditions.parse_parameters(prm);
    plate.parse_parameters(prm);
    discretization.parse_parameters(prm, plate, units);
    plate.parse_slab_sections(prm, discretization.geometry());
    interface_springs.use_base(plate.base);
    mesh_refinement.parse_parameters(prm);
    foundation.parse_parameters(prm, plate.mass_on_bed());
    joint_springs.parse_parameters(prm);
    joint_dowels.parse_parameters(prm);
    joint_dowels.place_on(discretization.geometry());
    active_set.use_terms(system_terms());
    loads.parse_parameters(prm);
    loads.use_plate(plate);
    newmark.parse_parameters(prm);
    energy_check.parse_parameters(prm);
    active_set.parse_parameters(prm);
    active_set.linear_solver().parse_parameters(prm);
  }


  void
  SceneParts::check() const
  {
    if (!dynamic)
      AssertThrow(discretization.geometry().has_kinematic_support()
                    || foundation.law().model() != ContactLaw::Model::none,
                  ExcMessage("Analysis/Type = static: a plate with all edges "
                             "free and Foundation/Model = none has no static "
                             "equilibrium."));

    if (dynamic)
      newmark.check_end_time();
    newmark.step_control.check_against(newmark, dynamic);
    mesh_refinement.check_against(discretization);
    joint_springs.check_against(discretization.geometry().slabs());
  }


  void
  SceneParts::setup_mesh()
  {
    // The direct solver's factor dominates a large scene: what it and the
    // mesh would allocate is estimated before anything is built.
    MemoryEstimate::check(discretization,
                          active_set.linear_solver().factor_placement(),
                          discretization.mpi_communicator);
    discretization.setup();
    const double window =
      mesh_refinement.steps_between_adaptations() * clock().time_step();
    mesh_refinement.refine_around_loads(
      discretization,
      loads.regions_in_windows(0, window, mesh_refinement.n_windows()));
    loads.check_against(discretization, clock().time_step(), clock().n_steps());
  }


  Clock
  SceneParts::clock() const
  {
    return dynamic ? newmark.clock() : Clock();
  }


  void
  SceneParts::check_not_trivial() const
  {
    // Nothing to compute: most likely a load whose Magnitude was left at its
    // default 0.
    const bool has_interface = plate.base.n_layers() == 2;
    // A pre-compressed interface pushes slab and base apart unloaded.
    const bool is_pressed =
      foundation.law().is_pressing_plate()
      || (has_interface && interface_springs.law().is_pressing_plate());
    if (loads.is_empty() && !is_pressed)
      AssertThrow(dynamic && !initial_conditions.is_at_rest(discretization),
                  ExcMessage(
                    "The scene has no load (every Loads/.../Magnitude is 0)"
                    + std::string(dynamic ? " and starts at rest (Initial "
                                            "conditions are 0)"
                                          : "")
                    + " on a bed that presses nowhere (Foundation/Initial "
                      "gap >= 0"
                    + (has_interface ? ", Base/Interface gap >= 0" : "")
                    + "), so its solution is u = 0. Give a load a "
                      "Magnitude"
                    + (dynamic ? ", or the plate an initial displacement or "
                                 "velocity."
                               : ".")));
  }


  bool
  SceneParts::is_dynamic() const
  {
    return dynamic;
  }


  std::vector<SystemTerm *>
  SceneParts::system_terms()
  {
    std::vector<SystemTerm *> terms;
    for (const SystemTerm *term : std::as_const(*this).system_terms())
      terms.push_back(const_cast<SystemTerm *>(term));
    return terms;
  }


  std::vector<const SystemTerm *>
  SceneParts::system_terms() const
  {
    std::vector<const SystemTerm *> terms = {&plate_term, &foundation};
    if (plate.base.n_layers() == 2)
      terms.push_back(&interface_springs);
    // Only a plate of several slabs has joints to pass forces.
    if (discretization.geometry().slabs().is_jointed())
      terms.push_back(&joint_springs);
    if (!joint_dowels.sites().empty())
      terms.push_back(&joint_dowels);
    return terms;
  }


  SceneView
  SceneParts::view(const PhysicalUnits      &units,
                   const ConditionalOStream &notes) const
  {
    std::vector<std::string> energy_columns;
    for (const SystemTerm *term : system_terms())
      energy_columns.push_back(term->energy_column());
    return {plate,
            discretization,
            foundation,
            plate.base.n_layers() == 2 ? &interface_springs : nullptr,
            joint_springs,
            joint_dowels,
            loads,
            mesh_refinement,
            units,
            clock(),
            dynamic,
            energy_columns,
            notes};
  }


  TimeStepper::Parts
  SceneParts::for_stepper()
  {
    return {plate,
            discretization,
            matrices,
            system_terms(),
            loads,
            newmark,
            energy_check,
            mesh_refinement,
            active_set};
  }
} // namespace liftoff
