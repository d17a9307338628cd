#include <liftoff/newmark_integrator.h>

#include <cmath>

namespace liftoff
{
  void
  NewmarkIntegrator::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry("Beta",
                      "0.25",
                      Patterns::Double(0.0, 0.5),
                      "Newmark beta, in (0, 0.5]; 1/4 with gamma = 1/2 is "
                      "the average acceleration rule.");
    prm.declare_entry("Gamma",
                      "0.5",
                      Patterns::Double(0.5, 1.0),
                      "Newmark gamma, in [0.5, 1]; above 1/2 it damps.");
    prm.declare_entry(
      "Scheme",
      "newmark",
      Patterns::Selection("newmark|generalized-alpha"),
      "newmark: Beta and Gamma as given. generalized-alpha: the scheme of "
      "Chung and Hulbert (1993), which damps frequencies far above 1/dtau "
      "(spectral radius at infinite frequency: Spectral radius) and keeps "
      "second-order accuracy; Beta and Gamma are then derived from it and "
      "not read. With Spectral radius = 1 it is Newmark's average "
      "acceleration rule.");
    prm.declare_entry("Spectral radius",
                      "1",
                      Patterns::Double(0.0, 1.0),
                      "rho_inf in [0, 1] for Scheme = generalized-alpha: 1 "
                      "damps nothing, 0 annihilates the highest frequencies "
                      "in one step.");
    prm.declare_entry("Time step",
                      "5e-4",
                      Patterns::Double(0.0),
                      "dtau > 0, in units of t0 = L^2 sqrt(rho H / D).");
    prm.declare_entry("End time",
                      "0.2",
                      Patterns::Double(0.0),
                      "Final dimensionless time tau > 0.");
    prm.leave_subsection();
  }


  void
  NewmarkIntegrator::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    beta    = prm.get_double("Beta");
    gamma   = prm.get_double("Gamma");
    alpha_m = 0;
    alpha_f = 0;
    if (prm.get("Scheme") == "generalized-alpha")
      {
        const double rho = prm.get_double("Spectral radius");
        alpha_m          = (2 * rho - 1) / (rho + 1);
        alpha_f          = rho / (rho + 1);
        beta  = 0.25 * (1 - alpha_m + alpha_f) * (1 - alpha_m + alpha_f);
        gamma = 0.5 - alpha_m + alpha_f;
      }
    time_step = prm.get_double("Time step");
    end_time  = prm.get_double("End time");
    prm.leave_subsection();
    AssertThrow(beta > 0,
                ExcMessage("Time integration/Beta must lie in (0, 0.5]."));
    AssertThrow(time_step > 0,
                ExcMessage("Time integration/Time step must be > 0."));
    AssertThrow(end_time > 0,
                ExcMessage("Time integration/End time must be > 0."));
    AssertThrow(end_time / time_step < 1e8,
                ExcMessage("Time integration/End time / Time step exceeds "
                           "1e8 steps; choose a larger Time step."));
  }


  unsigned int
  NewmarkIntegrator::n_steps() const
  {
    // The step is kept exactly as given; a remainder below one part in 1e9
    // counts as none.
    return static_cast<unsigned int>(std::ceil(end_time / time_step - 1e-9));
  }


  double
  NewmarkIntegrator::mass_factor() const
  {
    return (1 - alpha_m) / ((1 - alpha_f) * beta * time_step * time_step);
  }


  double
  NewmarkIntegrator::previous_state_weight() const
  {
    return alpha_f / (1 - alpha_f);
  }


  void
  NewmarkIntegrator::history_term(const LA::MPI::Vector &u,
                                  const LA::MPI::Vector &v,
                                  const LA::MPI::Vector &a,
                                  LA::MPI::Vector       &h) const
  {
    // (1 - alpha_m)/(beta dt^2) (u + dt v + dt^2 (1/2 - beta) a) - alpha_m a,
    // divided by 1 - alpha_f.
    const double c = 1.0 / (beta * time_step * time_step);
    const double s = (1 - alpha_m) / (1 - alpha_f);
    h.equ(s * c, u);
    h.add(s * c * time_step,
          v,
          (s * c * time_step * time_step * (0.5 - beta)
           - alpha_m / (1 - alpha_f)),
          a);
  }


  void
  NewmarkIntegrator::predict(const LA::MPI::Vector &u,
                             const LA::MPI::Vector &v,
                             const LA::MPI::Vector &a,
                             LA::MPI::Vector       &u_predicted) const
  {
    u_predicted = u;
    u_predicted.add(time_step, v, 0.5 * time_step * time_step, a);
  }


  void
  NewmarkIntegrator::advance(const LA::MPI::Vector &u_new,
                             LA::MPI::Vector       &u,
                             LA::MPI::Vector       &v,
                             LA::MPI::Vector       &a) const
  {
    // a_{n+1} = (u_{n+1} - u_n)/(beta dt^2) - v_n/(beta dt) - (1/(2beta)-1) a_n
    // is built in u's storage, which u_n no longer needs afterwards, so no
    // vector is allocated; the operations are those of the formula in its
    // order, so the rounding is too.
    LA::MPI::Vector &a_new = u;
    a_new.sadd(-1.0, 1.0, u_new);
    a_new *= 1.0 / (beta * time_step * time_step);
    a_new.add(-1.0 / (beta * time_step), v, -(1.0 / (2.0 * beta) - 1.0), a);

    v.add((1.0 - gamma) * time_step, a, gamma * time_step, a_new);
    a.swap(a_new);
    u = u_new;
  }
} // namespace liftoff
