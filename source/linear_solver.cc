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
                      "direct: sparse LU (factorised only when the matrix "
                      "changes); cg: conjugate gradients with algebraic "
                      "multigrid.");
    prm.declare_entry("Direct solver package",
                      "klu",
                      Patterns::Selection("klu|mumps"),
                      "Trilinos Amesos package for Type = direct.");
    prm.declare_entry("Tolerance",
                      "1e-12",
                      Patterns::Double(0.0, 1.0),
                      "Relative residual at which CG stops.");
    prm.declare_entry("Maximum iterations",
                      "10000",
                      Patterns::Integer(1),
                      "CG iterations before the solve fails.");
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
    tolerance      = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
    AssertThrow(tolerance > 0,
                ExcMessage("Linear solver/Tolerance must lie in (0, 1)."));
  }


  void
  LinearSolver::prepare(const LA::MPI::SparseMatrix &A,
                        const Discretization        &disc)
  {
    matrix = &A;
    ++n_preparations;
    if (type == Type::direct)
      {
        control.set_max_steps(1);
        direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          control,
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
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(A, data);
      }
  }


  void
  LinearSolver::solve(LA::MPI::Vector &x, const LA::MPI::Vector &b)
  {
    Assert(matrix != nullptr, ExcMessage("LinearSolver::prepare() first."));
    if (type == Type::direct)
      {
        direct->solve(x, b);
        return;
      }
    SolverControl             cg_control(max_iterations,
                             std::max(tolerance * b.l2_norm(), 1e-300));
    SolverCG<LA::MPI::Vector> cg(cg_control);
    cg.solve(*matrix, x, b, *amg);
  }
} // namespace liftoff
