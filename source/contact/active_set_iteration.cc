#include <liftoff/base/archives.h>
#include <liftoff/base/selection.h>
#include <liftoff/contact/active_set_iteration.h>

#include <cmath>

namespace liftoff
{
  namespace
  {
    using CycleRule                        = ActiveSetIteration::CycleRule;
    const Selection<CycleRule> cycle_rules = {{"union",
                                               CycleRule::union_of_cycle},
                                              {"stop", CycleRule::stop},
                                              {"none", CycleRule::none}};
    // Whether the iteration starts from the prediction's contact set.
    const Selection<bool> initial_sets = {{"predicted", true},
                                          {"previous", false}};
  } // namespace


  void
  ActiveSetIteration::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Active set");
    prm.declare_entry("Maximum iterations",
                      "50",
                      Patterns::Integer(1),
                      "Iterations of eq. (3.9) per step before the run stops "
                      "with an error naming the step.");
    prm.declare_entry(
      "Cycle rule",
      "union",
      cycle_rules.pattern(),
      "When the contact set of a step returns to a set it had before "
      "(a cycle that would never settle): union, solve once more with every "
      "Gauss point in contact that was in contact in any set of the cycle "
      "and accept that, reported in history.csv (active_set_cycle) and "
      "summary.txt; stop, end the run with an error naming the step; none, "
      "do not look for cycles and iterate up to Maximum iterations.");
    prm.declare_entry(
      "Initial set",
      "predicted",
      initial_sets.pattern(),
      "The contact set a time step's iteration starts from. predicted: "
      "the set of the Newmark predictor u + dt v + dt^2/2 a (the points it "
      "presses into the foundation); previous: the set the previous step "
      "ended with. Either way the first step starts from the bilateral set, "
      "and points that end inside the round-off band of the contact rule "
      "keep the previous step's status, so both reach the same sets; the "
      "prediction mostly needs fewer iterations.");
    prm.leave_subsection();
  }


  void
  ActiveSetIteration::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Active set");
    max_iterations = prm.get_integer("Maximum iterations");
    cycle_rule =
      cycle_rules.parse(prm.get("Cycle rule"), "Active set/Cycle rule");
    starts_from_prediction =
      initial_sets.parse(prm.get("Initial set"), "Active set/Initial set");
    prm.leave_subsection();
  }


  const LinearSolver &
  ActiveSetIteration::linear_solver() const
  {
    return solver;
  }


  LinearSolver &
  ActiveSetIteration::linear_solver()
  {
    return solver;
  }


  ActiveSetIteration::ActiveSetIteration(const Discretization &discretization,
                                         SectionTimer         &timer)
      : discretization(discretization)
      , timer(timer)
      , solver(timer)
  {}


  void
  ActiveSetIteration::use_terms(const std::vector<SystemTerm *> &system_terms)
  {
    bed = &Bed::of(system_terms);
    terms.clear();
    for (SystemTerm *term : system_terms)
      if (term->has_status())
        terms.push_back(&dynamic_cast<StatusTerm &>(*term));
  }


  ActiveSetIteration::Statuses
  ActiveSetIteration::statuses() const
  {
    Statuses all;
    for (const StatusTerm *term : terms)
      all.push_back(term->status());
    return all;
  }


  ActiveSetIteration::Statuses
  ActiveSetIteration::statuses_in_matrix() const
  {
    Statuses all;
    for (const StatusTerm *term : terms)
      all.push_back(term->status_in_matrix());
    return all;
  }


  unsigned long
  ActiveSetIteration::count_changes(
    const std::function<unsigned long(StatusTerm &)> &change)
  {
    unsigned long n = 0;
    for (StatusTerm *term : terms)
      n += change(*term);
    return n;
  }


  bool
  ActiveSetIteration::has_status_load() const
  {
    for (const StatusTerm *term : terms)
      if (term->has_status_load())
        return true;
    return false;
  }


  void
  ActiveSetIteration::update_status(const LA::MPI::Vector &ghosted_u)
  {
    count_changes(
      [&](StatusTerm &term) { return term.update_status(ghosted_u); });
  }


  void
  ActiveSetIteration::add_status_loads(LA::MPI::Vector &vector) const
  {
    for (const StatusTerm *term : terms)
      if (term->has_status_load())
        term->add_status_load(vector);
  }


  double
  ActiveSetIteration::status_load_work(const LA::MPI::Vector &ghosted_u) const
  {
    double work = 0;
    for (const StatusTerm *term : terms)
      work += term->status_load_work(ghosted_u);
    return work;
  }


  void
  ActiveSetIteration::multiply_by_change(const LA::MPI::Vector &src,
                                         LA::MPI::Vector       &dst,
                                         const Since            since)
  {
    if (change_source.size() != src.size()
        || change_source.locally_owned_elements()
             != src.locally_owned_elements())
      {
        discretization.reinit_ghosted_vector(change_source);
        change_owned.reinit(src, true);
      }
    // CG's vectors need not satisfy the constraints; the springs act on
    // the w they stand for (hanging: the masters', supported: zero).
    copy_values(src, change_owned);
    ghosts.distribute(discretization.constraints, change_owned, change_source);
    dst = 0;
    const Statuses &reference =
      since == Since::factorisation ? factorised_status : solved_status;
    for (unsigned int t = 0; t < terms.size(); ++t)
      terms[t]->add_change_product(reference[t],
                                   velocity_factor,
                                   change_source,
                                   dst);
  }


  void
  ActiveSetIteration::save(OutputArchive &archive) const
  {
    archive << matrix_values(matrix) << factorised_status;
    solver.save(archive);
  }


  void
  ActiveSetIteration::load(InputArchive     &archive,
                           const BaseMatrix &write,
                           const double      kappa)
  {
    // The factor is rebuilt from the matrix it was built from, and then
    // the matrix is given the values it had.
    std::vector<double> current;
    archive >> current >> factorised_status;
    write_base      = write;
    velocity_factor = kappa;
    discretization.reinit_matrix(matrix);
    write_base(matrix);
    AssertThrow(factorised_status.size() == terms.size(),
                ExcMessage("The checkpoint holds the statuses of "
                           + std::to_string(factorised_status.size())
                           + " terms where the scene has "
                           + std::to_string(terms.size())
                           + ": it was written for another scene."));
    for (unsigned int t = 0; t < terms.size(); ++t)
      terms[t]->add_to_matrix(factorised_status[t], velocity_factor, matrix);
    solver.load(archive, matrix, discretization, this);
    set_matrix_values(current, matrix);
  }


  void
  ActiveSetIteration::set_base_matrix(const BaseMatrix                  &write,
                                      const double                       kappa,
                                      const std::optional<unsigned int> &key)
  {
    kept_factors.clear();
    key_in_use = key;
    build_and_factorise(write, kappa);
  }


  void
  ActiveSetIteration::switch_base_matrix(const unsigned int key,
                                         const BaseMatrix  &write,
                                         const double       kappa)
  {
    std::optional<FactorCache::Entry> kept = kept_factors.take(key);
    if (key_in_use)
      {
        FactorCache::Entry in_use{*key_in_use,
                                  factorised_status,
                                  velocity_factor,
                                  {}};
        exchange(solver, in_use.factor);
        kept_factors.keep(std::move(in_use));
      }
    key_in_use = key;
    if (!kept)
      return build_and_factorise(write, kappa);
    // The matrix B + K_f(S) for the current S; the factor is exact for it
    // if S is the set it was built with (the same sums give the same
    // values), else it is a stale factor of a changed matrix.
    const bool is_exact =
      Utilities::MPI::min(static_cast<int>(statuses()
                                           == kept->factorised_status),
                          discretization.mpi_communicator)
      == 1;
    {
      SectionTimer::Scope t(timer, "foundation update");
      write_base        = write;
      velocity_factor   = kappa;
      factorised_status = std::move(kept->factorised_status);
      write_base(matrix);
      for (StatusTerm *term : terms)
        term->add_to_matrix({0.0, velocity_factor}, matrix);
    }
    kept->factor.is_exact = is_exact;
    exchange(solver, kept->factor);
    if (!is_exact)
      solver.matrix_changed();
  }


  void
  ActiveSetIteration::save_kept_factors(OutputArchive &archive) const
  {
    const bool         has_key = key_in_use.has_value();
    const unsigned int key     = key_in_use.value_or(0);
    archive << has_key << key;
    kept_factors.save(archive);
  }


  void
  ActiveSetIteration::load_kept_factors(
    InputArchive                                        &archive,
    const std::function<BaseMatrix(const unsigned int)> &write_of_key)
  {
    bool         has_key = false;
    unsigned int key     = 0;
    archive >> has_key >> key;
    // Each factor from the matrix it was built from, as load() does.
    kept_factors.load(archive, [&](FactorCache::Entry &entry) {
      discretization.reinit_matrix(matrix);
      write_of_key(entry.key)(matrix);
      for (unsigned int t = 0; t < terms.size(); ++t)
        terms[t]->add_to_matrix(entry.factorised_status[t],
                                entry.velocity_factor,
                                matrix);
      solver.prepare(matrix, discretization, this);
      exchange(solver, entry.factor);
    });
    key_in_use = has_key ? std::optional<unsigned int>(key) : std::nullopt;
  }


  void
  ActiveSetIteration::build_and_factorise(const BaseMatrix &write,
                                          const double      kappa)
  {
    {
      SectionTimer::Scope t(timer, "foundation update");
      solver.release();
      write_base      = write;
      velocity_factor = kappa;
      discretization.reinit_matrix(matrix);
      write_base(matrix);
      for (StatusTerm *term : terms)
        term->add_to_matrix({0.0, velocity_factor}, matrix);
      factorised_status = statuses_in_matrix();
    }
    solver.prepare(matrix, discretization, this);
  }


  void
  ActiveSetIteration::rebuild_matrix()
  {
    SectionTimer::Scope t(timer, "foundation update");
    write_base(matrix);
    factorised_status = statuses_in_matrix();
    for (unsigned int t = 0; t < terms.size(); ++t)
      terms[t]->add_to_matrix(factorised_status[t], velocity_factor, matrix);
  }


  bool
  ActiveSetIteration::is_solution_of_system(
    const LA::MPI::Vector       &x,
    const LA::MPI::Vector       &b,
    const LinearSolver::Accuracy accuracy) const
  {
    // Only a plate with free edges asks. Its B + K_f(S) is singular exactly
    // when the springs of S do not hold every rigid-body motion (S empty or
    // on a line): decide that from S. A residual test against ||b|| cannot:
    // a soft foundation (Gamma = 1e-8) gives a regular system so
    // ill-conditioned that no solver meets it.
    if (bed->diagnostics().rigid_body_restraint() < 1e-10)
      return false;
    if (accuracy == LinearSolver::Accuracy::trial)
      return true;
    // A net for what a solver may still return: the normwise backward
    // error, which every backward-stable solve meets at any conditioning.
    LA::MPI::Vector residual(b);
    matrix.vmult(residual, x);
    residual -= b;
    // Constrained rows are not equations of the plate (x there follows
    // from other entries).
    discretization.constraints.set_zero(residual);
    const double r     = residual.l2_norm();
    const double scale = matrix.frobenius_norm() * x.l2_norm() + b.l2_norm();
    return std::isfinite(r) && std::isfinite(scale) && r <= 1e-8 * scale;
  }


  const LA::MPI::SparseMatrix &
  ActiveSetIteration::system_matrix() const
  {
    return matrix;
  }


  double
  ActiveSetIteration::refinement_change(const LA::MPI::Vector &x,
                                        const System          &system)
  {
    // The residual, computed in double, carries round-off of the order of
    // eps ||A|| ||x||; the correction it gives is then of the order of the
    // error that the conditioning makes of that round-off.
    const LA::MPI::Vector &system_rhs = with_status_loads(system);
    LA::MPI::Vector        residual(system_rhs), correction(system_rhs);
    matrix.vmult(residual, x);
    residual.sadd(-1.0, 1.0, system_rhs);
    discretization.constraints.set_zero(residual);
    correction = 0;
    solver.solve(correction, residual);
    const double size = x.l2_norm();
    return size > 0 ? correction.l2_norm() / size : 0.0;
  }


  const LA::MPI::Vector &
  ActiveSetIteration::with_status_loads(const System &system)
  {
    if (!has_status_load())
      return system.rhs;
    rhs_with_loads = system.rhs;
    add_status_loads(rhs_with_loads);
    return rhs_with_loads;
  }


  void
  ActiveSetIteration::solve_with_current_set(
    const System                &system,
    LA::MPI::Vector             &solution,
    LA::MPI::Vector             &ghosted_solution,
    const LinearSolver::Accuracy accuracy)
  {
    {
      SectionTimer::Scope t(timer, "foundation update");
      if (count_changes([&](StatusTerm &term) {
            return term.update_matrix(velocity_factor, matrix);
          })
          > 0)
        solver.matrix_changed();
    }
    solver.solve(solution,
                 with_status_loads(system),
                 accuracy,
                 continues_solve);
    // The next solve of this step continues this one if nothing but the
    // statuses change in between: a status load changes with the status,
    // and hanging nodes take their masters' values in the solution
    // (below).
    solved_status   = statuses_in_matrix();
    continues_solve = !has_status_load() && !discretization.has_hanging_nodes();
    ghosts.distribute(discretization.constraints, solution, ghosted_solution);
  }


  std::optional<unsigned long>
  ActiveSetIteration::solve_and_update_set(
    const System                &system,
    LA::MPI::Vector             &solution,
    LA::MPI::Vector             &ghosted_solution,
    const LinearSolver::Accuracy accuracy)
  {
    solve_with_current_set(system, solution, ghosted_solution, accuracy);
    if (system.requires_contact
        && !is_solution_of_system(solution,
                                  with_status_loads(system),
                                  accuracy))
      return {};
    SectionTimer::Scope t(timer, "contact update");
    return count_changes(
      [&](StatusTerm &term) { return term.update_status(ghosted_solution); });
  }


  std::optional<unsigned long>
  ActiveSetIteration::iterate(const System    &system,
                              LA::MPI::Vector &solution,
                              LA::MPI::Vector &ghosted_solution)
  {
    // While the set may still change, a solution only decides the next
    // one; the solve to the full tolerance waits until a set holds, and
    // the set is asked again for its solution.
    const auto                         accuracy = solver.has_looser_trials()
                                                    ? LinearSolver::Accuracy::trial
                                                    : LinearSolver::Accuracy::final;
    const std::optional<unsigned long> n_changed =
      solve_and_update_set(system, solution, ghosted_solution, accuracy);
    if (n_changed && *n_changed == 0
        && accuracy == LinearSolver::Accuracy::trial
        && !solver.last_solve_met_tolerance())
      return solve_and_update_set(system,
                                  solution,
                                  ghosted_solution,
                                  LinearSolver::Accuracy::final);
    return n_changed;
  }


  unsigned int
  ActiveSetIteration::find_in(const std::vector<Statuses> &visited) const
  {
    const Statuses status = statuses();
    for (unsigned int k = 0; k < visited.size(); ++k)
      if (Utilities::MPI::min(static_cast<int>(visited[k] == status),
                              discretization.mpi_communicator)
          == 1)
        return k;
    return visited.size();
  }


  bool
  ActiveSetIteration::has_settled(const unsigned long n_changed,
                                  const Statuses     &start_set)
  {
    // Points whose w_h ends inside the round-off band keep the status they
    // had when the step began. The rule's choice there would otherwise
    // depend on the path of the iteration: the prediction's set, or a
    // trial solution whose error exceeds the band (on the plate of
    // contact_at_round_off_np2, trial solves to 0.5 from the previous set
    // left 6.6 % of it out of contact where full solves kept it in).
    // Restoring it (and solving once more) makes the converged set a
    // function of the step's start alone.
    if (n_changed > 0)
      return false;
    unsigned int t = 0;
    return count_changes([&](StatusTerm &term) {
             return term.keep_status_in_band(start_set[t++]);
           })
           == 0;
  }


  void
  ActiveSetIteration::start_from_prediction(const LA::MPI::Vector &prediction,
                                            LA::MPI::Vector &ghosted_solution)
  {
    // The contact rule applied to the prediction: where the plate is
    // heading.
    SectionTimer::Scope t(timer, "contact update");
    ghosts.copy(prediction, ghosted_solution);
    update_status(ghosted_solution);
  }


  void
  ActiveSetIteration::solve_with_union(const std::vector<Statuses> &visited,
                                       const unsigned int           first,
                                       const System                &system,
                                       LA::MPI::Vector             &solution,
                                       LA::MPI::Vector &ghosted_solution)
  {
    // Springs wherever any set of the cycle had them: the stiffer choice,
    // whose error is a tension in the springs of the points that the
    // solution lifts.
    for (unsigned int t = 0; t < terms.size(); ++t)
      {
        StatusTerm::Status all(visited[first][t].size(), 0);
        for (unsigned int k = first; k < visited.size(); ++k)
          terms[t]->unite(visited[k][t], all);
        terms[t]->set_status(all);
      }
    solve_with_current_set(system, solution, ghosted_solution);
  }


  ActiveSetIteration::Result
  ActiveSetIteration::solve(const System    &system,
                            LA::MPI::Vector &solution,
                            LA::MPI::Vector &ghosted_solution,
                            const bool       guess_is_prediction)
  {
    Assert(matrix.m() > 0, ExcMessage("set_base_matrix() first."));
    Result result;
    continues_solve = false;
    // The set the previous step ended with: the status of points that end
    // in the round-off band.
    const Statuses start_set = statuses();
    if (guess_is_prediction && starts_from_prediction)
      start_from_prediction(solution, ghosted_solution);
    // The sets of this step so far. The solution depends on the set only,
    // so meeting one again means the iteration would go round for ever.
    std::vector<Statuses> visited{statuses()};
    while (result.iterations < max_iterations)
      {
        ++result.iterations;
        const std::optional<unsigned long> n_changed =
          iterate(system, solution, ghosted_solution);
        if (!n_changed)
          {
            result.lost_contact = true;
            return result;
          }
        SectionTimer::Scope t(timer, "contact update");
        if (has_settled(*n_changed, start_set))
          {
            result.converged = true;
            return result;
          }
        if (system.requires_contact
            && bed->diagnostics().contact_area_fraction() == 0.0)
          {
            result.lost_contact = true;
            return result;
          }
        if (cycle_rule == CycleRule::none)
          continue;
        const unsigned int repeated = find_in(visited);
        if (repeated < visited.size())
          {
            result.cycle_length = visited.size() - repeated;
            if (cycle_rule == CycleRule::stop)
              return result;
            t.stop();
            ++result.iterations;
            solve_with_union(
              visited, repeated, system, solution, ghosted_solution);
            result.converged = true;
            return result;
          }
        visited.push_back(statuses());
      }
    return result;
  }
} // namespace liftoff
