#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <liftoff/discretization.h>
#include <liftoff/linear_algebra.h>

#include <memory>

namespace liftoff
{
  using namespace dealii;

  /**
   * Solves A x = b for a matrix that is set up once with `prepare()` and then
   * used for as many right hand sides as needed: a sparse direct
   * factorisation (Trilinos Amesos: KLU or MUMPS) or conjugate gradients
   * with algebraic multigrid (Trilinos ML). Neither assumes that the plate
   * stiffness alone is invertible; the effective matrices of liftoff are
   * made regular by the mass or the foundation.
   */
  class LinearSolver
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Factorise A, or build its preconditioner. A must outlive the solves.
    void
    prepare(const LA::MPI::SparseMatrix &A, const Discretization &disc);

    /// x holds the initial guess for CG on entry.
    void
    solve(LA::MPI::Vector &x, const LA::MPI::Vector &b);

    /// Number of factorisations or preconditioner set-ups so far.
    unsigned int n_preparations = 0;

  private:
    enum class Type
    {
      direct,
      cg
    };
    Type         type           = Type::direct;
    std::string  direct_package = "Amesos_Klu";
    double       tolerance      = 1e-12;
    unsigned int max_iterations = 10000;

    const LA::MPI::SparseMatrix                       *matrix = nullptr;
    SolverControl                                      control;
    std::unique_ptr<TrilinosWrappers::SolverDirect>    direct;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
  };
} // namespace liftoff
