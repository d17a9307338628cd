#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_control.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/selection.h>
#include <liftoff/solver/cholesky_factor.h>
#include <liftoff/solver/linear_solver.h>
#include <liftoff/solver/mumps_cholesky_factor.h>

#include <Epetra_Comm.h>
#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <tuple>

namespace liftoff
{
  namespace
  {
    const Selection<LinearSolver::Type> types =
      {{"direct", LinearSolver::Type::direct}, {"cg", LinearSolver::Type::cg}};
    const Selection<LinearSolver::Package> packages = {
      {"cholmod", LinearSolver::Package::cholmod},
      {"mumps", LinearSolver::Package::mumps},
      {"mumps lu", LinearSolver::Package::mumps_lu},
      {"klu", LinearSolver::Package::klu}};
  } // namespace


  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type",
                      "direct",
                      types.pattern(),
                      "direct: sparse LU, factorised once and then used to "
                      "precondition CG on the changed matrices; cg: "
                      "conjugate gradients with algebraic multigrid.");
    prm.declare_entry(
      "Direct solver package",
      "cholmod",
      packages.pattern(),
      "Factorisation for Type = direct. cholmod: a sparse Cholesky factor, "
      "CHOLMOD's (SuiteSparse) on one rank, the fastest there; CHOLMOD is "
      "serial, so on several ranks MUMPS's Cholesky factor. mumps: MUMPS's "
      "Cholesky factor (symmetric positive definite mode) on any number of "
      "ranks, factorised in parallel. With either, a matrix that is not "
      "positive definite is factorised with MUMPS's LU instead. mumps lu: "
      "Trilinos Amesos MUMPS, an LU (twice the factor of a Cholesky one) "
      "factorised in parallel. klu: Trilinos Amesos KLU, an LU that gathers "
      "the matrix on one rank.");
    prm.declare_entry("Refactorisation threshold",
                      "8",
                      Patterns::Integer(0),
                      "Type = direct: when CG preconditioned with the stored "
                      "factor needs more than this many iterations for a "
                      "changed matrix, the matrix is factorised anew. 0 "
                      "factorises at every change."
                        + quantity("number"));
    prm.declare_entry("Tolerance",
                      "1e-12",
                      Patterns::Double(0.0, 1e-3),
                      "Relative residual at which CG stops (at most 1e-3: "
                      "at 0.1 the energy balance of a point load on a quarter "
                      "plate was off by 0.96 of its energies)."
                        + quantity("number"));
    prm.declare_entry(
      "Trial tolerance",
      "1e-6",
      Patterns::Double(0.0, 1.0),
      "Type = direct: relative residual at which CG stops while the contact "
      "set may still change; such a solution only decides the next set. "
      "Once a set holds, the solve is continued to `Tolerance` and the set "
      "asked again, so the answer keeps `Tolerance`, and points that end "
      "within the contact tolerance's round-off band keep the status they "
      "had when the step began, whatever a trial solution gave them. One "
      "CG iteration preconditioned by the stored factor mostly meets 1e-6, "
      "so a solve whose set changes costs one substitution instead of two. "
      "Values at or below `Tolerance` solve every time to `Tolerance`. "
      "Type = cg always solves to `Tolerance`: with AMG a trial error "
      "flips points at round-off and costs iterations."
        + quantity("number"));
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
    type    = types.parse(prm.get("Type"), "Linear solver/Type");
    package = packages.parse(prm.get("Direct solver package"),
                             "Linear solver/Direct solver package");
    refactorization_threshold = prm.get_integer("Refactorisation threshold");
    tolerance                 = prm.get_double("Tolerance");
    trial_tolerance           = prm.get_double("Trial tolerance");
    max_iterations            = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
    AssertThrow(tolerance > 0,
                ExcMessage("Linear solver/Tolerance must lie in (0, 1e-3]."));
  }


  LinearSolver::LinearSolver(SectionTimer &timer)
      : timer(timer)
  {}


  LinearSolver::~LinearSolver() = default;


  std::string
  LinearSolver::factor_name() const
  {
    if (cholesky)
      return "CHOLMOD Cholesky";
    if (mumps_cholesky)
      return "MUMPS Cholesky";
    if (direct)
      return package == Package::klu ? "KLU LU" : "MUMPS LU";
    return type == Type::cg ? "none (CG + AMG)" : "none";
  }


  MemoryEstimate::Factor
  LinearSolver::factor_placement() const
  {
    if (type == Type::cg)
      return MemoryEstimate::Factor::none;
    if (package == Package::klu)
      return MemoryEstimate::Factor::lu_on_rank_0;
    return package == Package::mumps_lu ? MemoryEstimate::Factor::lu
                                        : MemoryEstimate::Factor::cholesky;
  }


  void
  LinearSolver::release()
  {
    direct.reset();
    cholesky.reset();
    mumps_cholesky.reset();
    amg.reset();
  }


  void
  LinearSolver::prepare(const LA::MPI::SparseMatrix &A,
                        const Discretization        &disc,
                        ChangingMatrix              *changes_of_A)
  {
    SectionTimer::Scope t(timer, "factorisation");
    changes        = changes_of_A;
    matrix         = &A;
    discretization = &disc;
    ++n_preparations;
    factor_is_exact     = true;
    cg_excess_flops     = 0;
    substitution_error  = -1;
    residual_is_current = false;
    if (type == Type::direct)
      factorize(A);
    else
      build_multigrid(A, disc);
  }


  void
  LinearSolver::factorize(const LA::MPI::SparseMatrix &A)
  {
    // Release the old factor before the new one is built.
    direct.reset();
    cholesky.reset();
    mumps_cholesky.reset();
    // The number of ranks is the same on all of them, and so is the test
    // of positive definiteness (CHOLMOD's on one rank, MUMPS's global
    // status), so every rank takes the same branch.
    const bool one_rank = A.trilinos_matrix().Comm().NumProc() == 1;
    if (package == Package::cholmod && one_rank)
      {
        cholesky = std::make_unique<CholeskyFactor>();
        if (cholesky->factorize(A.trilinos_matrix()))
          return;
        cholesky.reset();
        report_fallback("CHOLMOD");
      }
    else if (package == Package::cholmod || package == Package::mumps)
      {
        mumps_cholesky =
          std::make_unique<MumpsCholeskyFactor>(A.get_mpi_communicator());
        if (mumps_cholesky->factorize(A))
          return;
        mumps_cholesky.reset();
        report_fallback("MUMPS's Cholesky factorisation");
      }
    direct_control.set_max_steps(1);
    direct = std::make_unique<TrilinosWrappers::SolverDirect>(
      direct_control,
      TrilinosWrappers::SolverDirect::AdditionalData(
        false, package == Package::klu ? "Amesos_Klu" : "Amesos_Mumps"));
    direct->initialize(A);
  }


  void
  LinearSolver::build_multigrid(const LA::MPI::SparseMatrix &A,
                                const Discretization        &disc)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = (disc.element().degree() > 1);
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 0.02;
    DoFTools::extract_constant_modes(disc.dof_handler,
                                     ComponentMask(),
                                     data.constant_modes);
    amg.reset();
    amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    amg->initialize(A, data);
  }


  void
  LinearSolver::report_fallback(const std::string &factorisation)
  {
    if (!has_reported_fallback
        && Utilities::MPI::this_mpi_process(matrix->get_mpi_communicator())
             == 0)
      std::cout << "liftoff: " << factorisation
                << " found the system matrix not positive definite; "
                   "factorising it with MUMPS's LU instead."
                << std::endl;
    has_reported_fallback = true;
  }


  void
  LinearSolver::matrix_changed()
  {
    factor_is_exact = false;
    // A factorisation now would pay only for the solves with the matrix as
    // it is now.
    cg_excess_flops = 0;
  }


  void
  LinearSolver::vmult(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const
  {
    substitution_timer.start();
    if (cholesky)
      cholesky->substitute(dst.begin(), src.begin());
    else if (mumps_cholesky)
      mumps_cholesky->substitute(dst, src);
    else
      direct->solve(dst, src);
    substitution_timer.stop();
    ++n_substitutions;
  }


  double
  LinearSolver::relative_tolerance() const
  {
    return tolerance;
  }


  bool
  LinearSolver::has_looser_trials() const
  {
    return type == Type::direct && trial_tolerance > tolerance;
  }


  bool
  LinearSolver::last_solve_met_tolerance() const
  {
    return met_tolerance;
  }


  void
  LinearSolver::reinit_cg_vectors(const LA::MPI::Vector &b)
  {
    for (LA::MPI::Vector *v : {&r, &z, &p, &q, &change_product})
      if (v->size() != b.size()
          || v->locally_owned_elements() != b.locally_owned_elements())
        {
          v->reinit(b, true);
          residual_is_current = false;
        }
  }


  void
  LinearSolver::whole_residual(const LA::MPI::Vector &x,
                               const LA::MPI::Vector &b)
  {
    matrix->vmult(r, x);
    ++n_products;
    r.sadd(-1.0, 1.0, b);
  }


  void
  LinearSolver::derived_product(const double beta)
  {
    changes->multiply_by_change(z,
                                change_product,
                                ChangingMatrix::Since::factorisation);
    if (beta == 0.0)
      q = r;
    else
      q.sadd(beta, 1.0, r);
    q += change_product;
  }


  void
  LinearSolver::whole_product(const bool   measures_substitution,
                              const double residual)
  {
    matrix->vmult(q, p);
    ++n_products;
    if (measures_substitution)
      {
        // q = A z here: its distance from r + (A - A_f) z is A_f z - r, the
        // substitution's residual.
        changes->multiply_by_change(z,
                                    change_product,
                                    ChangingMatrix::Since::factorisation);
        change_product += r;
        change_product -= q;
        substitution_error = change_product.l2_norm() / residual;
      }
  }


  // Preconditioned CG, as deal.II's SolverCG, with products with the whole
  // matrix only where they are needed. With the stored factor of A_f as
  // preconditioner, z = A_f^{-1} r, so A z = r + (A - A_f) z, and with p =
  // z + beta p_old, A p = r + (A - A_f) z + beta A p_old: a product with the
  // change of the springs since the factorisation, a few cells, instead of
  // one with A (M: 7 ms). And a solve that continues the previous one (same
  // x and b, A changed by the springs since) starts from its residual:
  // b - A x = r_old - (A - A_old) x. Both hold as far as the substitution
  // does; its error |A_f z - r| / |r| is measured in the first iteration
  // after a factorisation, where both products are formed, and they are
  // used only if it is below a tenth of `Tolerance`. A solution that such a
  // solve claims to meet `Tolerance` is checked with a product with A (M:
  // the true residual was 1e-14 where the recursive one was 1e-17), and CG
  // goes on with whole products if the check fails.
  unsigned int
  LinearSolver::conjugate_gradients(LA::MPI::Vector       &x,
                                    const LA::MPI::Vector &b,
                                    const unsigned int     max_steps,
                                    const double           relative_tolerance,
                                    const bool             continues)
  {
    const double b_norm = b.l2_norm();
    const double target = std::max(relative_tolerance * b_norm, 1e-300);
    reinit_cg_vectors(b);
    CGProgress cg;
    cg.can_use_change = type == Type::direct && changes != nullptr;
    cg.uses_change    = cg.can_use_change && substitution_error >= 0
                     && substitution_error <= 0.1 * tolerance;
    if (continues && cg.uses_change && residual_is_current)
      {
        changes->multiply_by_change(x,
                                    change_product,
                                    ChangingMatrix::Since::last_solve);
        r -= change_product;
        cg.is_derived = true;
      }
    else
      whole_residual(x, b);
    residual_is_current = false;
    cg.residual         = r.l2_norm();
    while (true)
      {
        iterate_to(target, max_steps, x, cg);
        if (!cg.is_derived || cg.residual > tolerance * b_norm)
          break;
        whole_residual(x, b);
        cg.residual   = r.l2_norm();
        cg.is_derived = false;
        if (cg.residual <= target)
          break;
        // Not met after all: on with whole products, from this residual.
        ++n_failed_checks;
        cg.uses_change = false;
        cg.restart     = cg.step;
      }
    n_cg_iterations += cg.step;
    residual_is_current = true;
    // The residual norm is a reduction over all ranks: every rank decides
    // alike.
    met_tolerance = cg.residual <= tolerance * b_norm;
    return cg.step;
  }


  void
  LinearSolver::iterate_to(const double       target,
                           const unsigned int max_steps,
                           LA::MPI::Vector   &x,
                           CGProgress        &cg)
  {
    while (cg.residual > target)
      {
        if (cg.step == max_steps)
          {
            n_cg_iterations += cg.step;
            throw SolverControl::NoConvergence(cg.step, cg.residual);
          }
        ++cg.step;
        if (type == Type::direct)
          vmult(z, r);
        else
          amg->vmult(z, r);
        const double rz   = r * z;
        const double beta = cg.step == cg.restart + 1 ? 0.0 : rz / cg.rz_old;
        if (beta == 0.0)
          p = z;
        else
          p.sadd(beta, 1.0, z);
        if (cg.uses_change)
          {
            derived_product(beta);
            cg.is_derived = true;
          }
        else
          whole_product(cg.can_use_change && substitution_error < 0
                          && beta == 0.0,
                        cg.residual);
        const double alpha = rz / (p * q);
        x.add(alpha, p);
        r.add(-alpha, q);
        cg.residual = r.l2_norm();
        cg.rz_old   = rz;
      }
  }


  unsigned int
  LinearSolver::solve(LA::MPI::Vector       &x,
                      const LA::MPI::Vector &b,
                      const Accuracy         accuracy,
                      const bool             continues)
  {
    const double relative_tolerance = accuracy == Accuracy::trial
                                        ? std::max(trial_tolerance, tolerance)
                                        : tolerance;
    Assert(matrix != nullptr, ExcMessage("LinearSolver::prepare() first."));
    if (type == Type::cg)
      {
        SectionTimer::Scope t(timer, "solve");
        return conjugate_gradients(
          x, b, max_iterations, relative_tolerance, continues);
      }

    // With the matrix unchanged since its last solves, CG costs more than
    // the one substitution a fresh factor would: when that excess has added
    // up to the price of a factorisation, factorising pays (the rule of
    // renting skis until their price has been paid, at most twice the cost
    // of the best choice made in hindsight). A change of the matrix starts
    // the count anew, since a factor of the old one would not have helped.
    // Counted in floating-point operations, so the choice is the same in
    // every run and a resumed run repeats it. Only CHOLMOD reports the
    // counts.
    if (!factor_is_exact && cholesky
        && cg_excess_flops >= cholesky->factorization_cost())
      refactorise();
    if (!factor_is_exact && refactorization_threshold > 0)
      {
        SectionTimer::Scope t(timer, "solve");
        const unsigned long products_before = n_products;
        try
          {
            const unsigned int n = conjugate_gradients(
              x, b, refactorization_threshold, relative_tolerance, continues);
            if (cholesky)
              cg_excess_flops +=
                (std::max(n, 1u) - 1.0) * cholesky->substitution_flops()
                + (n_products - products_before) * 2.0
                    * matrix->trilinos_matrix().NumGlobalNonzeros();
            return n;
          }
        catch (const SolverControl::NoConvergence &)
          {
            // Too far from the factorised matrix (or singular): factorise
            // the matrix as it is and substitute, which overwrites x.
          }
      }
    if (!factor_is_exact)
      refactorise();
    SectionTimer::Scope t(timer, "solve");
    vmult(x, b);
    met_tolerance       = true;
    residual_is_current = false;
    return 0;
  }


  void
  LinearSolver::refactorise()
  {
    if (changes != nullptr)
      changes->rebuild_matrix();
    prepare(*matrix, *discretization, changes);
  }


  KeptFactor::KeptFactor()                       = default;
  KeptFactor::KeptFactor(KeptFactor &&) noexcept = default;
  KeptFactor &
  KeptFactor::operator=(KeptFactor &&) noexcept = default;
  KeptFactor::~KeptFactor()                     = default;


  void
  exchange(LinearSolver &solver, KeptFactor &kept)
  {
    std::swap(solver.direct, kept.direct);
    std::swap(solver.cholesky, kept.cholesky);
    std::swap(solver.mumps_cholesky, kept.mumps_cholesky);
    std::swap(solver.amg, kept.amg);
    std::swap(solver.factor_is_exact, kept.is_exact);
    std::swap(solver.cg_excess_flops, kept.cg_excess_flops);
    std::swap(solver.substitution_error, kept.substitution_error);
    // CG's residual belongs to the last solve, with the other factor.
    solver.residual_is_current = false;
    solver.met_tolerance       = false;
  }


  void
  LinearSolver::save(OutputArchive &archive) const
  {
    AssertThrow(matrix != nullptr,
                ExcMessage("LinearSolver::save() needs a prepared matrix."));
    archive << factor_is_exact << cg_excess_flops << substitution_error;
  }


  void
  LinearSolver::load(InputArchive          &archive,
                     LA::MPI::SparseMatrix &A,
                     const Discretization  &disc,
                     ChangingMatrix        *changes_of_A)
  {
    bool   exact  = false;
    double excess = 0, error = -1;
    archive >> exact >> excess >> error;
    prepare(A, disc, changes_of_A);
    factor_is_exact    = exact;
    cg_excess_flops    = excess;
    substitution_error = error;
  }
} // namespace liftoff
