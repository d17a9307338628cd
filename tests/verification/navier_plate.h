#pragma once

// The hard simply supported square Mindlin plate under uniform pressure
// (tests navier_plate and thin_plates): Navier's series and the scene.
//
// Reference. With D = 1 and S = 6 chi (1 - nu) / Delta^2 the equations are
//   -S div(grad w - psi) = q,   L psi + S (grad w - psi) = 0,
//   L psi = ((1 - nu)/2) Lap psi + ((1 + nu)/2) grad div psi.
// The divergence of the second equation with the first gives
// Lap div psi = q and Lap w = div psi - q / S, so Lap Lap w = q - Lap q / S.
// Each Navier mode sin(m pi X) sin(n pi Y) (X = x + 1/2, Y = y + 1/2)
// satisfies the hard support (w = 0, tangential rotation 0, normal moment 0)
// exactly, with
//   w_mn = q_mn / alpha^4 (1 + alpha^2 / S),  alpha^2 = (m pi)^2 + (n pi)^2,
//   psi = grad w_K,  w_K = sum q_mn / alpha^4 sin sin (the Kirchhoff plate),
// q_mn = 16 q / (pi^2 m n) for odd m, n. So w = w_K + w_M / S, w_M the
// membrane deflection (-Lap w_M = q). The double series converges far too
// slowly at the 1e-10 level (its shear part only like 1/N^3), so the sum
// over n is done in closed form (Levy): for a = m pi, the functions
//   g(Y) = sum_n 4/(n pi) sin(n pi Y) / (a^2 + (n pi)^2),
//   h(Y) = sum_n 4/(n pi) sin(n pi Y) / (a^2 + (n pi)^2)^2
// solve -g'' + a^2 g = 1 and -h'' + a^2 h = g with zero end values; at
// Y = 1/2
//   g = (1 - 1/cosh(a/2)) / a^2,
//   h = 1/a^4 - (1/a^4 + tanh(a/2) / (4 a^3)) / cosh(a/2).
// The remaining single series in m is alternating (centre) or decays like
// 1/m^4 (edge rotation) and is summed to below 1e-13. The closed form is
// itself checked against the brute force double series.

#include <liftoff/fem/point_functional.h>

#include "test_tools.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace navier
{
  using namespace dealii;

  constexpr double poisson_ratio    = 0.3; // not the default: must reach S
  constexpr double shear_correction = 5.0 / 6.0;

  inline double
  shear_stiffness(const double thickness_ratio)
  {
    return 6.0 * shear_correction * (1.0 - poisson_ratio)
           / (thickness_ratio * thickness_ratio);
  }

  // Levy closed forms of the sums over n at Y = 1/2 (see the top).
  inline double
  levy_g(const double a)
  {
    return (1.0 - 1.0 / std::cosh(a / 2)) / (a * a);
  }

  inline double
  levy_h(const double a)
  {
    const double a4 = a * a * a * a;
    return 1.0 / a4
           - (1.0 / a4 + std::tanh(a / 2) / (4 * a * a * a)) / std::cosh(a / 2);
  }

  struct Reference
  {
    double centre_deflection;  // w(0, 0)
    double edge_rotation;      // psi_x(1/2, 0)
    double last_term_relative; // size of the last term kept, relative
  };

  inline Reference
  navier_reference(const double S, const double q = 1.0)
  {
    Reference    r{0, 0, 0};
    double       last = 0;
    const double pi   = M_PI;
    for (unsigned int m = 1; m <= 40001; m += 2)
      {
        const double a    = m * pi;
        const double sign = ((m - 1) / 2) % 2 == 0 ? 1.0 : -1.0;
        // w(centre) = sum_m 4 q/(m pi) sin(m pi/2) [h_m + g_m / S]
        last = 4 * q / (m * pi) * sign * (levy_h(a) + levy_g(a) / S);
        r.centre_deflection += last;
        // psi_x(X = 1, Y = 1/2) = sum_m 4 q cos(m pi) h_m
        r.edge_rotation += -4 * q * levy_h(a);
      }
    r.last_term_relative = std::abs(last / r.centre_deflection);
    return r;
  }

  // The moments and shear forces (doc/model.md's signs: z along w, so
  // M_xx = -(psi_x,x + nu psi_y,y), M_xy = -(1 - nu)/2 (psi_x,y + psi_y,x),
  // Q = S (grad w - psi)). Since psi = grad w_K the moments are those of
  // the Kirchhoff plate whatever S. With w_K = sum_m 4q/(m pi) sin(m pi X)
  // h_m(Y) and h'' = a^2 h - g (the equation of h above):
  //   M_xx(x, 0) = sum_m 4q/(m pi) sin(m pi X) [(1 - nu) a^2 h_m + nu g_m],
  //   M_yy(x, 0) = sum_m 4q/(m pi) sin(m pi X) [g_m - (1 - nu) a^2 h_m],
  // with terms like 1/m^3 (alternating at the centre). At a corner
  //   M_xy = -(1 - nu) w_K,xy = -(1 - nu) 16 q / pi^4 sum_{m,n odd}
  //          1 / (m^2 + n^2)^2,
  // the sum over n in closed form, the derivative in m^2 of
  // sum_{n odd} 1/(n^2 + m^2) = pi tanh(pi m/2) / (4 m):
  //   sum_{n odd} 1/(n^2 + m^2)^2 = pi/(8 m^3) [tanh(pi m/2)
  //                                 - (pi m/2) / cosh^2(pi m/2)].
  // Q = grad w_M (S grad (w - w_K) = grad w_M), w_M = sum_m 4q/(m pi)
  // sin(m pi X) g_m(Y), so at the middle of the right edge
  //   Q_x(1/2, 0) = -4 q sum_m g_m(1/2),
  // with g_m = 1/a^2 beyond cosh's range, whose tail beyond the last odd
  // m = N is -4 q / pi^2 sum_{m > N} 1/m^2 = -4 q / (2 pi^2 (N + 1)) to
  // O(1/N^3). Textbook values (Timoshenko & Woinowsky-Krieger, table 8,
  // nu = 0.3): 0.0479, 0.0325 (R = 2 M_xy = 0.065) and 0.338 in q a^2, q a.
  struct MomentReference
  {
    double centre_moment;   // M_xx = M_yy at (0, 0)
    double axis_m_xx;       // M_xx at (1/4, 0)
    double axis_m_yy;       // M_yy at (1/4, 0)
    double corner_twisting; // M_xy at (1/2, 1/2)
    double edge_shear;      // Q_x at (1/2, 0)
  };

  inline MomentReference
  navier_moments(const double q = 1.0)
  {
    MomentReference    r{0, 0, 0, 0, 0};
    const double       pi = M_PI, nu = poisson_ratio;
    const unsigned int last = 400001;
    for (unsigned int m = 1; m <= last; m += 2)
      {
        const double a       = m * pi;
        const double sign    = ((m - 1) / 2) % 2 == 0 ? 1.0 : -1.0;
        const double bending = (1 - nu) * a * a * levy_h(a);
        r.centre_moment += 4 * q / a * sign * (bending + nu * levy_g(a));
        const double at_axis = 4 * q / a * std::sin(0.75 * a);
        r.axis_m_xx += at_axis * (bending + nu * levy_g(a));
        r.axis_m_yy += at_axis * (levy_g(a) - bending);
        const double c = std::cosh(pi * m / 2);
        r.corner_twisting += pi / (8.0 * m * m * m)
                             * (std::tanh(pi * m / 2) - (pi * m / 2) / (c * c));
        r.edge_shear += -4 * q * levy_g(a);
      }
    r.corner_twisting *= -(1 - nu) * 16 * q / std::pow(pi, 4);
    r.edge_shear += -4 * q / (2 * pi * pi * (last + 1));
    return r;
  }

  // The moments' double series as the modes give them, truncated at N, to
  // check the closed forms: the moments at the centre and at (1/4, 0), and
  // the corner's sum.
  inline MomentReference
  double_series_moments(const unsigned int N, const double q = 1.0)
  {
    MomentReference r{0, 0, 0, 0, 0};
    const double    pi = M_PI, nu = poisson_ratio;
    for (unsigned int m = 1; m <= N; m += 2)
      for (unsigned int n = 1; n <= N; n += 2)
        {
          const double mm = double(m) * m, nn = double(n) * n;
          const double alpha2 = pi * pi * (mm + nn);
          const double q_mn   = 16 * q / (pi * pi * m * n);
          const double sign =
            (((m - 1) / 2 + (n - 1) / 2) % 2 == 0) ? 1.0 : -1.0;
          r.centre_moment +=
            sign * q_mn / (alpha2 * alpha2) * pi * pi * (mm + nu * nn);
          // At X = 3/4, Y = 1/2.
          const double mode = q_mn / (alpha2 * alpha2) * pi * pi
                              * std::sin(0.75 * m * pi)
                              * (((n - 1) / 2) % 2 == 0 ? 1.0 : -1.0);
          r.axis_m_xx += mode * (mm + nu * nn);
          r.axis_m_yy += mode * (nn + nu * mm);
          r.corner_twisting += 1 / ((mm + nn) * (mm + nn));
        }
    r.corner_twisting *= -(1 - nu) * 16 * q / std::pow(pi, 4);
    return r;
  }

  // The series exactly as written in the brief, truncated at m, n <= N.
  inline double
  double_series_centre(const double S, const unsigned int N, const double q)
  {
    const double pi  = M_PI;
    double       sum = 0;
    for (unsigned int m = 1; m <= N; m += 2)
      for (unsigned int n = 1; n <= N; n += 2)
        {
          const double alpha2 = pi * pi * (double(m) * m + double(n) * n);
          const double q_mn   = 16 * q / (pi * pi * m * n);
          const double sign =
            (((m - 1) / 2 + (n - 1) / 2) % 2 == 0) ? 1.0 : -1.0;
          sum += sign * q_mn / (alpha2 * alpha2) * (1 + alpha2 / S);
        }
    return sum;
  }

  // The single Navier mode q = q0 sin(pi X) sin(pi Y) on a square plate
  // on a Pasternak bed (springs k, shear layer G_p, bilateral): with the
  // bed the first equation above gains k w - G_p Lap w, and for one mode
  // w = W sin sin, psi = Psi grad(sin sin) the two equations give
  //   Psi = W / (1 + alpha^2 / S),
  //   W (alpha^4 / (1 + alpha^2 / S) + k + G_p alpha^2) = q0,
  // alpha^2 = 2 pi^2; S -> infinity gives the Kirchhoff plate's
  // W = q0 / (alpha^4 + k + G_p alpha^2).
  inline double
  pasternak_mode_amplitude(const double S,
                           const double k,
                           const double shear_modulus,
                           const double q0 = 1.0)
  {
    const double alpha2 = 2 * M_PI * M_PI;
    return q0
           / (alpha2 * alpha2 / (1 + alpha2 / S) + k + shear_modulus * alpha2);
  }

  struct Result
  {
    double w_centre;
    double psi_edge;
  };


  /// The scene: `cells_full` cells per side of the full plate, of which
  /// a quarter model meshes the quarter x, y >= 0.
  inline std::string
  scene_text(const unsigned int degree,
             const unsigned int cells_full,
             const bool         quarter,
             const double       thickness_ratio,
             const std::string &shear_integration,
             const std::string &element = "lagrange")
  {
    std::ostringstream scene;
    scene << std::setprecision(17) << "subsection Analysis\n"
          << "  set Type = static\n"
          << "end\n"
          << liftoff_tests::square_plate(thickness_ratio,
                                         poisson_ratio,
                                         shear_correction)
          << "subsection Foundation\n"
          << "  set Model = none\n"
          << "end\n"
          << liftoff_tests::all_edges("hard simply supported");
    const unsigned int cells = quarter ? cells_full / 2 : cells_full;
    scene << "subsection Discretization\n"
          << "  set Symmetry = " << (quarter ? "quarter" : "full") << "\n"
          << "  set Cells along x = " << cells << "\n"
          << "  set Cells along y = " << cells << "\n"
          << "  set Polynomial degree = " << degree << "\n"
          << "  set Shear integration = " << shear_integration << "\n"
          << "  set Element = " << element << "\n"
          << "end\n"
          << "subsection Loads\n"
          << "  subsection Pressure 1\n"
          << "    set Magnitude = 1\n"
          << "    set Region = whole plate\n"
          << "  end\n"
          << "end\n";
    return scene.str();
  }


  inline Result
  run_navier(const unsigned int degree,
             const unsigned int cells_full, // cells per side on the full plate
             const bool         quarter,
             const double       thickness_ratio,
             const std::string &shear_integration,
             const std::string &element = "lagrange")
  {
    const std::string scene = scene_text(
      degree, cells_full, quarter, thickness_ratio, shear_integration, element);
    {
      const auto sim = liftoff_tests::run_scene(scene);
      // psi_x at the midpoint of the right edge, through the library's
      // own point functional (component 1).
      const liftoff::PointFunctional rotation(sim->get_discretization(),
                                              Point<2>(0.5, 0.0),
                                              1);
      const double                   psi =
        Utilities::MPI::sum(rotation.local_value(sim->solution()),
                            MPI_COMM_WORLD);
      return Result{sim->deflection_at(Point<2>(0, 0)), psi};
    }
  }
} // namespace navier
