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
    beta      = prm.get_double("Beta");
    gamma     = prm.get_double("Gamma");
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
    return 1.0 / (beta * time_step * time_step);
  }


  void
  NewmarkIntegrator::history_term(const LA::MPI::Vector &u,
                                  const LA::MPI::Vector &v,
                                  const LA::MPI::Vector &a,
                                  LA::MPI::Vector       &h) const
  {
    h.equ(mass_factor(), u);
    h.add(1.0 / (beta * time_step), v, 1.0 / (2.0 * beta) - 1.0, a);
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
    LA::MPI::Vector a_new(u_new);
    a_new.add(-1.0, u);
    a_new *= mass_factor();
    a_new.add(-1.0 / (beta * time_step), v, -(1.0 / (2.0 * beta) - 1.0), a);

    v.add((1.0 - gamma) * time_step, a, gamma * time_step, a_new);
    a = a_new;
    u = u_new;
  }
} // namespace liftoff
