#pragma once

// Manufactured solutions of the Mindlin plate on a bilateral Winkler
// foundation, clamped on all edges (manufactured_solution.cc,
// adaptive_convergence.cc).
//
// Exact fields u_c = T(t) A_c F_c(X) G_c(Y) (X = x + 1/2, Y = y + 1/2 in
// [0, 1]), each profile zero at both ends, as clamping requires. The
// forcing is the strong form of the equations of motion, obtained by
// varying the energy
//   1/2 int [psi_x,x^2 + psi_y,y^2 + 2 nu psi_x,x psi_y,y
//            + (1-nu)/2 (psi_x,y + psi_y,x)^2]
//   + S/2 int |grad w - psi|^2 + Gamma/2 int w^2
// and adding the inertia (1 on w, I = Delta^2/12 on psi):
//   f_w = w_tt - S div(grad w - psi) + Gamma w
//   m_x = I psi_x,tt - [psi_x,xx + nu psi_y,yx
//                       + (1-nu)/2 (psi_x,yy + psi_y,xy)] - S (w_x - psi_x)
//   m_y = I psi_y,tt - [psi_y,yy + nu psi_x,xy
//                       + (1-nu)/2 (psi_y,xx + psi_x,yx)] - S (w_y - psi_y)
// All test functions vanish on the clamped boundary, so the weak form has no
// boundary terms and the body force (integrated against all three
// components by the library) is the whole right hand side. strong_form()
// evaluates these expressions from analytic derivatives of the fields;
// finite_difference_check() checks those derivatives.

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include "test_tools.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace liftoff_tests::manufactured
{
  using namespace dealii;

  // Material: Delta = 0.2 is thick enough that full integration does not
  // lock; nu is not the default so that a dropped nu would show.
  constexpr double thickness_ratio  = 0.2;
  constexpr double poisson_ratio    = 0.25;
  constexpr double shear_correction = 5.0 / 6.0;
  constexpr double gamma_foundation = 10.0;

  const double S = 6.0 * shear_correction * (1.0 - poisson_ratio)
                   / (thickness_ratio * thickness_ratio);
  const double I = thickness_ratio * thickness_ratio / 12.0;

  /// T(t) = cos(omega t) + 0.5 sin(omega t) and its derivatives (omega = 0:
  /// T = 1, a static solution).
  struct TimeFactor
  {
    double omega;
    double
    value(const double t) const
    {
      return std::cos(omega * t) + 0.5 * std::sin(omega * t);
    }
    double
    first(const double t) const
    {
      return omega * (-std::sin(omega * t) + 0.5 * std::cos(omega * t));
    }
    double
    second(const double t) const
    {
      return -omega * omega * value(t);
    }
  };

  /// A function of one variable s in [0, 1] vanishing at both ends, with
  /// two derivatives:
  /// - sine: sin(k pi s);
  /// - bubble: s (1 - s);
  /// - layer: s (1 - s) tanh(k (s - s0)), a steep interior layer of width
  ///   about 1/k at s0.
  struct Profile
  {
    enum Kind
    {
      sine,
      bubble,
      layer
    };
    Kind   kind;
    double k  = 0;
    double s0 = 0;

    double
    value(const double s) const
    {
      return kind == sine ? std::sin(k * M_PI * s)
                          : s * (1 - s) * (kind == layer ? t(s) : 1.0);
    }
    double
    first(const double s) const
    {
      if (kind == sine)
        return k * M_PI * std::cos(k * M_PI * s);
      if (kind == bubble)
        return 1 - 2 * s;
      return (1 - 2 * s) * t(s) + s * (1 - s) * k * (1 - t(s) * t(s));
    }
    double
    second(const double s) const
    {
      if (kind == sine)
        return -std::pow(k * M_PI, 2) * std::sin(k * M_PI * s);
      if (kind == bubble)
        return -2.0;
      const double tt = t(s), t1 = k * (1 - tt * tt), t2 = -2 * k * tt * t1;
      return -2 * tt + 2 * (1 - 2 * s) * t1 + s * (1 - s) * t2;
    }
    /// The profile as a muParser expression in `s`.
    std::string
    expression(const std::string &s) const
    {
      std::ostringstream text;
      text << std::setprecision(17);
      if (kind == sine)
        text << "sin(" << k << "*pi*(" << s << "))";
      else
        {
          text << "(" << s << ")*(1-(" << s << "))";
          if (kind == layer)
            text << "*tanh(" << k << "*((" << s << ")-" << s0 << "))";
        }
      return text.str();
    }

  private:
    double
    t(const double s) const
    {
      return std::tanh(k * (s - s0));
    }
  };

  inline Profile
  sine(const double k)
  {
    return {Profile::sine, k};
  }
  inline Profile
  bubble()
  {
    return {Profile::bubble};
  }
  inline Profile
  layer(const double k, const double s0)
  {
    return {Profile::layer, k, s0};
  }

  /// Exact fields u_c = T(t) A_c F_c(X) G_c(Y) for c = w, psi_x, psi_y.
  struct Fields
  {
    std::string            name;
    TimeFactor             T;
    std::array<double, 3>  amplitude;
    std::array<Profile, 3> along_x, along_y;

    /// u_c(x, y, t) as a muParser expression times T(0) or T'(0).
    std::string
    expression(const double time_factor) const
    {
      std::ostringstream text;
      text << std::setprecision(17);
      for (unsigned int c = 0; c < 3; ++c)
        text << (c > 0 ? "; " : "") << time_factor * amplitude[c] << "*"
             << along_x[c].expression("x+0.5") << "*"
             << along_y[c].expression("y+0.5");
      return text.str();
    }
  };

  /// Values and derivatives of the three fields at a point and time.
  struct Derivatives
  {
    std::array<double, 3> u, u_tt, u_x, u_y, u_xx, u_yy, u_xy;
  };

  inline Derivatives
  derivatives(const Fields &f, const Point<2> &p, const double t)
  {
    Derivatives  d;
    const double X = p[0] + 0.5, Y = p[1] + 0.5;
    const double T0 = f.T.value(t), T2 = f.T.second(t);
    for (unsigned int c = 0; c < 3; ++c)
      {
        const Profile &F = f.along_x[c], &G = f.along_y[c];
        const double   A = f.amplitude[c];
        d.u[c]           = A * T0 * F.value(X) * G.value(Y);
        d.u_tt[c]        = A * T2 * F.value(X) * G.value(Y);
        d.u_x[c]         = A * T0 * F.first(X) * G.value(Y);
        d.u_y[c]         = A * T0 * F.value(X) * G.first(Y);
        d.u_xx[c]        = A * T0 * F.second(X) * G.value(Y);
        d.u_yy[c]        = A * T0 * F.value(X) * G.second(Y);
        d.u_xy[c]        = A * T0 * F.first(X) * G.first(Y);
      }
    return d;
  }

  /// The strong form of the equations of motion (see the top) applied to
  /// fields given with their derivatives.
  inline std::array<double, 3>
  strong_form(const Derivatives &d)
  {
    const double nu = poisson_ratio, twist = 0.5 * (1 - nu);
    return {{d.u_tt[0] - S * (d.u_xx[0] + d.u_yy[0] - d.u_x[1] - d.u_y[2])
               + gamma_foundation * d.u[0],
             I * d.u_tt[1]
               - (d.u_xx[1] + nu * d.u_xy[2] + twist * (d.u_yy[1] + d.u_xy[2]))
               - S * (d.u_x[0] - d.u[1]),
             I * d.u_tt[2]
               - (d.u_yy[2] + nu * d.u_xy[1] + twist * (d.u_xx[2] + d.u_xy[1]))
               - S * (d.u_y[0] - d.u[2])}};
  }

  inline std::array<double, 3>
  exact_values(const Derivatives &d)
  {
    return d.u;
  }

  /// A quantity of the manufactured solution at time get_time(): the exact
  /// (w, psi_x, psi_y) (exact_values), or the forcing (f_w, m_x, m_y) that
  /// produces it (strong_form). The gradient is that of the exact fields.
  class ManufacturedField : public Function<2>
  {
  public:
    using Quantity = std::array<double, 3> (*)(const Derivatives &);

    ManufacturedField(const Fields &fields, const Quantity quantity)
        : Function<2>(3)
        , fields(fields)
        , quantity(quantity)
    {}

    void
    vector_value(const Point<2> &p, Vector<double> &values) const override
    {
      const auto q = quantity(derivatives(fields, p, this->get_time()));
      for (unsigned int c = 0; c < 3; ++c)
        values[c] = q[c];
    }

    double
    value(const Point<2> &p, const unsigned int component) const override
    {
      return quantity(derivatives(fields, p, this->get_time()))[component];
    }

    Tensor<1, 2>
    gradient(const Point<2> &p, const unsigned int component) const override
    {
      const Derivatives d = derivatives(fields, p, this->get_time());
      return Tensor<1, 2>({d.u_x[component], d.u_y[component]});
    }

  private:
    const Fields   fields;
    const Quantity quantity;
  };

  /// The strong form with every derivative taken by central differences
  /// of the field values, against the same with the analytic derivatives:
  /// checks derivatives(). Returns the largest difference over sample
  /// points relative to the largest forcing.
  inline double
  finite_difference_check(const Fields &fields)
  {
    const double h  = 1e-4;
    const auto   at = [&](const double x, const double y, const double t) {
      return derivatives(fields, Point<2>(x, y), t).u;
    };
    double max_difference = 0, max_forcing = 0;
    for (const double t : {0.0, 0.37, 1.1})
      for (const double x : {-0.41, -0.13, 0.05, 0.33})
        for (const double y : {-0.37, -0.02, 0.21, 0.44})
          {
            Derivatives fd;
            fd.u = at(x, y, t);
            for (unsigned int k = 0; k < 3; ++k)
              {
                const double c = fd.u[k];
                fd.u_tt[k] =
                  (at(x, y, t + h)[k] - 2 * c + at(x, y, t - h)[k]) / (h * h);
                fd.u_xx[k] =
                  (at(x + h, y, t)[k] - 2 * c + at(x - h, y, t)[k]) / (h * h);
                fd.u_yy[k] =
                  (at(x, y + h, t)[k] - 2 * c + at(x, y - h, t)[k]) / (h * h);
                fd.u_xy[k] = (at(x + h, y + h, t)[k] - at(x + h, y - h, t)[k]
                              - at(x - h, y + h, t)[k] + at(x - h, y - h, t)[k])
                             / (4 * h * h);
                fd.u_x[k] = (at(x + h, y, t)[k] - at(x - h, y, t)[k]) / (2 * h);
                fd.u_y[k] = (at(x, y + h, t)[k] - at(x, y - h, t)[k]) / (2 * h);
              }
            const auto approximate = strong_form(fd);
            const auto exact = strong_form(derivatives(fields, {x, y}, t));
            for (unsigned int k = 0; k < 3; ++k)
              {
                max_difference =
                  std::max(max_difference, std::abs(approximate[k] - exact[k]));
                max_forcing = std::max(max_forcing, std::abs(exact[k]));
              }
          }
    return max_difference / max_forcing;
  }

  /// prm text: the clamped square plate of this material on a bilateral
  /// bed, the full plate on `cells` x `cells` elements of degree `degree`,
  /// starting from the exact fields and their velocity at t = 0.
  inline std::string
  plate_scene(const Fields      &fields,
              const unsigned int degree,
              const unsigned int cells)
  {
    std::ostringstream scene;
    scene << std::setprecision(17)
          << square_plate(thickness_ratio, poisson_ratio, shear_correction)
          << "subsection Foundation\n"
          << "  set Model = bilateral\n"
          << "  set Stiffness = " << gamma_foundation << "\n"
          << "end\n"
          << all_edges("clamped") << "subsection Discretization\n"
          << "  set Symmetry = full\n"
          << "  set Cells along x = " << cells << "\n"
          << "  set Cells along y = " << cells << "\n"
          << "  set Polynomial degree = " << degree << "\n"
          << "end\n"
          << "subsection Initial conditions\n"
          << "  set Displacement = " << fields.expression(fields.T.value(0))
          << "\n"
          << "  set Velocity = " << fields.expression(fields.T.first(0)) << "\n"
          << "end\n"
          << "subsection Output\n"
          << "  set Write energies = false\n"
          << "end\n";
    return scene.str();
  }

  /// The error of the simulator's final state against `exact` (at its
  /// time) in `norm` (L2_norm or H1_seminorm), of the components `select`
  /// picks.
  inline double
  error_of(const liftoff::Simulator         &simulator,
           const Function<2>                &exact,
           const ComponentSelectFunction<2> &select,
           const VectorTools::NormType       norm = VectorTools::L2_norm)
  {
    const auto    &disc   = simulator.get_discretization();
    const unsigned degree = disc.dof_handler.get_fe().degree;
    Vector<float>  cellwise(disc.triangulation.n_active_cells());
    // solution() is the ghosted vector, as integrate_difference needs.
    VectorTools::integrate_difference(disc.mapping(),
                                      disc.dof_handler,
                                      simulator.solution(),
                                      exact,
                                      cellwise,
                                      QGauss<2>(degree + 3),
                                      norm,
                                      &select);
    return VectorTools::compute_global_error(disc.triangulation,
                                             cellwise,
                                             norm);
  }
} // namespace liftoff_tests::manufactured
