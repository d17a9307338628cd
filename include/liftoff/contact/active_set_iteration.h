#pragma once

#include <deal.II/base/parameter_handler.h>
#include <liftoff/base/section_timer.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/active_set_result.h>
#include <liftoff/contact/bed.h>
#include <liftoff/contact/status_term.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/solver/factor_cache.h>
#include <liftoff/solver/ghost_update.h>
#include <liftoff/solver/linear_solver.h>

#include <functional>
#include <optional>

namespace liftoff
{
  using namespace dealii;

  /**
   * The iteration of eq. (3.9): solve (B + K_f(S)) u = b with the foundation
   * stiffness of the current contact set S, rebuild S from u at the Gauss
   * points, repeat until S no longer changes. S stands for the statuses of
   * all the system's terms that have one (StatusTerm: the foundation, and
   * the dowels of a jointed plate), driven together: one solve, then each
   * term's status from it, until none changes. B (plate stiffness plus the
   * time integrator's mass term) is fixed for a mesh and time step; the
   * system matrix B + K_f(S) is built and factorised once and afterwards
   * only the springs of the Gauss points whose status flipped are added or
   * removed, and the LinearSolver reuses its factor. A step whose set does
   * not move costs one substitution.
   * The LinearSolver it owns reads its own parameters (`Linear solver`).
   */
  class ActiveSetIteration : private ChangingMatrix
  {
  public:
    using Result = ActiveSetResult;

    /// What to do when the set returns to one it had earlier in the step.
    enum class CycleRule
    {
      /// Solve once with the union of the sets of the cycle (every point
      /// in contact in any of them) and accept that; see doc/model.md.
      union_of_cycle,
      /// Report it as not converged: the run stops with an error.
      stop,
      /// Do not look for cycles: iterate up to max_iterations (to show
      /// that a cycle found is one).
      none
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    ActiveSetIteration(const Discretization &discretization,
                       SectionTimer         &timer);

    /// The terms of the plate's system (SceneParts::system_terms()): it
    /// drives those with a status, in their order, and asks the bed
    /// whether the plate is held (before the first set_base_matrix()).
    void
    use_terms(const std::vector<SystemTerm *> &system_terms);

    /// Every term's status from `ghosted_u` (a state, not a solve; the
    /// bed's pressure is the state's, Bed::use_pressure()).
    void
    update_status(const LA::MPI::Vector &ghosted_u);
    /// vector += the terms' loads of their statuses (their forces' parts
    /// that do not depend on u).
    void
    add_status_loads(LA::MPI::Vector &vector) const;
    /// The sum of the terms' StatusTerm::status_load_work().
    double
    status_load_work(const LA::MPI::Vector &ghosted_u) const;

    /// Writes the values of B into a matrix of the plate's pattern
    /// (Discretization::reinit_matrix), replacing all it held.
    using BaseMatrix = std::function<void(LA::MPI::SparseMatrix &)>;

    /// Use B from now on (a new mesh or time step): builds B + K_f(S) for
    /// the current set and factorises it, K_f with the springs' stiffness
    /// Gamma + c kappa, kappa = `velocity_factor` (0 for a static solve,
    /// gamma / (beta dt) for a time step: the velocity of the unknown is
    /// kappa u + ...). B is written into the system matrix itself, so no
    /// second matrix of the plate's size is alive while the factor is
    /// built (L: 330 MB of the peak). Drops the kept factors (a new mesh);
    /// `key` names the factor for switch_base_matrix().
    void
    set_base_matrix(const BaseMatrix                  &write_base,
                    const double                       velocity_factor,
                    const std::optional<unsigned int> &key = {});
    /// set_base_matrix() for one of a few B that take turns, named by
    /// `key` (a time step's level): the factor in use is kept (if it has a
    /// key), and a B whose factor is kept is not factorised again: its
    /// factor, of B + K_f(S') for the S' it was built with, serves the
    /// matrix B + K_f(S) as a stale factor does.
    void
    switch_base_matrix(const unsigned int key,
                       const BaseMatrix  &write_base,
                       const double       velocity_factor);
    /// The kept factors: what builds them again and their state, and the
    /// key in use. Before save() and load(); `write_of_key` gives the B of
    /// a key.
    void
    save_kept_factors(OutputArchive &archive) const;
    void
    load_kept_factors(
      InputArchive                                        &archive,
      const std::function<BaseMatrix(const unsigned int)> &write_of_key);

    /// What one solve needs besides the matrix: the right-hand side b
    /// (the terms' status loads join it; the bed's for the pressure k (w -
    /// e) of the unknown's velocity, Bed::use_pressure()), and whether
    /// nothing but the foundation holds the plate (a static free plate):
    /// then stop when the contact set empties or the solve is singular.
    struct System
    {
      const LA::MPI::Vector &rhs;
      bool                   requires_contact = false;
    };

    /// Solve; `solution` holds the initial guess on entry and the result
    /// on exit (owned entries, constraints distributed), `ghosted_solution`
    /// the same with ghosts. With `guess_is_prediction` (a time step's
    /// predictor) and `Initial set = predicted`, the iteration starts from
    /// the guess's contact set rather than the foundation's current one.
    Result
    solve(const System    &system,
          LA::MPI::Vector &solution,
          LA::MPI::Vector &ghosted_solution,
          const bool       guess_is_prediction = false);

    /// The linear solver, for its counters and its parameters.
    const LinearSolver &
    linear_solver() const;
    LinearSolver &
    linear_solver();

    /// B + K_f(S) for the current S.
    const LA::MPI::SparseMatrix &
    system_matrix() const;

    /// The system matrix B + K_f(S) as it is, round-off included, and the
    /// set of the matrix the solver's factor was built from.
    void
    save(OutputArchive &archive) const;
    /// Instead of set_base_matrix(): the matrix and factor of save(), with
    /// the B and kappa that were given to set_base_matrix() then. The
    /// foundation's own status must be loaded first.
    void
    load(InputArchive     &archive,
         const BaseMatrix &write_base,
         const double      velocity_factor);

    unsigned int max_iterations = 50;
    CycleRule    cycle_rule     = CycleRule::union_of_cycle;
    /// `Initial set = predicted`.
    bool starts_from_prediction = true;
    /// The change one step of iterative refinement makes to x, the solution
    /// of the last solve, of `system`, relative to x: an estimate of the
    /// forward error that the residual tests cannot see in a system near
    /// the limit of double precision (collective).
    double
    refinement_change(const LA::MPI::Vector &x, const System &system);

  private:
    using Statuses = std::vector<StatusTerm::Status>;

    const Discretization &discretization;
    /// The term the plate rests on, and the terms with a status.
    const Bed                *bed = nullptr;
    std::vector<StatusTerm *> terms;
    SectionTimer             &timer;
    /// B + K_f(S), kept in step with S.
    LA::MPI::SparseMatrix matrix;
    BaseMatrix            write_base;
    /// kappa of the matrix's K_f (set_base_matrix()).
    double velocity_factor = 0;
    /// The S of the matrix the solver's factor was built from, which
    /// B + K_f(S) gives again bit for bit (by rebuild_matrix()).
    Statuses factorised_status;
    /// Declared after `matrix`: a factorisation must die before its matrix.
    LinearSolver solver;
    /// Factors of other B (switch_base_matrix()), at most 4: one per time
    /// step size, as many as a run moves between; and the key of the one
    /// in use. After `solver`, whose direct solver's control they share.
    FactorCache                 kept_factors{4};
    std::optional<unsigned int> key_in_use;
    /// rhs + f_g(S) when the foundation has a gap.
    LA::MPI::Vector rhs_with_loads;
    /// The vector the solver multiplies by the change of the matrix since
    /// its factorisation or last solve, with its constraints applied, and
    /// with ghosts.
    LA::MPI::Vector change_owned, change_source;
    /// The S of the matrix at the last solve.
    Statuses solved_status;
    /// The next solve may continue the last one (LinearSolver::solve()).
    bool continues_solve = false;

    /// Build B + K_f(S) for the current S and factorise it.
    void
    build_and_factorise(const BaseMatrix &write, const double kappa);
    /// B + K_f(S) for the S the matrix holds, written afresh (before a
    /// factorisation: the factor is then of a matrix that can be built
    /// again from B and S).
    void
    rebuild_matrix() override;
    /// The springs whose status changed since the factorisation or the last
    /// solve, times src (constraints applied to src first).
    void
    multiply_by_change(const LA::MPI::Vector &src,
                       LA::MPI::Vector       &dst,
                       const Since            since) override;

    /// The right-hand side of the system for the current set: its rhs,
    /// plus the terms' status loads (the springs' push on a gap f_g(S),
    /// loose dowels' offsets), with which the reaction is affine.
    const LA::MPI::Vector &
    with_status_loads(const System &system);
    /// The solution's copies to its ghosted form, with one import kept.
    GhostUpdate ghosts;

    /// Whether x solves the system to the accuracy it was asked for: a
    /// `trial` solution is only checked for a set that holds the plate.
    bool
    is_solution_of_system(const LA::MPI::Vector &x,
                          const LA::MPI::Vector &b,
                          LinearSolver::Accuracy accuracy) const;

    /// Bring the matrix in step with the foundation's set and solve.
    void
    solve_with_current_set(
      const System          &system,
      LA::MPI::Vector       &solution,
      LA::MPI::Vector       &ghosted_solution,
      LinearSolver::Accuracy accuracy = LinearSolver::Accuracy::final);

    /// solve_with_current_set() and the contact rule applied to the
    /// solution: the number of statuses changed, or no value when the
    /// solution is not one of the system (a plate that needs contact has
    /// lost it). Collective.
    std::optional<unsigned long>
    solve_and_update_set(const System          &system,
                         LA::MPI::Vector       &solution,
                         LA::MPI::Vector       &ghosted_solution,
                         LinearSolver::Accuracy accuracy);

    /// One iterate: solve_and_update_set(), with a trial solve whose set
    /// held repeated to the full tolerance.
    std::optional<unsigned long>
    iterate(const System    &system,
            LA::MPI::Vector &solution,
            LA::MPI::Vector &ghosted_solution);

    /// No status changed in the last update, and none within the round-off
    /// band differs from `start_set`, the set the step began with (those
    /// are restored). Collective.
    bool
    has_settled(const unsigned long n_changed, const Statuses &start_set);
    /// Give the foundation the set the contact rule gives the prediction
    /// (ghosted_solution is set to it).
    void
    start_from_prediction(const LA::MPI::Vector &prediction,
                          LA::MPI::Vector       &ghosted_solution);
    /// Solve with the union of the sets visited[first], ... (a cycle).
    void
    solve_with_union(const std::vector<Statuses> &visited,
                     const unsigned int           first,
                     const System                &system,
                     LA::MPI::Vector             &solution,
                     LA::MPI::Vector             &ghosted_solution);
    /// Index of the statuses in `visited` equal to the terms' current ones
    /// on every rank, or visited.size().
    unsigned int
    find_in(const std::vector<Statuses> &visited) const;
    /// The terms' statuses, and those their matrix entries hold.
    Statuses
    statuses() const;
    Statuses
    statuses_in_matrix() const;
    /// The number of statuses changed (over all ranks) by `change` applied
    /// to each term.
    unsigned long
    count_changes(const std::function<unsigned long(StatusTerm &)> &change);
    /// Whether some term has a load of its status.
    bool
    has_status_load() const;
  };
} // namespace liftoff
