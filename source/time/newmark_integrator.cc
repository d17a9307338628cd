#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/selection.h>
#include <liftoff/time/newmark_integrator.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace liftoff
{
  namespace
  {
    // true: generalized-alpha.
    const Selection<bool> schemes = {{"newmark", false},
                                     {"generalized-alpha", true}};
  } // namespace


  void
  NewmarkIntegrator::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry("Beta",
                      "0.25",
                      Patterns::Double(0.0, 0.5),
                      "Newmark beta, in (0, 0.5]; 1/4 with gamma = 1/2 is "
                      "the average acceleration rule. Beta < Gamma/2 is only "
                      "conditionally stable: dtau must stay below "
                      "Omega_crit / omega_max, Omega_crit = (Gamma/2 - "
                      "Beta)^(-1/2), omega_max^2 the largest eigenvalue of "
                      "M^-1 (K + K_f) with every spring in contact, estimated "
                      "by power iteration before the first step. A larger "
                      "dtau is refused with a message giving the limit (the "
                      "estimate is a lower bound of omega_max, so a stable "
                      "scheme is never refused). The generalized-alpha "
                      "scheme is unconditionally stable for every Spectral "
                      "radius in [0, 1]."
                        + quantity("number"));
    prm.declare_entry("Gamma",
                      "0.5",
                      Patterns::Double(0.5, 1.0),
                      "Newmark gamma, in [0.5, 1]; above 1/2 it damps."
                        + quantity("number"));
    prm.declare_entry(
      "Scheme",
      "newmark",
      schemes.pattern(),
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
                      "in one step."
                        + quantity("number"));
    prm.declare_entry("Time step",
                      "5e-4",
                      Patterns::Double(0.0),
                      "dtau > 0, in units of t0 = L^2 sqrt(rho H / D), the "
                      "step (the largest with Time step control = error): End "
                      "time must be a whole number (at least 1) of it, to "
                      "1e-9; any other End time is refused, no step is "
                      "shortened. At least 1/sqrt(Beta 1e250) (about "
                      "2e-125), below which M / (Beta dtau^2) overflows."
                        + quantity("time"));
    prm.declare_entry("End time",
                      "0.2",
                      Patterns::Double(0.0),
                      "Final dimensionless time tau > 0, a multiple of Time "
                      "step."
                        + quantity("time"));
    prm.leave_subsection();
    StepSizeController::declare_parameters(prm);
  }


  void
  NewmarkIntegrator::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    beta    = prm.get_double("Beta");
    gamma   = prm.get_double("Gamma");
    alpha_m = 0;
    alpha_f = 0;
    if (schemes.parse(prm.get("Scheme"), "Time integration/Scheme"))
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
    step_control.parse_parameters(prm, time_step);
    AssertThrow(beta > 0,
                ExcMessage("Time integration/Beta must lie in (0, 0.5]."));
    AssertThrow(time_step > 0,
                ExcMessage("Time integration/Time step must be > 0."));
    AssertThrow(end_time > 0,
                ExcMessage("Time integration/End time must be > 0."));
    // M / (beta dt^2) enters the effective matrix and, times u, the
    // right-hand side: past 1e250 its products leave the range of double and
    // the solve returns inf or nan, whatever the scene.
    const double smallest_step = 1.0 / std::sqrt(beta * 1e250);
    AssertThrow(time_step >= smallest_step,
                ExcMessage("Time integration/Time step = "
                           + Utilities::to_string(time_step)
                           + " is so small that M / (Beta Time step^2) "
                             "overflows double precision; it must be at "
                             "least "
                           + Utilities::to_string(smallest_step) + "."));
    AssertThrow(end_time / time_step < 1e8,
                ExcMessage("Time integration/End time / Time step exceeds "
                           "1e8 steps; choose a larger Time step."));
  }


  void
  NewmarkIntegrator::check_end_time() const
  {
    // A run ends exactly at End time with steps of exactly Time step, or is
    // refused: silently stepping past End time (or not stepping at all)
    // would report times the scene did not ask for.
    const double ratio = end_time / time_step;
    const double n     = std::round(ratio);
    const auto   text  = [](const double value) {
      std::ostringstream out;
      out << std::setprecision(10) << value;
      return out.str();
    };
    AssertThrow(n >= 1,
                ExcMessage("Time integration/Time step = " + text(time_step)
                           + " exceeds End time = " + text(end_time)
                           + ": not one step would be taken."));
    AssertThrow(std::abs(ratio - n) <= 1e-9 * n,
                ExcMessage("Time integration/End time = " + text(end_time)
                           + " is not a multiple of Time step = "
                           + text(time_step) + " (" + text(ratio)
                           + " steps); the step is never shortened. Use End "
                             "time = "
                           + text(std::floor(ratio) * time_step) + " or "
                           + text(std::ceil(ratio) * time_step) + "."));
  }


  Clock
  NewmarkIntegrator::clock() const
  {
    return Clock(time_step, end_time);
  }


  NewmarkIntegrator
  NewmarkIntegrator::with_time_step(const double dt) const
  {
    NewmarkIntegrator scheme = *this;
    scheme.time_step         = dt;
    return scheme;
  }


  bool
  NewmarkIntegrator::conserves_energy() const
  {
    return std::abs(beta - 0.25) <= 1e-12 && std::abs(gamma - 0.5) <= 1e-12;
  }


  bool
  NewmarkIntegrator::dissipates_energy() const
  {
    return gamma > 0.5 + 1e-12;
  }


  bool
  NewmarkIntegrator::is_conditionally_stable() const
  {
    // Hughes (1987), sec. 9.1: for gamma >= 1/2 Newmark is unconditionally
    // stable iff 2 beta >= gamma. Generalized-alpha from rho_inf in [0, 1]
    // always satisfies alpha_m <= alpha_f <= 1/2, beta >= 1/4 + (alpha_f -
    // alpha_m)/2 (Chung and Hulbert 1993), i.e. unconditional stability.
    return alpha_m == 0 && alpha_f == 0 && 2 * beta < gamma;
  }


  double
  NewmarkIntegrator::stable_time_step(const double largest_eigenvalue) const
  {
    if (!is_conditionally_stable())
      return std::numeric_limits<double>::infinity();
    // omega_max dt <= Omega_crit = (gamma/2 - beta)^(-1/2) (undamped system).
    return 1.0 / std::sqrt((0.5 * gamma - beta) * largest_eigenvalue);
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


  bool
  NewmarkIntegrator::needs_force_balance() const
  {
    return previous_state_weight() != 0;
  }


  void
  NewmarkIntegrator::right_hand_side(const LA::MPI::SparseMatrix &mass,
                                     const LA::MPI::Vector       &u,
                                     const LA::MPI::Vector       &v,
                                     const LA::MPI::Vector       &a,
                                     const LA::MPI::Vector       &next_load,
                                     const LA::MPI::Vector       &balance,
                                     LA::MPI::Vector             &h,
                                     LA::MPI::Vector             &rhs) const
  {
    history_term(u, v, a, h);
    mass.vmult(rhs, h);
    rhs += next_load;
    if (needs_force_balance())
      rhs.add(previous_state_weight(), balance);
  }


  double
  NewmarkIntegrator::velocity_factor() const
  {
    return gamma / (beta * time_step);
  }


  void
  NewmarkIntegrator::velocity_offset(const LA::MPI::Vector &u,
                                     const LA::MPI::Vector &v,
                                     const LA::MPI::Vector &a,
                                     LA::MPI::Vector       &offset) const
  {
    // From advance(): v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1})
    // with a_{n+1} = (u_{n+1} - u_n)/(beta dt^2) - v_n/(beta dt)
    // - (1/(2 beta) - 1) a_n.
    offset.equ(velocity_factor(), u);
    offset.add(-(1 - gamma / beta),
               v,
               -time_step * (1 - 0.5 * gamma / beta),
               a);
  }


  void
  NewmarkIntegrator::predict(const LA::MPI::Vector &u,
                             const LA::MPI::Vector &v,
                             const LA::MPI::Vector &a,
                             LA::MPI::Vector       &u_predicted) const
  {
    copy_values(u, u_predicted);
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
    copy_values(u_new, u);
  }
} // namespace liftoff
