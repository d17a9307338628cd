#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/time/clock.h>
#include <liftoff/time/step_size_controller.h>

namespace liftoff
{
  using namespace dealii;

  /**
   * The Newmark family for M a + f(u) = F, f(u) = K u + R_f(u): Newmark's
   * method with beta and gamma from the scene (average acceleration, 1/4
   * and 1/2, by default), or the generalized-alpha method of Chung and
   * Hulbert (1993) with the spectral radius rho_inf. Generalized-alpha asks
   * for the weighted balance
   *   (1 - a_m) M a_{n+1} + a_m M a_n + (1 - a_f) f(u_{n+1}) + a_f f(u_n)
   *     = (1 - a_f) F_{n+1} + a_f F_n,
   * the forces weighted rather than evaluated at an intermediate state, so
   * that rho_inf = 1 (a_m = a_f = 1/2) gives exactly Newmark's sequence when
   * the initial acceleration is in balance. Divided by 1 - a_f, a step
   * solves
   *   (K + K_f(S) + c M) u_{n+1}
   *     = F_{n+1} + M h_n + a_f/(1 - a_f) (F_n - f(u_n)),
   * c = mass_factor(), h_n = history_term(), then updates a and v with the
   * Newmark relations. The class only knows these formulas; who solves the
   * system (and how the foundation enters f) is not its business.
   */
  class NewmarkIntegrator
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Refuse an End time that is not a whole number (at least 1) of time
    /// steps: a run never shortens a step nor passes End time. Only a time
    /// integration asks; a static analysis ignores both.
    void
    check_end_time() const;

    /// The scene's clock at step 0: Time step, End time and the number of
    /// steps between them (End time a multiple of dt after
    /// check_end_time()).
    Clock
    clock() const;

    /// The same scheme with steps of `dt` instead of Time step (the steps
    /// of Time step control = error).
    NewmarkIntegrator
    with_time_step(const double dt) const;

    /// Whether the scheme damps high frequencies (gamma > 1/2: Newmark with
    /// such a Gamma, generalized-alpha with Spectral radius < 1), so that
    /// the energy of a linear system decreases instead of being conserved.
    bool
    dissipates_energy() const;

    /// Whether the scheme conserves the energy of a linear system exactly
    /// (the trapezoidal rule: Beta = 1/4, Gamma = 1/2, or generalized-alpha
    /// with Spectral radius 1). Gamma = 1/2 with another Beta conserves a
    /// modified energy instead, which differs by a term of order
    /// (Beta - 1/4) dt^2 |a|^2.
    bool
    conserves_energy() const;

    /// Whether the scheme is stable only for small enough steps (Newmark
    /// with 2 beta < gamma).
    bool
    is_conditionally_stable() const;

    /// The largest stable dt for a system whose largest eigenvalue of
    /// M^-1 K is `largest_eigenvalue` (omega_max^2); infinite for an
    /// unconditionally stable scheme.
    double
    stable_time_step(const double largest_eigenvalue) const;

    /// The factor of M in the effective matrix: 1 / (beta dt^2) for
    /// Newmark, (1 - alpha_m) / ((1 - alpha_f) beta dt^2) in general.
    double
    mass_factor() const;

    /// alpha_f / (1 - alpha_f): the weight of the previous state's force
    /// balance F_n - K u_n - R_f(u_n) in the right-hand side (0 for
    /// Newmark).
    double
    previous_state_weight() const;

    /// h_n from u_n, v_n, a_n.
    void
    history_term(const LA::MPI::Vector &u,
                 const LA::MPI::Vector &v,
                 const LA::MPI::Vector &a,
                 LA::MPI::Vector       &h) const;

    /// Whether right_hand_side() needs the previous state's force balance
    /// F_n - f(u_n) (generalized-alpha); Newmark does not.
    bool
    needs_force_balance() const;

    /// The right-hand side of a step from (u_n, v_n, a_n):
    ///   F_{n+1} + M h_n + previous_state_weight() (F_n - f(u_n)),
    /// `balance` = F_n - f(u_n) being read only if needs_force_balance().
    /// `h` is scratch of the same layout.
    void
    right_hand_side(const LA::MPI::SparseMatrix &mass,
                    const LA::MPI::Vector       &u,
                    const LA::MPI::Vector       &v,
                    const LA::MPI::Vector       &a,
                    const LA::MPI::Vector       &next_load,
                    const LA::MPI::Vector       &balance,
                    LA::MPI::Vector             &h,
                    LA::MPI::Vector             &rhs) const;

    /// gamma / (beta dt): v_{n+1} = velocity_factor() u_{n+1} - o_n, the
    /// velocity of a step is affine in its displacement.
    double
    velocity_factor() const;
    /// o_n = gamma/(beta dt) u_n - (1 - gamma/beta) v_n
    ///       - dt (1 - gamma/(2 beta)) a_n.
    void
    velocity_offset(const LA::MPI::Vector &u,
                    const LA::MPI::Vector &v,
                    const LA::MPI::Vector &a,
                    LA::MPI::Vector       &offset) const;
    /// u_n + dt v_n + dt^2/2 a_n, u_{n+1} if the acceleration stayed a_n:
    /// the initial guess for an iterative solve of the step.
    void
    predict(const LA::MPI::Vector &u,
            const LA::MPI::Vector &v,
            const LA::MPI::Vector &a,
            LA::MPI::Vector       &u_predicted) const;

    /// Given u_{n+1}, overwrite (u, v, a) with the state at t_{n+1}.
    void
    advance(const LA::MPI::Vector &u_new,
            LA::MPI::Vector       &u,
            LA::MPI::Vector       &v,
            LA::MPI::Vector       &a) const;

    double beta  = 0.25;
    double gamma = 0.5;
    /// Generalized-alpha weights (0 for Newmark).
    double alpha_m = 0;
    double alpha_f = 0;
    /// How the steps between the multiples of Time step are chosen (its
    /// entries are in this section too).
    StepSizeController step_control;

  private:
    double time_step = 5e-4;
    double end_time  = 0.2;
  };
} // namespace liftoff
