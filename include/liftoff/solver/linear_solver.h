#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <liftoff/base/section_timer.h>

#include <liftoff/base/archive_types.h>
#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/memory_estimate.h>

#include <chrono>
#include <memory>

namespace liftoff
{
  using namespace dealii;

  class CholeskyFactor;
  class MumpsCholeskyFactor;

  /**
   * What LinearSolver needs from the owner of a matrix that the owner
   * changes in place between solves (ActiveSetIteration: the springs whose
   * status flipped). Given to LinearSolver::prepare() with the matrix.
   */
  class ChangingMatrix
  {
  public:
    /// Since when multiply_by_change() takes the change of the matrix.
    enum class Since
    {
      factorisation,
      last_solve
    };

    virtual ~ChangingMatrix() = default;

    /// dst = (A - A_s) src, A the matrix as it is and A_s the one last
    /// factorised or the one of the last solve. With it, CG on a changed
    /// matrix forms products with the whole matrix once or twice per step
    /// of the active set instead of once per iteration and solve
    /// (LinearSolver::conjugate_gradients()).
    virtual void
    multiply_by_change(const LA::MPI::Vector &src,
                       LA::MPI::Vector       &dst,
                       const Since            since) = 0;

    /// Write the matrix anew from the parts it was built from, before each
    /// later factorisation of it. Every factor is then of a matrix that its
    /// owner can build again, and a checkpoint keeps those parts instead of
    /// a copy of the values (L: 218 MB); the matrix as changed in place
    /// holds other round-off than a fresh build.
    virtual void
    rebuild_matrix() = 0;
  };

  /**
   * A LinearSolver's factor or preconditioner with its state, out of the
   * solver, to be put back later (FactorCache: one per time step size) by
   * exchange(). Parameters, counters, the matrix and CG's vectors stay
   * with the solver.
   */
  struct KeptFactor
  {
    KeptFactor();
    KeptFactor(KeptFactor &&) noexcept;
    KeptFactor &
    operator=(KeptFactor &&) noexcept;
    ~KeptFactor();

    std::unique_ptr<TrilinosWrappers::SolverDirect>    direct;
    std::unique_ptr<CholeskyFactor>                    cholesky;
    std::unique_ptr<MumpsCholeskyFactor>               mumps_cholesky;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    bool                                               is_exact        = false;
    double                                             cg_excess_flops = 0;
    double                                             substitution_error = -1;
  };

  /**
   * Solves A x = b for a matrix that changes a little between solves: the
   * effective matrix of a time step plus the foundation term of the current
   * contact set.
   *
   * `direct` factorises A once and keeps the factor: by default with a
   * sparse Cholesky factor (A is symmetric positive definite), CHOLMOD's
   * on one rank and MUMPS's (MumpsCholeskyFactor) on several, otherwise
   * with a sparse LU of Trilinos Amesos (MUMPS or KLU, on any number of
   * ranks). While A is the factorised matrix, a solve is one forward and
   * back substitution. After A has changed
   * (matrix_changed()), the stored factor preconditions conjugate gradients on
   * the new A; the change, a few Gauss points' springs, is small against M /
   * (beta dt^2), so CG needs one or two iterations. A is factorised anew
   * when CG needs more than `Refactorisation threshold` iterations, and
   * (CHOLMOD) when the work CG has spent beyond one substitution per solve
   * since the matrix last changed adds up to the cost of a factorisation:
   * on a small problem whose contact set seldom changes, factorising again
   * is cheaper than CG for the rest of the run.
   *
   * `cg` builds an algebraic multigrid preconditioner (Trilinos ML) once per
   * prepare() and keeps it for the changed matrices.
   *
   * Neither assumes that the plate stiffness alone is invertible; the
   * effective matrices of liftoff are made regular by the mass or the
   * foundation.
   */
  class LinearSolver
  {
  public:
    /// `Type`: a stored factor, or CG with algebraic multigrid.
    enum class Type
    {
      direct,
      cg
    };
    /// `Direct solver package`.
    enum class Package
    {
      /// A Cholesky factor: CHOLMOD's on one rank, MUMPS's on several;
      /// MUMPS's LU for a matrix that is not positive definite.
      cholmod,
      /// MUMPS's Cholesky factor on any number of ranks (LU as above).
      mumps,
      /// MUMPS's LU (Trilinos Amesos).
      mumps_lu,
      klu
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Section "factorisation" for factorisations and preconditioner
    /// set-ups, "solve" for the rest of a solve.
    explicit LinearSolver(SectionTimer &timer);
    ~LinearSolver();

    /// Factorise A, or build its preconditioner. A and `changes` must
    /// outlive the solves. With `changes`, A may change in place between
    /// solves (matrix_changed()); without, it is factorised as it is and a
    /// changed A is solved by CG with whole-matrix products.
    void
    prepare(const LA::MPI::SparseMatrix &A,
            const Discretization        &disc,
            ChangingMatrix              *changes = nullptr);

    /// Drop the factor and preconditioner: MUMPS's refers to the matrix it
    /// was built from, which a new mesh rebuilds.
    void
    release();

    /// The matrix given to prepare() has been changed in place.
    void
    matrix_changed();

    /// How accurate a solve must be: `final` to `Tolerance`; `trial` to
    /// `Trial tolerance`, for a solution that only decides the next contact
    /// set (ActiveSetIteration solves to `final` once the set holds).
    enum class Accuracy
    {
      final,
      trial
    };

    /// Solve A x = b with the matrix given to prepare(); x holds the
    /// initial guess on entry. `continues`: x and b are those the last
    /// solve returned and was given, unchanged, and A has changed since
    /// only as ChangingMatrix::multiply_by_change() describes; then CG starts
    /// from the last residual instead of a product with A. Returns the CG
    /// iterations (0 for a plain substitution).
    unsigned int
    solve(LA::MPI::Vector       &x,
          const LA::MPI::Vector &b,
          Accuracy               accuracy  = Accuracy::final,
          bool                   continues = false);

    /// `Tolerance`: the relative residual of a final solve.
    double
    relative_tolerance() const;

    /// Whether a `trial` solve may stop short of a `final` one.
    bool
    has_looser_trials() const;

    /// Whether the last solve met `Tolerance`, as a substitution with a
    /// factor of the matrix itself does even when a trial was asked for.
    bool
    last_solve_met_tolerance() const;

    /// The factor in use, for the summary ("CHOLMOD Cholesky", "MUMPS
    /// Cholesky", "MUMPS LU").
    std::string
    factor_name() const;

    /// Where the factor the parameters ask for will be kept, for the
    /// memory estimate made before anything is built.
    MemoryEstimate::Factor
    factor_placement() const;

    /// Factorisations or preconditioner set-ups so far.
    unsigned int n_preparations = 0;
    /// Forward and back substitutions with a stored factor so far, and the
    /// wall time they took.
    mutable unsigned int n_substitutions = 0;
    /// (A wall-time stopwatch: deal.II's Timer also reads the CPU time,
    /// which costs more than a substitution of a small factor.)
    mutable WallClock substitution_timer;
    /// CG iterations so far.
    unsigned long n_cg_iterations = 0;
    /// Products with the whole matrix in CG so far.
    unsigned long n_products = 0;
    /// CG solutions that met `Tolerance` by the residual CG carries but not
    /// by a product with the matrix (conjugate_gradients()).
    unsigned long n_failed_checks = 0;

    /// Apply the stored factor's inverse: dst = A_f^{-1} src. This makes
    /// the solver the preconditioner of its own CG.
    void
    vmult(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const;

    /// What it takes to continue with the same factor, besides the matrix
    /// it was built from: whether the matrix still equals that one, and
    /// the count towards the next factorisation.
    void
    save(OutputArchive &archive) const;
    /// prepare() with A, which must hold the values the saved factor was
    /// built from, and the state of save().
    void
    load(InputArchive          &archive,
         LA::MPI::SparseMatrix &A,
         const Discretization  &disc,
         ChangingMatrix        *changes = nullptr);

  private:
    /// Swap the solver's factor and its state with `kept`; the matrix
    /// given to prepare() stays, and is changed in place for the factor
    /// put in (matrix_changed()).
    friend void
    exchange(LinearSolver &solver, KeptFactor &kept);

    Type         type                      = Type::direct;
    Package      package                   = Package::cholmod;
    bool         has_reported_fallback     = false;
    double       tolerance                 = 1e-12;
    double       trial_tolerance           = 1e-6;
    unsigned int max_iterations            = 10000;
    unsigned int refactorization_threshold = 8;

    SectionTimer                &timer;
    const Discretization        *discretization = nullptr;
    const LA::MPI::SparseMatrix *matrix         = nullptr;
    ChangingMatrix              *changes        = nullptr;
    /// The factor belongs to the matrix as it is now.
    bool factor_is_exact = false;
    /// See last_solve_met_tolerance().
    bool met_tolerance = false;
    /// Floating-point operations CG has spent since the last factorisation
    /// beyond one substitution per solve (CHOLMOD only).
    double cg_excess_flops = 0;
    /// |A_f z - r| / |r| for the first substitution z = A_f^{-1} r of CG
    /// after the factorisation; negative until measured.
    double substitution_error = -1;
    /// CG's vectors, kept between solves.
    LA::MPI::Vector r, z, p, q, change_product;
    /// r holds b - A x (to round-off) for the x and b of the last solve.
    bool                                            residual_is_current = false;
    SolverControl                                   direct_control;
    std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
    std::unique_ptr<CholeskyFactor>                 cholesky;
    std::unique_ptr<MumpsCholeskyFactor>            mumps_cholesky;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;

    /// A factor of A: a Cholesky factor (CHOLMOD, MUMPS) where the package
    /// allows and A is positive definite, else an LU (Amesos).
    void
    factorize(const LA::MPI::SparseMatrix &A);
    /// `cg`'s algebraic multigrid preconditioner for A.
    void
    build_multigrid(const LA::MPI::SparseMatrix &A, const Discretization &disc);
    /// Say once (rank 0) that `factorisation` found the matrix not
    /// positive definite and MUMPS's LU takes over.
    void
    report_fallback(const std::string &factorisation);

    /// Factorise the matrix of prepare() again, as
    /// ChangingMatrix::rebuild_matrix() writes it.
    void
    refactorise();
    /// Where a conjugate_gradients() run stands.
    struct CGProgress
    {
      unsigned int step     = 0;
      unsigned int restart  = 0;
      double       residual = 0;
      double       rz_old   = 0;
      /// Products from the change of the matrix are allowed (a direct
      /// factor and a ChangingMatrix), and used (the substitution is
      /// accurate enough, and no check has failed).
      bool can_use_change = false;
      bool uses_change    = false;
      /// The residual r was derived from the change, not formed with A.
      bool is_derived = false;
    };
    /// CG iterations until the residual is below `target`; throws
    /// SolverControl::NoConvergence after `max_steps` in all.
    void
    iterate_to(const double       target,
               const unsigned int max_steps,
               LA::MPI::Vector   &x,
               CGProgress        &cg);
    /// CG's vectors in the layout of b (a new mesh changes it).
    void
    reinit_cg_vectors(const LA::MPI::Vector &b);
    /// r = b - A x with a product with the whole matrix.
    void
    whole_residual(const LA::MPI::Vector &x, const LA::MPI::Vector &b);
    /// q = A p for p = z + beta p_old, from r, q_old and the change of the
    /// matrix since the factorisation: A z = r + (A - A_f) z.
    void
    derived_product(const double beta);
    /// q = A p with the whole matrix; with `measures_substitution` (p = z)
    /// also the substitution's error |A_f z - r| / |r|, r of norm
    /// `residual`.
    void
    whole_product(const bool measures_substitution, const double residual);
    /// CG to the tolerance in at most `max_steps` iterations; throws
    /// SolverControl::NoConvergence otherwise.
    unsigned int
    conjugate_gradients(LA::MPI::Vector       &x,
                        const LA::MPI::Vector &b,
                        const unsigned int     max_steps,
                        const double           relative_tolerance,
                        const bool             continues);
  };
} // namespace liftoff
