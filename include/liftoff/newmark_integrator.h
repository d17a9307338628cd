#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/linear_algebra.h>

namespace liftoff
{
  using namespace dealii;

  /**
   * Newmark's method for M a + K(u) u = F, with beta and gamma from the scene
   * (average acceleration, 1/4 and 1/2, by default). A step solves
   *   (K(u) + M / (beta dt^2)) u_{n+1} = F_{n+1} + M h_n,
   *   h_n = u_n / (beta dt^2) + v_n / (beta dt) + (1/(2 beta) - 1) a_n,
   * then updates a and v. The class only knows these formulas; who solves
   * the system (and how the foundation enters K) is not its business.
   */
  class NewmarkIntegrator
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Number of steps of size dt that reach the end time.
    unsigned int
    n_steps() const;

    /// 1 / (beta dt^2), the factor of M in the effective matrix.
    double
    mass_factor() const;

    /// h_n from u_n, v_n, a_n.
    void
    history_term(const LA::MPI::Vector &u,
                 const LA::MPI::Vector &v,
                 const LA::MPI::Vector &a,
                 LA::MPI::Vector       &h) const;

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

    double beta      = 0.25;
    double gamma     = 0.5;
    double time_step = 5e-4;
    double end_time  = 0.2;
  };
} // namespace liftoff
