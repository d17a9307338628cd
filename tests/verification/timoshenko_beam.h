#pragma once

// What the beam tests (static_beam_winkler.cc, static_beam_liftoff.cc) share:
// the plate strip that acts as a Timoshenko beam, the scene that models it,
// the closed form of a Timoshenko beam on an elastic foundation with its
// independent self-checks, and the sampling of a reference deflection.
//
// With nu = 0, free long edges and a load that is uniform across the width,
// the Mindlin strip is exactly a Timoshenko beam per unit width: w and psi_x
// do not depend on y, psi_y = 0, the twisting and Poisson couplings vanish,
// and bending stiffness 1, shear stiffness S = 6 chi (1 - nu) / Delta^2 and
// foundation modulus Gamma act per unit width. The discrete solution is
// y-independent too: for a y-independent field the 2D weak form against any
// test function equals the 1D weak form against the test function's average
// across the width (the (p+1)-point Gauss rules integrate these products
// exactly in y), and the nodal loads of beam_strip_scene() are the consistent
// loads of a uniform line load. So the FE strip is the 1D Timoshenko beam
// element, and w_h must converge to the closed form at the optimal rate p + 1
// (where the foundation is linear).
//
// Half model x >= 0: the line load q (per unit width, along x = 0) is given
// as point loads on x = 0 whose magnitudes are the consistent nodal loads of
// q on the edge of the single cell across the strip (Q1: q mu / 2 at both
// corners; Q2: Simpson weights q mu (1/6, 4/6, 1/6)); the library applies
// half of a point load that lies on the symmetry plane, so the half strip
// carries q / 2 per unit width.

#include <deal.II/base/quadrature_lib.h>

#include "test_tools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace liftoff_tests
{
  // Internal linkage, as when this code was part of each test: the compiler
  // then inlines the closed form into main() and evaluates its complex
  // constants at compile time, as before, so the printed closed-form residuals
  // (rounding noise) keep their values to the last digit.
  namespace
  {
    /// Parameters of the strip, the same in all beam tests (the foundation
    /// model and modulus are the tests' own).
    namespace beam_strip
    {
      constexpr double mu          = 0.05; // strip width / length
      constexpr double Delta       = 0.1;  // thickness / length
      constexpr double chi         = 5.0 / 6.0;
      constexpr double line_load   = 1.0; // q, force per unit width
      constexpr double half_length = 0.5; // meshed part [0, 1/2]

      /// Shear stiffness per unit width, independent of the library's
      /// MindlinPlate::shear_stiffness().
      constexpr double S = 6.0 * chi * (1.0 - 0.0) / (Delta * Delta);
      /// Load F carried by the half beam.
      constexpr double F = line_load / 2;
    } // namespace beam_strip


    /**
     * Timoshenko beam on a Winkler foundation, per unit width:
     *   psi'' + S (w' - psi) = 0,  S (w' - psi)' - Gamma w = 0  on (0, l),
     * moment M = psi', shear force Q = S (w' - psi). Solutions are
     * w = sum_k c_k e^{lambda_k x}, psi = sum_k c_k b_k e^{lambda_k x} with
     * lambda^4 - (Gamma / S) lambda^2 + Gamma = 0 and b = S lambda / (S -
     * lambda^2) (from the first equation). The four constants follow from
     *   psi(0) = 0 (symmetry), Q(0) = -F (the load F presses at x = 0),
     *   M(l) = 0, Q(l) = 0 (free end, or edge of the contact zone).
     * Sign of Q(0): the weak form on [0, l] has the boundary term
     * -Q(0) dw(0), which balances the load F dw(0), so Q(0) = -F; then
     * Q' = Gamma w > 0 brings Q up to zero at x = l, i.e. the foundation
     * reaction Gamma int w equals F.
     */
    class TimoshenkoBeamOnFoundation
    {
    public:
      using cd = std::complex<double>;

      TimoshenkoBeamOnFoundation(const double shear, const double modulus)
          : S(shear)
      {
        const cd root =
          std::sqrt(cd(modulus * modulus / (S * S) - 4 * modulus));
        const cd r1 = 0.5 * (modulus / S + root);
        const cd r2 = 0.5 * (modulus / S - root);
        lambda      = {
               {std::sqrt(r1), -std::sqrt(r1), std::sqrt(r2), -std::sqrt(r2)}};
        for (unsigned int k = 0; k < 4; ++k)
          b[k] = S * lambda[k] / (S - lambda[k] * lambda[k]);
      }

      /// Solve for the constants on [0, l] with the load F at x = 0.
      void
      solve(const double l, const double F)
      {
        // Growing modes are written as e^{lambda (x - l)}, decaying ones as
        // e^{lambda x}, so that no basis function overflows.
        for (unsigned int k = 0; k < 4; ++k)
          origin[k] = (lambda[k].real() > 0 ? l : 0.0);

        std::array<std::array<cd, 5>, 4> A; // augmented matrix
        for (unsigned int k = 0; k < 4; ++k)
          {
            const cd e0 = mode(k, 0.0), el = mode(k, l);
            A[0][k] = b[k] * e0;                   // psi(0)
            A[1][k] = S * (lambda[k] - b[k]) * e0; // Q(0)
            A[2][k] = b[k] * lambda[k] * el;       // M(l)
            A[3][k] = S * (lambda[k] - b[k]) * el; // Q(l)
          }
        A[0][4] = 0;
        A[1][4] = -F;
        A[2][4] = 0;
        A[3][4] = 0;

        // Gaussian elimination with partial pivoting.
        for (unsigned int i = 0; i < 4; ++i)
          {
            unsigned int pivot = i;
            for (unsigned int r = i + 1; r < 4; ++r)
              if (std::abs(A[r][i]) > std::abs(A[pivot][i]))
                pivot = r;
            std::swap(A[i], A[pivot]);
            for (unsigned int r = i + 1; r < 4; ++r)
              {
                const cd factor = A[r][i] / A[i][i];
                for (unsigned int j = i; j < 5; ++j)
                  A[r][j] -= factor * A[i][j];
              }
          }
        for (int i = 3; i >= 0; --i)
          {
            cd sum = A[i][4];
            for (unsigned int j = i + 1; j < 4; ++j)
              sum -= A[i][j] * c[j];
            c[i] = sum / A[i][i];
          }
      }

      double
      w(const double x) const
      {
        return combination(x, {{1, 1, 1, 1}}).real();
      }

      double
      psi(const double x) const
      {
        return combination(x, b).real();
      }

      /// |Im w| + |Im psi|: the conditions are real, so this must vanish.
      double
      imaginary_part(const double x) const
      {
        return std::abs(combination(x, {{1, 1, 1, 1}}).imag())
               + std::abs(combination(x, b).imag());
      }

    private:
      double                S;
      std::array<cd, 4>     lambda, b, c;
      std::array<double, 4> origin{};

      cd
      mode(const unsigned int k, const double x) const
      {
        return std::exp(lambda[k] * (x - origin[k]));
      }

      cd
      combination(const double x, const std::array<cd, 4> &factor) const
      {
        cd sum = 0;
        for (unsigned int k = 0; k < 4; ++k)
          sum += c[k] * factor[k] * mode(k, x);
        return sum;
      }
    };


    /// Independent checks of the closed form on [0, l], by finite differences
    /// and quadrature of its values only: the ODEs, the four boundary
    /// conditions and the global equilibrium Gamma int_0^l w = F.
    inline void
    verify_closed_form(const TimoshenkoBeamOnFoundation &beam,
                       const double                      S,
                       const double                      modulus,
                       const double                      l,
                       const double                      F,
                       Checks                           &checks)
    {
      const double h = 1e-3;
      // Fourth-order central differences.
      const auto d1 = [h](const auto &f, const double x) {
        return (f(x - 2 * h) - 8 * f(x - h) + 8 * f(x + h) - f(x + 2 * h))
               / (12 * h);
      };
      const auto d2 = [h](const auto &f, const double x) {
        return (-f(x - 2 * h) + 16 * f(x - h) - 30 * f(x) + 16 * f(x + h)
                - f(x + 2 * h))
               / (12 * h * h);
      };
      const auto w   = [&](const double x) { return beam.w(x); };
      const auto psi = [&](const double x) { return beam.psi(x); };

      // Residuals of both equations relative to the size of their terms.
      double residual = 0, scale = 0, imaginary = 0, w_max = 0;
      for (unsigned int i = 1; i < 50; ++i)
        {
          const double x  = l * i / 50.0;
          const double r1 = d2(psi, x) + S * (d1(w, x) - psi(x));
          const double r2 = S * (d2(w, x) - d1(psi, x)) - modulus * w(x);
          residual        = std::max({residual, std::abs(r1), std::abs(r2)});
          scale           = std::max(scale, modulus * std::abs(w(x)));
          imaginary       = std::max(imaginary, beam.imaginary_part(x));
          w_max           = std::max(w_max, std::abs(w(x)));
        }
      checks.less("closed form: ODE residual / Gamma max|w|",
                  residual / scale,
                  1e-6);
      checks.less("closed form: imaginary part / max|w|",
                  imaginary / w_max,
                  1e-10);
      checks.less("closed form: psi(0) / max|w|",
                  std::abs(psi(0)) / w_max,
                  1e-10);

      // Boundary values by one-sided differences (points inside [0, l]).
      const auto d1_forward = [h](const auto &f, const double x) {
        return (-25 * f(x) + 48 * f(x + h) - 36 * f(x + 2 * h)
                + 16 * f(x + 3 * h) - 3 * f(x + 4 * h))
               / (12 * h);
      };
      const auto d1_backward = [h](const auto &f, const double x) {
        return (25 * f(x) - 48 * f(x - h) + 36 * f(x - 2 * h)
                - 16 * f(x - 3 * h) + 3 * f(x - 4 * h))
               / (12 * h);
      };
      checks.less("closed form: |Q(0) + F| / F",
                  std::abs(S * (d1_forward(w, 0.0) - psi(0.0)) + F) / F,
                  1e-4);
      checks.less("closed form: |M(l)| l / F",
                  std::abs(d1_backward(psi, l)) * l / F,
                  1e-4);
      checks.less("closed form: |Q(l)| / F",
                  std::abs(S * (d1_backward(w, l) - psi(l))) / F,
                  1e-4);

      // Global equilibrium of the half beam: Gamma int_0^l w = F.
      const QGauss<1> gauss(8);
      double          integral = 0;
      const unsigned  n        = 200;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int q = 0; q < gauss.size(); ++q)
          integral +=
            beam.w(l * (i + gauss.point(q)[0]) / n) * gauss.weight(q) * l / n;
      checks.less("closed form: |Gamma int w - F| / F",
                  std::abs(modulus * integral - F) / F,
                  1e-10);
    }


    /// The static half strip of beam_strip on the foundation `model`
    /// ("bilateral" or "tensionless") of modulus Gamma, one cell across, with
    /// the consistent nodal loads of the line load at x = 0 (see the top).
    inline std::string
    beam_strip_scene(const std::string &model,
                     const double       Gamma,
                     const unsigned int degree,
                     const unsigned int n_cells_x)
    {
      using namespace beam_strip;
      std::ostringstream s;
      s.precision(17);
      s << "subsection Analysis\n  set Type = static\nend\n"
        << "subsection Plate\n"
        << "  set Aspect ratio = " << mu << "\n"
        << "  set Thickness ratio = " << Delta << "\n"
        << "  set Poisson ratio = 0\n"
        << "  set Shear correction factor = " << chi << "\n"
        << "end\n"
        << "subsection Discretization\n"
        << "  set Symmetry = half\n"
        << "  set Cells along x = " << n_cells_x << "\n"
        << "  set Cells along y = 1\n"
        << "  set Polynomial degree = " << degree << "\n"
        << "end\n"
        << "subsection Foundation\n"
        << "  set Model = " << model << "\n"
        << "  set Stiffness = " << Gamma << "\n"
        << "end\n";
      // Consistent nodal loads of q on the edge x = 0 of the one cell across.
      std::vector<std::pair<double, double>> y_and_weight;
      if (degree == 1)
        y_and_weight = {{-mu / 2, 0.5}, {mu / 2, 0.5}};
      else
        y_and_weight = {{-mu / 2, 1.0 / 6}, {0.0, 4.0 / 6}, {mu / 2, 1.0 / 6}};
      s << "subsection Loads\n";
      for (unsigned int i = 0; i < y_and_weight.size(); ++i)
        s << "  subsection Point load " << i + 1 << "\n"
          << "    set Magnitude = " << line_load * mu * y_and_weight[i].second
          << "\n"
          << "    set Position = 0, " << y_and_weight[i].first << "\n"
          << "  end\n";
      s << "end\n";
      return s.str();
    }


    /// A reference deflection w along the half strip at sample points that
    /// avoid the mesh nodes (where 1D FE solutions can be superconvergent):
    /// the midpoints of n equal parts of [0, 1/2].
    class DeflectionSamples
    {
    public:
      template <typename Deflection>
      explicit DeflectionSamples(const Deflection  &w_reference,
                                 const unsigned int n = 400)
          : x(n)
          , w(n)
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            x[i] = beam_strip::half_length * (i + 0.5) / n;
            w[i] = w_reference(x[i]);
            rms += w[i] * w[i];
          }
        rms = std::sqrt(rms / n);
      }

      /// Discrete L2 norm of w_h - w over the samples, relative to that of w.
      template <typename Deflection>
      double
      relative_l2_error(const Deflection &w_h) const
      {
        double error = 0;
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            const double difference = w_h(x[i]) - w[i];
            error += difference * difference;
          }
        return std::sqrt(error / x.size()) / rms;
      }

      std::vector<double> x, w;
      double              rms = 0;
    };


    /// Bisection for a sign change of f in [lo, hi] with f(lo) > 0 >= f(hi).
    template <typename Function>
    double
    bisect(const Function &f, double lo, double hi)
    {
      for (unsigned int i = 0; i < 60 && hi - lo > 1e-14; ++i)
        {
          const double mid       = 0.5 * (lo + hi);
          (f(mid) > 0 ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    }


    /// The closed form's contact half-length on a tensionless bed: the
    /// first a at which w(a), with the other four conditions imposed at a,
    /// turns from positive to negative; -1 if the strip does not lift off.
    /// Leaves `beam` solved for that a.
    inline double
    contact_half_length(TimoshenkoBeamOnFoundation &beam, const double force)
    {
      const auto w_at_edge = [&](const double a) {
        beam.solve(a, force);
        return beam.w(a);
      };
      double a = -1;
      for (double x = 0.005; x < beam_strip::half_length; x += 0.005)
        if (w_at_edge(x) > 0 && w_at_edge(x + 0.005) <= 0)
          {
            a = bisect(w_at_edge, x, x + 0.005);
            break;
          }
      if (a > 0)
        beam.solve(a, force);
      return a;
    }


    /// The first zero of a deflection w_h along the axis of the half strip
    /// (scanned at n points, then bisected); 1/2 if it has none.
    template <typename Deflection>
    double
    first_zero(const Deflection &w_h, const unsigned int n_scan = 1000)
    {
      for (unsigned int i = 1; i <= n_scan; ++i)
        {
          const double x0 = beam_strip::half_length * (i - 1) / n_scan;
          const double x1 = beam_strip::half_length * i / n_scan;
          if (w_h(x1) <= 0)
            return bisect(w_h, x0, x1);
        }
      return beam_strip::half_length;
    }
  } // namespace
} // namespace liftoff_tests
