#include <liftoff/active_set_iteration.h>

#include <cmath>

namespace liftoff
{
  void
  ActiveSetIteration::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Active set");
    prm.declare_entry("Maximum iterations",
                      "50",
                      Patterns::Integer(1),
                      "Iterations of eq. (3.9) per step before the run stops "
                      "with an error naming the step.");
    prm.leave_subsection();
    LinearSolver::declare_parameters(prm);
  }


  void
  ActiveSetIteration::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Active set");
    max_iterations = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
    solver.parse_parameters(prm);
  }


  const LinearSolver &
  ActiveSetIteration::linear_solver() const
  {
    return solver;
  }


  ActiveSetIteration::ActiveSetIteration(
    const Discretization         &discretization,
    TensionlessWinklerFoundation &foundation,
    TimerOutput                  &timer)
      : discretization(discretization)
      , foundation(foundation)
      , timer(timer)
      , solver(timer)
  {}


  void
  ActiveSetIteration::prepare_for_checkpoints()
  {
    solver.keeps_prepared_values = true;
  }


  void
  ActiveSetIteration::save(OutputArchive &archive) const
  {
    archive << matrix_values(matrix);
    solver.save(archive);
  }


  void
  ActiveSetIteration::load(InputArchive                &archive,
                           const LA::MPI::SparseMatrix &B)
  {
    // The same structure as set_base_matrix() builds; the values follow.
    discretization.reinit_matrix(matrix);
    matrix.copy_from(B);
    std::vector<double> current;
    archive >> current;
    solver.load(archive, matrix, discretization);
    set_matrix_values(current, matrix);
  }


  void
  ActiveSetIteration::set_base_matrix(const LA::MPI::SparseMatrix &B)
  {
    {
      TimerOutput::Scope t(timer, "foundation update");
      discretization.reinit_matrix(matrix);
      matrix.copy_from(B);
      foundation.add_to_matrix(matrix);
    }
    solver.prepare(matrix, discretization);
  }


  bool
  ActiveSetIteration::is_solution_of_system(const LA::MPI::Vector &x,
                                            const LA::MPI::Vector &b) const
  {
    // A singular matrix gives a direct solver no error, only a wrong or
    // non-finite x: check the residual.
    LA::MPI::Vector residual(b);
    matrix.vmult(residual, x);
    residual -= b;
    const double r = residual.l2_norm();
    return std::isfinite(r) && r <= 1e-8 * b.l2_norm();
  }


  ActiveSetIteration::Result
  ActiveSetIteration::solve(const LA::MPI::Vector &rhs,
                            LA::MPI::Vector       &solution,
                            LA::MPI::Vector       &ghosted_solution)
  {
    Assert(matrix.m() > 0, ExcMessage("set_base_matrix() first."));
    Result result;
    while (result.iterations < max_iterations)
      {
        ++result.iterations;
        {
          TimerOutput::Scope t(timer, "foundation update");
          if (foundation.update_matrix(matrix) > 0)
            solver.matrix_changed();
        }
        solver.solve(solution, rhs);
        discretization.constraints.distribute(solution);
        ghosted_solution = solution;
        if (requires_contact && !is_solution_of_system(solution, rhs))
          {
            result.lost_contact = true;
            return result;
          }
        TimerOutput::Scope  t(timer, "contact update");
        const unsigned long n_changed =
          foundation.update_contact_status(ghosted_solution);
        if (n_changed == 0)
          {
            result.converged = true;
            return result;
          }
        if (requires_contact && foundation.contact_area_fraction() == 0.0)
          {
            result.lost_contact = true;
            return result;
          }
      }
    return result;
  }
} // namespace liftoff
