#include <deal.II/base/mpi.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/output_files.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/initial_conditions.h>
#include <liftoff/fem/mesh_refinement.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/fem/plate_matrices.h>
#include <liftoff/fem/point_functional.h>
#include <liftoff/fem/stiffness_limit.h>
#include <liftoff/loads/load_set.h>
#include <liftoff/time/energy_check.h>
#include <liftoff/time/newmark_integrator.h>
#include <liftoff/time/static_equilibrium.h>
#include <liftoff/time/step_size_controller.h>
#include <liftoff/time/time_stepper.h>

#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace liftoff
{
  namespace
  {
    // Why an active-set iteration did not settle, for error messages.
    std::string
    unsettled(const ActiveSetIteration::Result &result,
              const unsigned int                max_iterations)
    {
      if (result.cycle_length > 0)
        return "went round a cycle of " + std::to_string(result.cycle_length)
               + " sets";
      return "did not settle in " + std::to_string(max_iterations)
             + " iterations";
    }

    /// "a; or b; or c.": the likely causes of a failure, most likely first.
    std::string
    as_alternatives(const std::vector<std::string> &causes)
    {
      std::string text;
      for (const auto &cause : causes)
        text += (text.empty() ? "" : "; or ") + cause;
      return text + ".";
    }
  } // namespace


  TimeStepper::TimeStepper(const Parts   &parts,
                           const Options &options,
                           SectionTimer  &timer)
      : plate(parts.plate)
      , discretization(parts.discretization)
      , matrices(parts.matrices)
      , terms(parts.terms)
      , bed(Bed::of(parts.terms))
      , loads(parts.loads)
      , scene_newmark(parts.newmark)
      , newmark(parts.newmark)
      , energy_check(parts.energy_check)
      , mesh_refinement(parts.mesh_refinement)
      , active_set(parts.active_set)
      , controller(parts.newmark.step_control)
      , options(options)
      , timer(timer)
  {
    state_.clock = options.clock;
  }


  void
  TimeStepper::setup()
  {
    build_on_current_mesh(false);
    // A circle's cells follow it between their support points only: the
    // run says how much area, and so how much of a pressure and of the bed,
    // the mesh misses.
    // 1e-3: the coarse disc's 8 arcs of degree 2 (7.8e-4) pass, a Q1
    // polygon below 4 refinements does not.
    constexpr double largest_area_error = 1e-3;
    const double     area_error         = discretization.area_error();
    if (area_error <= largest_area_error)
      return;
    warn(mesh_warning,
         "The mesh's area differs from the plate's by "
           + format_number(area_error)
           + " (accepted: " + format_number(largest_area_error)
           + "): its cells follow the circles only at their nodes; "
             "loads over the plate and the bed are short by as much. "
             "Refine (Discretization/Global refinements) or raise "
             "Discretization/Polynomial degree.");
  }


  void
  TimeStepper::warn(std::string &kept, const std::string &message) const
  {
    kept = options.in_scene_terms ? options.in_scene_terms(message) : message;
    if (Utilities::MPI::this_mpi_process(discretization.mpi_communicator) == 0)
      std::cerr << "liftoff: warning: " << kept << std::endl;
  }


  void
  TimeStepper::build_on_current_mesh(const bool keep_motion)
  {
    // The plate's matrices count as assembly, the other terms' points and
    // the loads as set-up (the summary's sections).
    for (SystemTerm *term : terms)
      {
        SectionTimer::Scope t(timer,
                              term->stores() == SystemTerm::Stores::strain
                                ? "assembly"
                                : "setup");
        term->setup(discretization);
      }
    SectionTimer::Scope t(timer, "setup");
    StiffnessLimit::check(matrices.stiffness,
                          discretization.constraints,
                          terms);
    loads.setup(discretization);
    if (!keep_motion)
      for (auto *vector : {&state_.u, &state_.v, &state_.a, &state_.rest})
        discretization.reinit_vector(*vector);
    for (auto *vector : {&state_.load,
                         &state_.balance,
                         &next_load,
                         &rhs,
                         &u_next,
                         &scratch,
                         &scratch_2,
                         &dissipative_force})
      discretization.reinit_vector(*vector);
    discretization.reinit_ghosted_vector(state_.ghosted_u);
    discretization.reinit_ghosted_vector(state_.ghosted_rest);
    discretization.reinit_ghosted_vector(ghosted_scratch);
    state_.ghosted_u    = state_.u;
    state_.ghosted_rest = state_.rest;
    largest_eigenvalue  = 0;
    if (controller.is_enabled())
      w_entries =
        DoFTools::extract_dofs(discretization.dof_handler,
                               PlateFields::w_mask(
                                 discretization.dof_handler.get_fe()));
  }


  void
  TimeStepper::set_initial_state(const InitialConditions &initial_conditions)
  {
    initial_conditions.interpolate(discretization, state_.u, state_.v);
    state_.ghosted_u = state_.u;
  }


  void
  TimeStepper::check_time_step()
  {
    if (!newmark.is_conditionally_stable())
      return;
    const double limit = stable_time_step();
    AssertThrow(state_.clock.time_step() <= limit,
                ExcMessage(
                  "Time integration/Time step = <"
                  + format_number(state_.clock.time_step())
                  + "> exceeds the stability limit dtau = "
                  + format_number(limit) + " of Newmark's method with Beta = "
                  + format_number(newmark.beta)
                  + " < Gamma/2 = " + format_number(0.5 * newmark.gamma)
                  + " (omega_max, the largest frequency of M^-1 (K + K_f), "
                    "estimated as "
                  + tagged(format_number(std::sqrt(largest_eigenvalue)),
                           Quantity::frequency)
                  + (n_new_meshes > 0 ? " on the mesh refined at step "
                                          + std::to_string(state_.clock.step())
                                      : std::string())
                  + "): the run would blow up. Use a smaller Time "
                    "step or Beta >= Gamma/2 (e.g. 0.25 and 0.5)"
                  + (mesh_refinement.is_enabled()
                       ? ", or a smaller Mesh refinement/Maximum level."
                       : ".")));
  }


  double
  TimeStepper::stable_time_step()
  {
    if (largest_eigenvalue == 0)
      {
        SectionTimer::Scope t(timer, "stability limit");
        // Every spring in contact (the status setup() leaves): the stiffest
        // the foundation can make the plate.
        LA::MPI::Vector ghosted;
        discretization.reinit_ghosted_vector(ghosted);
        // The plate's K is the operator's own; the other terms add theirs.
        largest_eigenvalue = matrices.largest_eigenvalue(
          discretization, [&](const LA::MPI::Vector &x, LA::MPI::Vector &y) {
            ghosted = x;
            for (const SystemTerm *term : terms)
              if (term->stores() != SystemTerm::Stores::strain)
                term->add_force({x, ghosted, scratch_2}, y);
          });
      }
    return newmark.stable_time_step(largest_eigenvalue);
  }


  void
  TimeStepper::require_finite(
    const unsigned int                          step,
    const double                                tau,
    const std::string                          &what,
    const std::vector<const LA::MPI::Vector *> &vectors,
    const std::vector<double>                  &numbers,
    const std::function<std::string()>         &cause)
  {
    bool finite = std::all_of(numbers.begin(), numbers.end(), [](double x) {
      return std::isfinite(x);
    });
    for (const auto *vector : vectors)
      finite = finite && has_finite_local_entries(*vector);
    if (Utilities::MPI::min(static_cast<int>(finite),
                            discretization.mpi_communicator)
        == 1)
      return;
    AssertThrow(false,
                ExcMessage("Step " + std::to_string(step)
                           + " (tau = " + format_number(tau) + "): " + what
                           + " is not a finite number. Likely cause: "
                           + cause()));
  }


  void
  TimeStepper::require_finite_state(
    const std::string                          &what,
    const std::vector<const LA::MPI::Vector *> &vectors,
    const std::vector<double>                  &numbers,
    const LA::MPI::Vector                      &load)
  {
    require_finite(state_.clock.step(),
                   state_.clock.tau(),
                   what,
                   vectors,
                   numbers,
                   [&]() { return cause_of_non_finite_state(load); });
  }


  std::string
  TimeStepper::cause_of_non_finite_state(const LA::MPI::Vector &load)
  {
    if (newmark.is_conditionally_stable() && options.is_dynamic)
      return "Newmark's method with Beta = " + format_number(newmark.beta)
             + " < Gamma/2 = " + format_number(0.5 * newmark.gamma)
             + " is stable only for steps up to about dtau = "
             + format_number(stable_time_step())
             + " (an estimate from below of omega_max); Time integration/Time "
               "step = <"
             + format_number(state_.clock.time_step())
             + "> is too large for it.";
    return "the values overflow the range of double: the largest load "
           "entry is "
           + format_number(load.linfty_norm())
           + "; check Loads/.../Magnitude and the initial conditions.";
  }


  bool
  TimeStepper::checks_energy() const
  {
    // The balance is a law of the scheme only where the scheme conserves
    // the energy or can only lose it; Beta != 1/4 with Gamma = 1/2
    // conserves another energy (Beta = 1/2 on a quarter plate under a
    // sudden point load: 0.335 of the scale at the first step).
    return options.is_dynamic && energy_check.is_enabled()
           && (newmark.conserves_energy() || newmark.dissipates_energy());
  }


  void
  TimeStepper::check_energy_balance()
  {
    if (!checks_energy())
      return;
    if (!energy_check.exceeds(state_.clock.step(),
                              state_.energies,
                              state_.initial_energies,
                              newmark.dissipates_energy()))
      return;
    const std::string message =
      "Step " + std::to_string(state_.clock.step())
      + " (tau = " + format_number(state_.clock.tau())
      + "): " + energy_check.describe_violation()
      + ". Likely cause: " + likely_cause_of_energy_error();
    AssertThrow(energy_check.mode() != EnergyCheck::Mode::fail,
                ExcMessage(message));
    warn(warning, message);
  }


  void
  TimeStepper::check_static_equilibrium(const LA::MPI::Vector &load)
  {
    equilibrium = StaticEquilibrium::check(
      discretization, bed, state_.ghosted_u, load, active_set.system_matrix());
    if (equilibrium.holds())
      return;
    warn(warning,
         "The static solution is not in equilibrium: the bed's "
         "resultant or moment differs from the loads' by "
           + format_number(equilibrium.imbalance)
           + " of the loads (accepted: " + format_number(equilibrium.accepted())
           + ", the larger of " + format_number(StaticEquilibrium::tolerance)
           + " and the round-off of the solve). Likely cause: an "
             "ill-conditioned system (a very soft bed under a free "
             "plate) or a defect; do not use these results.");
  }


  const StaticEquilibrium::Result &
  TimeStepper::static_equilibrium() const
  {
    return equilibrium;
  }


  std::string
  TimeStepper::likely_cause_of_energy_error() const
  {
    std::vector<std::string> causes;
    // The plate on its springs swings at sqrt(Gamma) (unit mass): a step
    // longer than a radian of that swing lets contact switch within it.
    const double omega = bed.law().rigid_body_frequency();
    if (state_.clock.time_step() * omega > 1)
      causes.push_back(
        "Time integration/Time step = <"
        + format_number(state_.clock.time_step())
        + "> is long for the bed: the plate swings on it at omega = "
          "sqrt(k / (rho H)) = "
        + tagged(format_number(omega), Quantity::frequency)
        + ", so Time step * omega = "
        + format_number(state_.clock.time_step() * omega)
        + " > 1; use a step below dtau = " + format_number(1 / omega));
    const double tolerance = active_set.linear_solver().relative_tolerance();
    if (tolerance > 1e-8)
      causes.push_back("Linear solver/Tolerance = " + format_number(tolerance)
                       + " lets each solve miss its equations by that share; "
                         "use 1e-10 or less");
    if (causes.empty())
      causes.push_back(
        "a parameter near the end of its range (Foundation/Stiffness, Shear "
        "modulus, Damping) or a mesh too coarse for the contact front; "
        "compare a run with half the Time step");
    return as_alternatives(causes);
  }


  std::string
  TimeStepper::likely_cause_of_ill_conditioning() const
  {
    std::vector<std::string> causes;
    const std::string edge = discretization.geometry().only_supported_edge();
    if (!edge.empty())
      causes.push_back("the plate is held on one edge only (Boundary "
                       "conditions/"
                       + edge
                       + "), about which it can turn: a mechanism that "
                         "only the foundation's contact holds; clamp that "
                         "edge or support another");
    const PlateGeometry &geometry   = discretization.geometry();
    const double         elongation = geometry.largest_cell_aspect_ratio();
    if (elongation > 100)
      causes.push_back(
        "the cells are " + format_number(elongation)
        + " times longer than wide ("
        + (geometry.shape() == PlateShape::mesh_file
             ? "the cells of Discretization/Mesh file"
             : "Plate/Aspect ratio against Discretization/Cells along x and y")
        + "); use cells closer to square");
    if (const std::string slab = slab_barely_in_contact(); !slab.empty())
      causes.push_back(slab);
    if (causes.empty())
      causes.push_back(
        "a very small Foundation/Stiffness under a thin plate (Plate/Thickness "
        "ratio) with free edges; use a stiffer foundation, support an edge "
        "or run a dynamic analysis");
    return as_alternatives(causes);
  }


  std::string
  TimeStepper::slab_barely_in_contact() const
  {
    const SlabLayout &slabs = discretization.geometry().slabs();
    if (slabs.n_slabs() < 2)
      return "";
    const Vector<float> fraction =
      bed.diagnostics().contact_fraction_per_cell();
    // Each slab's area and area in contact; the cut mesh numbers a cell's
    // material by its slab.
    std::vector<double> area(2 * slabs.n_slabs(), 0.0);
    for (const auto &cell : discretization.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          area[2 * cell->material_id()] += cell->measure();
          area[2 * cell->material_id() + 1] +=
            fraction[cell->active_cell_index()] * cell->measure();
        }
    Utilities::MPI::sum(area, discretization.mpi_communicator, area);
    unsigned int least    = 0;
    double       smallest = 2;
    for (unsigned int s = 0; s < slabs.n_slabs(); ++s)
      if (area[2 * s] > 0 && area[2 * s + 1] / area[2 * s] < smallest)
        {
          smallest = area[2 * s + 1] / area[2 * s];
          least    = s;
        }
    if (smallest >= 0.1)
      return "";
    std::string joints;
    for (const Joint &joint : slabs.joints())
      if (!joint.tied)
        joints += (joints.empty() ? "" : ", ") + joint.name;
    return "slab " + std::to_string(least + 1) + " (of "
           + std::to_string(slabs.n_slabs())
           + ", numbered along x first) touches the bed over only "
           + format_number(100 * smallest)
           + " % of its area: a slab that its joints (" + joints
           + ") hold too little tips about a load at its own edge, or floats "
             "without one, on a bed that does not pull; stiffen the joint "
             "(Slabs/Shear stiffness, Slabs/Dowels), move the load off the "
             "joint, give the slabs their weight (Loads/Self weight) or run "
             "a dynamic analysis";
  }


  ActiveSetIteration::Result
  TimeStepper::solve_static(const LA::MPI::Vector &load,
                            const std::string     &what,
                            const std::string     &during,
                            const std::string     &remedy,
                            const StopCheck       &stop_if_requested)
  {
    // The plate at rest: the springs' Gamma (w - g), no dashpot force.
    bed.use_pressure(bed.law().pressure());
    const ActiveSetIteration::System system{
      load, !discretization.geometry().has_kinematic_support()};
    bed.activate_all();
    active_set.set_base_matrix(base_matrix({0.0, 0.0}), 0.0);

    const auto result = active_set.solve(system, state_.u, state_.ghosted_u);
    require_finite_state("the static solution", {&state_.u}, {}, load);
    // The one "step" of a static analysis is done: a stop request ends the
    // run here, like a dynamic run after a step, with no result written.
    stop_if_requested("during " + during + "; no result was written.");
    check_static_solution(result, system, what, remedy);
    return result;
  }


  void
  TimeStepper::check_static_solution(const ActiveSetIteration::Result &result,
                                     const ActiveSetIteration::System &system,
                                     const std::string                &what,
                                     const std::string                &remedy)
  {
    AssertThrow(!result.lost_contact,
                ExcMessage(what
                           + ": the plate lifts off the "
                             "foundation everywhere (or keeps too little "
                             "contact to be held) and has no support, so it "
                             "has no static equilibrium under these loads. "
                           + remedy));
    AssertThrow(result.converged,
                ExcMessage(what + ": the active set "
                           + unsettled(result, active_set.max_iterations)
                           + (result.cycle_length > 0
                                ? " (Active set/Cycle rule = stop)."
                                : " (Active set/Maximum iterations).")));
    // A very soft foundation under a plate with free edges leaves the
    // rigid-body motion held by Gamma alone: the system is regular, its
    // residual small, and its answer still round-off. Measure, don't trust.
    const double change = active_set.refinement_change(state_.u, system);
    AssertThrow(change <= 1e-3,
                ExcMessage(what
                           + ": the solution is not accurate to "
                             "0.1 %: one step of iterative refinement changes "
                             "it by "
                           + format_number(change)
                           + " (relative). The system is too ill-conditioned "
                             "for double precision. Likely cause: "
                           + likely_cause_of_ill_conditioning()));
  }


  ActiveSetIteration::Result
  TimeStepper::solve_static_analysis(const StopCheck &stop_if_requested)
  {
    solve_rest_state();
    LA::MPI::Vector &load = state_.load;
    assemble_loads(0, 0.0, load);
    const auto result =
      solve_static(load,
                   "Static analysis",
                   "the static analysis",
                   "Use a dynamic analysis or support an edge.",
                   stop_if_requested);
    // Loads applied proportionally: the response is positively homogeneous
    // (max(w, 0) is), so their work is 1/2 F.u (Clapeyron) even with
    // lift-off, and the balance column checks it against the state at
    // rest. A gap makes the response affine; Clapeyron's identity at the
    // equilibrium then gains the gap's term (gap_work()).
    state_.work =
      0.5 * discretization.geometry().n_symmetry_copies()
      * (load * state_.u + active_set.status_load_work(state_.ghosted_u));
    state_.energies = energies();
    require_finite_state("an energy", {}, state_.energies.values(), load);
    check_static_equilibrium(load);
    return result;
  }


  void
  TimeStepper::set_rest_state()
  {
    state_.rest         = state_.u;
    state_.ghosted_rest = state_.rest;
  }


  void
  TimeStepper::solve_rest_state()
  {
    // Only the joints' load transfer reads it: a plate of one slab is spared
    // the second solve.
    if (!loads.has_rest_loads()
        || !discretization.geometry().slabs().is_jointed())
      return;
    SectionTimer::Scope t(timer, "permanent loads");
    loads.assemble_rest(scratch);
    try
      {
        solve_static(scratch,
                     "The static equilibrium under the weight and the "
                     "temperature loads alone, from which the joints' load "
                     "transfer is measured",
                     "the equilibrium under the weight and the temperature "
                     "loads",
                     "",
                     // A stop request is answered by the analysis's own
                     // solve, which follows: here it would be taken for
                     // a failure of the rest state.
                     [](const std::string &) {});
      }
    catch (const ExcMessage &e)
      {
        // Curl without weight on a bed that does not pull has no rest: the
        // transfer is then of the whole deflection. The failure is
        // decided collectively, so every rank is here.
        state_.u = 0;
        warn(rest_warning,
             "The weight and the temperature loads alone have no static "
             "equilibrium ("
               + message_of(e)
               + "); the joints' load transfer (lte columns, joints.csv) is "
                 "of the whole deflection, curl and weight included.");
      }
    set_rest_state();
  }


  void
  TimeStepper::settle_under_permanent_loads(const StopCheck &stop_if_requested)
  {
    SectionTimer::Scope t(timer, "permanent loads");
    // The initial displacement is measured from the settled state.
    LA::MPI::Vector initial_displacement = state_.u;
    state_.u                             = 0;
    loads.assemble_permanent(scratch);
    solve_static(scratch,
                 "The static equilibrium under Loads/Self weight, from "
                 "which the time integration starts",
                 "the static equilibrium under Loads/Self weight",
                 "Give it a foundation (Foundation/Model) or support an "
                 "edge.",
                 stop_if_requested);
    state_.u += initial_displacement;
    state_.ghosted_u = state_.u;
  }


  bool
  TimeStepper::adapt_mesh()
  {
    {
      SectionTimer::Scope t(timer, "mesh refinement");
      if (!mesh_refinement.mark_cells(
            discretization,
            bed.diagnostics().contact_fraction_per_cell(),
            // A static analysis's cycles look ahead at the scene's time
            // step too.
            loads.regions_in_windows(state_.clock.tau(),
                                     mesh_refinement.steps_between_adaptations()
                                       * scene_newmark.clock().time_step(),
                                     mesh_refinement.n_windows()),
            state_.ghosted_u))
        return false;
      mesh_refinement.execute(discretization,
                              {&state_.u, &state_.v, &state_.a, &state_.rest});
    }
    ++n_new_meshes;
    build_on_current_mesh(true);
    return true;
  }


  std::optional<double>
  TimeStepper::adapt_mesh_in_time_loop()
  {
    const double before = stored_energy();
    if (!adapt_mesh())
      return {};
    // The state on the new mesh: its contact status at the new Gauss
    // points, the load and force balance there, an acceleration in
    // balance with them, the system matrix and its factor (once per mesh).
    {
      SectionTimer::Scope t(timer, "mesh refinement");
      equilibrate(state_.clock.step(),
                  state_.clock.tau(),
                  "the acceleration after a new mesh");
    }
    // The time steps' matrix holds the dashpots too (Gamma + c kappa):
    // kappa is passed as the argument, not kept as a setting of the
    // foundation, whose setup on a new mesh would reset it to 0 (a damped
    // adaptive run would then solve with Gamma alone: balance error 0.38
    // of the energy scale).
    active_set.set_base_matrix(effective_base_matrix(),
                               newmark.velocity_factor(),
                               level_in_use);
    check_time_step();
    state_.energies    = energies();
    const double after = stored_energy();
    return before > 0 ? (after - before) / before : 0.0;
  }


  double
  TimeStepper::stored_energy()
  {
    const EnergyBalance e = state_energies();
    return e.kinetic + e.strain + e.supports;
  }


  EnergyBalance
  TimeStepper::state_energies()
  {
    EnergyBalance e = energies_of(terms,
                                  state_.u,
                                  state_.ghosted_u,
                                  state_.v,
                                  discretization.geometry().n_symmetry_copies(),
                                  state_.work,
                                  scratch);
    e.dissipated    = state_.dissipated;
    return e;
  }


  EnergyBalance
  TimeStepper::energies()
  {
    if (!options.records_energies && !checks_energy())
      return EnergyBalance{0, 0, 0, state_.work, state_.dissipated, {}};
    return state_energies();
  }


  ActiveSetIteration::BaseMatrix
  TimeStepper::base_matrix(const MatrixFactors &factors) const
  {
    return [this, factors](LA::MPI::SparseMatrix &base) {
      base = 0;
      for (SystemTerm *term : terms)
        if (!term->has_status())
          term->add_to_matrix(factors, base);
    };
  }


  ActiveSetIteration::BaseMatrix
  TimeStepper::effective_base_matrix() const
  {
    return base_matrix({newmark.mass_factor(), newmark.velocity_factor()});
  }


  void
  TimeStepper::equilibrate(const unsigned int step,
                           const double       tau,
                           const std::string &what)
  {
    use_pressure_at_state_velocity();
    active_set.update_status(state_.ghosted_u);
    assemble_loads(step, tau, state_.load);
    force_balance(state_.load, state_.balance);
    if (bed.law().has_damping())
      compute_dissipative_force();
    matrices.solve_with_mass(state_.a, state_.balance);
    discretization.constraints.distribute(state_.a);
    require_finite_state(what, {&state_.a}, {}, state_.load);
  }


  void
  TimeStepper::start_time_integration(const StopCheck &stop_if_requested)
  {
    // The initial acceleration solves M a0 = F(0) - (K + K_f(u0)) u0 with
    // the contact set of u0.
    if (loads.has_permanent_loads())
      settle_under_permanent_loads(stop_if_requested);
    {
      SectionTimer::Scope t(timer, "initial acceleration");
      equilibrate(0, 0.0, "the initial acceleration");
    }
    set_rest_state();
    // The energies with the contact status of the initial state (the shear
    // layer's is taken over it), before the first iterate replaces it.
    state_.energies         = energies();
    state_.initial_energies = state_.energies;
    require_finite_state("an energy",
                         {},
                         state_.energies.values(),
                         state_.load);
    first_step_pending = true;
  }


  ActiveSetIteration::Result
  TimeStepper::do_step(const unsigned int step)
  {
    if (std::exchange(first_step_pending, false))
      {
        // The first iterate is the bilateral problem.
        bed.activate_all();
        active_set.set_base_matrix(effective_base_matrix(),
                                   newmark.velocity_factor(),
                                   level_in_use);
      }
    if (controller.is_enabled())
      return do_controlled_steps(step);
    const double tau = state_.clock.tau_at(step);
    assemble_right_hand_side(step, tau);
    const auto iteration = solve_contact_problem(step, tau, step > 1);
    advance(step);
    return iteration;
  }


  ActiveSetIteration::Result
  TimeStepper::do_controlled_steps(const unsigned int step)
  {
    // Positions count steps of the finest level from tau_at(step - 1); a
    // time is that tau plus a power of 2 times Time step, and the last one
    // is tau_at(step) itself, as in a fixed-step run.
    const unsigned int         finest = controller.finest_level();
    const unsigned int         units  = 1u << finest;
    const double               start  = state_.clock.tau();
    ActiveSetIteration::Result total;
    total.converged = true;
    controller.start_interval();
    // The contact area of the state, for the event rule: a repeated step
    // leaves the foundation with the set of its own solution.
    double contact = bed.diagnostics().contact_area_fraction();
    for (unsigned int position = 0; position < units;)
      {
        use_level(controller.level());
        const unsigned int end = position + (1u << (finest - level_in_use));
        const double       tau = end == units
                                   ? state_.clock.tau_at(step)
                                   : start
                                 + std::ldexp(state_.clock.time_step() * end,
                                              -static_cast<int>(finest));
        assemble_right_hand_side(step, tau);
        const auto iteration =
          solve_contact_problem(step, tau, step > 1 || position > 0);
        total.iterations += iteration.iterations;
        total.cycle_length =
          std::max(total.cycle_length, iteration.cycle_length);
        total.lost_contact = total.lost_contact || iteration.lost_contact;
        const double contact_after = bed.diagnostics().contact_area_fraction();
        if (!controller.judge(relative_step_error(),
                              std::abs(contact_after - contact),
                              position))
          continue;
        contact = contact_after;
        // The clock reaches `step` with the last substep only.
        advance(end == units ? step : step - 1);
        position = end;
      }
    return total;
  }


  void
  TimeStepper::use_level(const unsigned int level)
  {
    if (level == level_in_use)
      return;
    newmark      = scheme_of_level(level);
    level_in_use = level;
    // The factors of the levels used last are kept (ActiveSetIteration):
    // a return to one costs no factorisation.
    active_set.switch_base_matrix(level,
                                  effective_base_matrix(),
                                  newmark.velocity_factor());
  }


  NewmarkIntegrator
  TimeStepper::scheme_of_level(const unsigned int level) const
  {
    return scene_newmark.with_time_step(
      std::ldexp(scene_newmark.clock().time_step(), -static_cast<int>(level)));
  }


  double
  TimeStepper::relative_step_error()
  {
    // e = (beta - 1/6) dt^2 (a_{n+1} - a_n), and a_{n+1} - a_n is
    // (u_{n+1} - u_predicted) / (beta dt^2) by advance().
    newmark.predict(state_.u, state_.v, state_.a, scratch_2);
    scratch_2.sadd(-1.0, 1.0, u_next);
    double error = 0, w = 0;
    for (const auto i : w_entries)
      {
        error = std::max(error, std::abs(scratch_2[i]));
        w     = std::max(w, std::abs(u_next[i]));
      }
    const double factor = std::abs(newmark.beta - 1.0 / 6.0) / newmark.beta;
    return controller.relative_error(
      factor * Utilities::MPI::max(error, discretization.mpi_communicator),
      Utilities::MPI::max(w, discretization.mpi_communicator));
  }


  void
  TimeStepper::assemble_right_hand_side(const unsigned int step,
                                        const double       tau)
  {
    assemble_loads(step, tau, next_load);
    SectionTimer::Scope t(timer, "right hand side");
    newmark.right_hand_side(matrices.mass,
                            state_.u,
                            state_.v,
                            state_.a,
                            next_load,
                            state_.balance,
                            scratch,
                            rhs);
  }


  void
  TimeStepper::use_pressure_at_state_velocity()
  {
    if (!bed.law().has_damping())
      {
        bed.use_pressure(bed.law().pressure());
        return;
      }
    // At a given state v is given: kappa = 0, o = -v.
    scratch.equ(-1.0, state_.v);
    ghosted_scratch = scratch;
    bed.use_pressure(bed.law().pressure(0.0, ghosted_scratch));
  }


  void
  TimeStepper::compute_dissipative_force()
  {
    ghosted_scratch   = state_.v;
    dissipative_force = 0;
    bed.add_dissipative_force(state_.ghosted_u,
                              ghosted_scratch,
                              dissipative_force);
  }


  ActiveSetIteration::Result
  TimeStepper::solve_contact_problem(const unsigned int step,
                                     const double       tau,
                                     const bool         from_prediction)
  {
    if (bed.law().has_damping())
      {
        // In the step v_{n+1} = kappa u_{n+1} - o_n: the dashpots' pressure
        // is affine in the new displacement, like a spring on a gap.
        newmark.velocity_offset(state_.u, state_.v, state_.a, scratch);
        ghosted_scratch = scratch;
        bed.use_pressure(
          bed.law().pressure(newmark.velocity_factor(), ghosted_scratch));
      }
    else
      bed.use_pressure(bed.law().pressure());
    newmark.predict(state_.u, state_.v, state_.a, u_next);
    // The first step starts from the bilateral set: the predictor has no
    // motion yet to extrapolate.
    const auto result =
      active_set.solve({rhs}, u_next, state_.ghosted_u, from_prediction);
    // Before the convergence test: a nan makes the contact set wander.
    require_finite(step, tau, "the solution", {&u_next}, {}, [&]() {
      return cause_of_non_finite_state(next_load);
    });
    AssertThrow(result.converged,
                ExcMessage("The active set "
                           + unsettled(result, active_set.max_iterations)
                           + " at step " + std::to_string(step)
                           + " (tau = " + format_number(tau)
                           + (result.cycle_length > 0
                                ? "); Active set/Cycle rule = stop asks "
                                  "for this error; union resolves it."
                                : "); raise Active set/Maximum iterations "
                                  "or reduce Time integration/Time "
                                  "step.")));
    return result;
  }


  void
  TimeStepper::advance(const unsigned int step)
  {
    state_.work += work_of_step(state_.u,
                                u_next,
                                state_.load,
                                next_load,
                                discretization.geometry().n_symmetry_copies(),
                                scratch,
                                scratch_2);
    copy_values(next_load, state_.load);
    newmark.advance(u_next, state_.u, state_.v, state_.a);
    state_.clock.set_step(step);
    if (bed.law().has_damping())
      add_dissipated_energy();
    if (newmark.needs_force_balance())
      {
        SectionTimer::Scope t(timer, "right hand side");
        use_pressure_at_state_velocity();
        force_balance(state_.load, state_.balance);
      }
    state_.energies = energies();
    require_finite_state("the velocity, acceleration or an energy",
                         {&state_.v, &state_.a},
                         state_.energies.values(),
                         state_.load);
    check_energy_balance();
  }


  void
  TimeStepper::add_dissipated_energy()
  {
    // The work over the step, by the trapezoidal rule as the loads',
    // 1/2 (u_{n+1} - u_n).(f_n + f_{n+1}), of the dashpots and of the
    // springs' force that the foundation energy does not hold (where the
    // dashpots decide the status): without the latter the balance missed
    // a term that does not fall with dt (truck-crossing-slab: 2.3e-3 and
    // 2.9e-3 of the energy scale at dt and dt/2). `scratch` still holds
    // u_{n+1} - u_n from work_of_step().
    LA::MPI::Vector &previous_force = scratch_2;
    previous_force                  = dissipative_force;
    compute_dissipative_force();
    previous_force += dissipative_force;
    state_.dissipated += 0.5 * discretization.geometry().n_symmetry_copies()
                         * (scratch * previous_force);
  }


  void
  TimeStepper::assemble_loads(const unsigned int step,
                              const double       tau,
                              LA::MPI::Vector   &load)
  {
    loads.assemble(tau, load);
    require_finite(step, tau, "the load vector", {&load}, {}, [&]() {
      return loads.non_finite_load(tau);
    });
  }


  void
  TimeStepper::force_balance(const LA::MPI::Vector &load,
                             LA::MPI::Vector       &balance)
  {
    balance = 0;
    for (const SystemTerm *term : terms)
      term->add_force({state_.u, state_.ghosted_u, scratch}, balance);
    balance.sadd(-1.0, 1.0, load);
    active_set.add_status_loads(balance);
  }


  const PlateState &
  TimeStepper::state() const
  {
    return state_;
  }


  double
  TimeStepper::deflection_at(const Point<2> &p) const
  {
    const PointFunctional probe(discretization,
                                discretization.geometry().to_modelled_part(p));
    return Utilities::MPI::sum(probe.local_value(state_.ghosted_u),
                               discretization.mpi_communicator);
  }


  FoundationDiagnostics::PressureRange
  TimeStepper::contact_pressure_range() const
  {
    LA::MPI::Vector v;
    discretization.reinit_ghosted_vector(v);
    v = state_.v;
    return bed.diagnostics().pressure_range(state_.ghosted_u, v);
  }


  std::string
  TimeStepper::warnings() const
  {
    std::string all;
    for (const std::string *text : {&mesh_warning, &rest_warning, &warning})
      if (!text->empty())
        all += (all.empty() ? "" : " ") + *text;
    return all;
  }


  unsigned int
  TimeStepper::n_adaptations() const
  {
    return n_new_meshes;
  }


  const StepSizeController &
  TimeStepper::step_control() const
  {
    return controller;
  }


  template <class Archive>
  void
  TimeStepper::serialize_state(Archive &archive)
  {
    archive &state_;
    archive &energy_check;
    // The level of the saved matrix, which serialize_contact() then reads.
    if (!controller.is_enabled())
      return;
    unsigned int level = level_in_use;
    archive     &controller;
    archive     &level;
    if constexpr (Archive::is_loading::value)
      {
        level_in_use = level;
        newmark      = scheme_of_level(level);
      }
  }


  template <class Archive>
  void
  TimeStepper::serialize_contact(Archive &archive)
  {
    if constexpr (Archive::is_loading::value)
      {
        // The matrix of the time steps, which the saved one is, holds the
        // dashpots (Gamma + c kappa).
        for (SystemTerm *term : terms)
          term->load(archive);
        if (controller.is_enabled())
          active_set.load_kept_factors(archive, [this](const unsigned int l) {
            const NewmarkIntegrator scheme = scheme_of_level(l);
            return base_matrix(
              {scheme.mass_factor(), scheme.velocity_factor()});
          });
        active_set.load(archive,
                        effective_base_matrix(),
                        newmark.velocity_factor());
        // The dashpots' force of the saved state, for the next step's
        // dissipation.
        if (bed.law().has_damping())
          compute_dissipative_force();
      }
    else
      {
        for (const SystemTerm *term : terms)
          term->save(archive);
        if (controller.is_enabled())
          active_set.save_kept_factors(archive);
        active_set.save(archive);
      }
  }


  template void
  TimeStepper::serialize_state(InputArchive &);
  template void
  TimeStepper::serialize_state(OutputArchive &);
  template void
  TimeStepper::serialize_contact(InputArchive &);
  template void
  TimeStepper::serialize_contact(OutputArchive &);
} // namespace liftoff
