// Curling stress of a slab on a bilateral bed under a uniform temperature
// difference dT (Loads/Temperature load), against references liftoff does
// not compute:
//  - the infinite strip of width b (free edges x = +-b/2, long along y) on
//    a Winkler bed under the thermal moment, solved here in closed form
//    (Kirchhoff, plane strain along y): D w'''' + k w = 0 with the free
//    edge's M_xx = 0 (w'' = (1 + nu) kappa_T) and Q_x = 0 (w''' = 0), w =
//    A cosh(bx) cos(bx) + B sinh(bx) sin(bx), b = (k / 4D)^(1/4). A thin
//    slab b = 4 l wide and 16 l long, quarter model: M_xx and M_yy at its
//    centre and across, and M_yy at the edge (exactly D (1 - nu^2)
//    kappa_T, Bradbury's edge stress E alpha dT / 2). The strip's C factor
//    is printed beside Bradbury's formula;
//  - Huang's Example 4.1 (Pavement Analysis and Design): a slab 7.62 m x
//    3.66 m x 203 mm, dT = 11.1 K (20 F), k = 54.3 MPa/m, alpha = 9e-6 /K,
//    E = 27.6 GPa (4e6 psi), nu = 0.15: Bradbury's formulas give 238 psi
//    inside and 214 psi at the edge (Huang: 238 to 240 and 214 to 216 by
//    chart and formula). liftoff's Mindlin slab, in SI, against them.

#include "test_tools.h"

#include <cmath>

namespace
{
  using liftoff_tests::set;

  // Bradbury's (Westergaard's) C(L / l).
  double
  bradbury(const double length_over_l)
  {
    const double l = length_over_l / std::sqrt(8.0);
    return 1
           - 2 * std::cos(l) * std::cosh(l) * (std::tan(l) + std::tanh(l))
               / (std::sin(2 * l) + std::sinh(2 * l));
  }

  // f(x) = w''(x) / ((1 + nu) kappa_T) of the free strip |x| <= a, beta =
  // 1 / (l sqrt(2)): f(a) = 1, f'(a) = 0.
  struct Strip
  {
    double a, beta, first = 0, second = 0;
    Strip(const double a, const double l)
        : a(a)
        , beta(1 / (l * std::sqrt(2.0)))
    {
      const double t = beta * a, sh = std::sinh(t), ch = std::cosh(t),
                   s = std::sin(t), c = std::cos(t);
      // -A sh s + B ch c = 1, -A (ch s + sh c) + B (sh c - ch s) = 0.
      const double m11 = -sh * s, m12 = ch * c, m21 = -(ch * s + sh * c),
                   m22 = sh * c - ch * s, det = m11 * m22 - m12 * m21;
      first  = m22 / det;
      second = -m21 / det;
    }
    double
    f(const double x) const
    {
      const double t = beta * x;
      return -first * std::sinh(t) * std::sin(t)
             + second * std::cosh(t) * std::cos(t);
    }
  };
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  // The strip: b = L = 1, l = 1/4 (Gamma = 256), 16 l long.
  {
    const double nu = 0.15, delta = 0.005, alpha = 1e-5, dt = 10,
                 kappa = alpha * dt / delta, l = 0.25;
    const Strip strip(0.5, l);
    const auto  run = liftoff_tests::run_scene(
      set("Analysis/Type", "static") + set("Foundation/Model", "bilateral")
      + set("Foundation/Stiffness", std::pow(l, -4))
      + set("Plate/Aspect ratio", 4) + set("Plate/Thickness ratio", delta)
      + set("Plate/Poisson ratio", nu)
      + set("Discretization/Symmetry", "quarter")
      + set("Discretization/Cells along x", 16)
      + set("Discretization/Cells along y", 48)
      + set("Discretization/Polynomial degree", 2)
      + set("Loads/Temperature load 1/Magnitude", dt)
      + set("Loads/Temperature load 1/Expansion coefficient", alpha)
      + set("Output/Probe quantities",
            "M_xx(0; 0), M_yy(0; 0), M_xx(0.25; 0), M_yy(0.25; 0), "
             "M_yy(0.5; 0)"));
    const auto               &row      = run->history().back();
    const double              m_t      = (1 + nu) * kappa;
    const std::vector<double> m_xx     = row.probes("M_xx"),
                              m_yy     = row.probes("M_yy");
    const std::vector<double> exact_xx = {m_t * (1 - strip.f(0)),
                                          m_t * (1 - strip.f(0.25))},
                              exact_yy = {m_t * (1 - nu * strip.f(0)),
                                          m_t * (1 - nu * strip.f(0.25)),
                                          m_t * (1 - nu)};
    double error                       = 0;
    for (unsigned int k = 0; k < 2; ++k)
      error = std::max(error, std::abs(m_xx[k] - exact_xx[k]) / m_t);
    for (unsigned int k = 0; k < 3; ++k)
      error = std::max(error, std::abs(m_yy[k] - exact_yy[k]) / m_t);
    // The strip's C at the centre, from sigma_x = E alpha dT / (2 (1 -
    // nu^2)) (C_x + nu C_y) with C_y = 1.
    const double c_strip   = 1 - (1 + nu) * strip.f(0);
    const double c_liftoff = m_xx[0] / m_t * (1 + nu) - nu;
    std::cout << "strip b = 4 l: M_xx(0) " << m_xx[0] << " (exact "
              << exact_xx[0] << "), M_yy(0) " << m_yy[0] << " (exact "
              << exact_yy[0] << "), edge M_yy " << m_yy[2] << " (exact "
              << exact_yy[2] << "); C: strip " << c_strip << ", liftoff "
              << c_liftoff << ", Bradbury " << bradbury(4) << std::endl;
    checks.less("strip: max |M - Kirchhoff strip| / ((1 + nu) D kappa_T) at "
                "the centre, x = b/4 and the edge",
                error,
                5e-3);
  }

  // Huang's Example 4.1, in SI.
  {
    const double psi = 6894.757, e = 4e6 * psi, nu = 0.15, h = 0.203,
                 k = 54.3e6, alpha = 9e-6, dt = 11.1;
    const double l   = std::pow(e * h * h * h / (12 * (1 - nu * nu) * k), 0.25);
    const double c_x = bradbury(7.62 / l), c_y = bradbury(3.66 / l);
    const double interior =
      e * alpha * dt / (2 * (1 - nu * nu)) * (c_x + nu * c_y) / psi;
    const double edge = c_x * e * alpha * dt / 2 / psi;
    std::cout << "Huang 4.1: l = " << l << " m, C_x = " << c_x
              << ", C_y = " << c_y << "; Bradbury: interior " << interior
              << " psi, edge " << edge << " psi" << std::endl;
    checks.within("Huang 4.1: Bradbury's interior stress [psi]",
                  interior,
                  236,
                  241);
    checks.within("Huang 4.1: Bradbury's edge stress [psi]", edge, 212, 217);
    const auto run = liftoff_tests::run_scene(
      set("Units/System", "SI") + set("Units/Length", 7.62)
      + set("Units/Width", 3.66) + set("Units/Thickness", h)
      + set("Units/Young's modulus", e) + set("Units/Density", 2400)
      + set("Units/Gravity", 0) + set("Units/Subgrade modulus", k)
      + set("Plate/Poisson ratio", nu) + set("Analysis/Type", "static")
      + set("Foundation/Model", "bilateral")
      + set("Discretization/Symmetry", "quarter")
      + set("Discretization/Cells along x", 24)
      + set("Discretization/Cells along y", 12)
      + set("Discretization/Polynomial degree", 2)
      + set("Loads/Temperature load 1/Magnitude", dt)
      + set("Loads/Temperature load 1/Expansion coefficient", alpha)
      + set("Output/Probe quantities",
            "sigma_xx(0; 0), sigma_yy(0; 0), sigma_xx(0; 1.83)"));
    const auto &row = run->history().back();
    // The history in memory is the solver's: stresses in F0 / L^2 = D / L^3.
    const double d       = e * h * h * h / (12 * (1 - nu * nu)),
                 unit    = d / std::pow(7.62, 3) / psi;
    const double fe_in   = row.probes("sigma_xx")[0] * unit,
                 fe_y    = row.probes("sigma_yy")[0] * unit,
                 fe_edge = row.probes("sigma_xx")[1] * unit;
    std::cout << "Huang 4.1, liftoff: sigma_xx(0; 0) " << fe_in
              << " psi, sigma_yy(0; 0) " << fe_y << " psi, edge sigma_xx(0; "
              << "1.83) " << fe_edge << " psi" << std::endl;
    checks.within("Huang 4.1: liftoff's interior / Bradbury's",
                  fe_in / interior,
                  0.97,
                  1.02);
    checks.within("Huang 4.1: liftoff's edge / Bradbury's",
                  fe_edge / edge,
                  0.98,
                  1.03);
  }
  return checks.exit_code();
}
