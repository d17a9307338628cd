#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <liftoff/discretization.h>
#include <liftoff/linear_algebra.h>
#include <liftoff/linear_solver.h>
#include <liftoff/tensionless_winkler_foundation.h>

namespace liftoff
{
  using namespace dealii;

  /**
   * The iteration of eq. (3.9): solve (B + K_f(S)) u = b with the foundation
   * stiffness of the current contact set S, rebuild S from u at the Gauss
   * points, repeat until S no longer changes. B (plate stiffness plus the
   * time integrator's mass term) is fixed; only K_f is rebuilt, and the
   * system is refactorised only when S has changed since the last
   * factorisation, so a step whose set does not move costs one solve.
   * Its parameters include those of the LinearSolver it owns.
   */
  class ActiveSetIteration
  {
  public:
    struct Result
    {
      unsigned int iterations = 0;
      bool         converged  = false;
      /// Only with requires_contact: the set emptied or the system was
      /// singular, i.e. nothing holds the plate.
      bool lost_contact = false;
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    ActiveSetIteration(const Discretization         &discretization,
                       TensionlessWinklerFoundation &foundation,
                       TimerOutput                  &timer);

    /// Use B from now on (a new mesh or time step).
    void
    set_base_matrix(const LA::MPI::SparseMatrix &B);

    /// The contact set was changed from outside (e.g. activate_all()).
    void
    contact_set_changed();

    /// Solve; `solution` holds the result (owned entries, constraints
    /// distributed) and `ghosted_solution` the same with ghosts.
    Result
    solve(const LA::MPI::Vector &rhs,
          LA::MPI::Vector       &solution,
          LA::MPI::Vector       &ghosted_solution);

    /// Factorisations (or preconditioner set-ups) so far.
    unsigned int
    n_factorisations() const;

    unsigned int max_iterations = 50;
    /// Nothing but the foundation holds the plate (a static free plate):
    /// stop when the contact set empties or the solve is singular.
    bool requires_contact = false;

  private:
    const Discretization         &discretization;
    TensionlessWinklerFoundation &foundation;
    TimerOutput                  &timer;
    const LA::MPI::SparseMatrix  *base_matrix = nullptr;
    LA::MPI::SparseMatrix         foundation_matrix;
    LA::MPI::SparseMatrix         matrix;
    bool                          matrix_is_current = false;
    /// Declared after `matrix`: a factorisation must die before its matrix.
    LinearSolver solver;

    bool
    is_solution_of_system(const LA::MPI::Vector &x,
                          const LA::MPI::Vector &b) const;
  };
} // namespace liftoff
