#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_cg.h>

#include <liftoff/linear_solver.h>

namespace liftoff
{
  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type",
                      "direct",
                      Patterns::Selection("direct|cg"),
                      "direct: sparse LU, factorised once and then used to "
                      "precondition CG on the changed matrices; cg: "
                      "conjugate gradients with algebraic multigrid.");
    prm.declare_entry("Direct solver package",
                      "mumps",
                      Patterns::Selection("klu|mumps"),
                      "Trilinos Amesos package for Type = direct. MUMPS "
                      "factorises in parallel; KLU gathers the matrix on "
                      "one rank.");
    prm.declare_entry("Refactorisation threshold",
                      "8",
                      Patterns::Integer(0),
                      "Type = direct: when CG preconditioned with the stored "
                      "factor needs more than this many iterations for a "
                      "changed matrix, the matrix is factorised anew. 0 "
                      "factorises at every change.");
    prm.declare_entry("Tolerance",
                      "1e-12",
                      Patterns::Double(0.0, 1.0),
                      "Relative residual at which CG stops.");
    prm.declare_entry("Maximum iterations",
                      "10000",
                      Patterns::Integer(1),
                      "CG iterations before the solve fails (Type = cg).");
    prm.leave_subsection();
  }


  void
  LinearSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    type = (prm.get("Type") == "direct" ? Type::direct : Type::cg);
    direct_package =
      (prm.get("Direct solver package") == "klu" ? "Amesos_Klu"
                                                 : "Amesos_Mumps");
    refactorisation_threshold = prm.get_integer("Refactorisation threshold");
    tolerance                 = prm.get_double("Tolerance");
    max_iterations            = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
    AssertThrow(tolerance > 0,
                ExcMessage("Linear solver/Tolerance must lie in (0, 1)."));
  }


  LinearSolver::LinearSolver(TimerOutput &timer)
      : timer(timer)
  {
    substitution_timer.stop();
    substitution_timer.reset();
  }


  void
  LinearSolver::prepare(const LA::MPI::SparseMatrix &A,
                        const Discretization        &disc)
  {
    TimerOutput::Scope t(timer, "factorisation");
    matrix         = &A;
    discretization = &disc;
    ++n_preparations;
    factor_is_exact = true;
    if (keeps_prepared_values)
      prepared_values = matrix_values(A);
    if (type == Type::direct)
      {
        // Release the old factor before the new one is built.
        direct.reset();
        direct_control.set_max_steps(1);
        direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          direct_control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         direct_package));
        direct->initialize(A);
      }
    else
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = (disc.degree() > 1);
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        DoFTools::extract_constant_modes(disc.dof_handler,
                                         ComponentMask(),
                                         data.constant_modes);
        amg.reset();
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(A, data);
      }
  }


  void
  LinearSolver::matrix_changed()
  {
    factor_is_exact = false;
  }


  void
  LinearSolver::vmult(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const
  {
    substitution_timer.start();
    direct->solve(dst, src);
    substitution_timer.stop();
    ++n_substitutions;
  }


  unsigned int
  LinearSolver::conjugate_gradients(LA::MPI::Vector       &x,
                                    const LA::MPI::Vector &b,
                                    const unsigned int     max_steps)
  {
    SolverControl             control(max_steps,
                          std::max(tolerance * b.l2_norm(), 1e-300),
                          false,
                          false);
    SolverCG<LA::MPI::Vector> cg(control);
    try
      {
        if (type == Type::direct)
          cg.solve(*matrix, x, b, *this);
        else
          cg.solve(*matrix, x, b, *amg);
      }
    catch (const SolverControl::NoConvergence &)
      {
        n_cg_iterations += control.last_step();
        throw;
      }
    n_cg_iterations += control.last_step();
    return control.last_step();
  }


  unsigned int
  LinearSolver::solve(LA::MPI::Vector &x, const LA::MPI::Vector &b)
  {
    Assert(matrix != nullptr, ExcMessage("LinearSolver::prepare() first."));
    if (type == Type::cg)
      {
        TimerOutput::Scope t(timer, "solve");
        return conjugate_gradients(x, b, max_iterations);
      }

    if (!factor_is_exact && refactorisation_threshold > 0)
      {
        TimerOutput::Scope t(timer, "solve");
        try
          {
            return conjugate_gradients(x, b, refactorisation_threshold);
          }
        catch (const SolverControl::NoConvergence &)
          {
            // Too far from the factorised matrix (or singular): factorise
            // the matrix as it is and substitute, which overwrites x.
          }
      }
    if (!factor_is_exact)
      prepare(*matrix, *discretization);
    TimerOutput::Scope t(timer, "solve");
    vmult(x, b);
    return 0;
  }


  void
  LinearSolver::save(OutputArchive &archive) const
  {
    AssertThrow(keeps_prepared_values && matrix != nullptr,
                ExcMessage("LinearSolver::save() needs keeps_prepared_values "
                           "and a prepared matrix."));
    archive << factor_is_exact << prepared_values;
  }


  void
  LinearSolver::load(InputArchive          &archive,
                     LA::MPI::SparseMatrix &A,
                     const Discretization  &disc)
  {
    bool                exact = false;
    std::vector<double> values;
    archive >> exact >> values;
    set_matrix_values(values, A);
    prepare(A, disc);
    factor_is_exact = exact;
  }
} // namespace liftoff
