#pragma once

#include <deal.II/base/point.h>

#include <functional>

namespace liftoff
{
  using namespace dealii;

  /**
   * What a temperature field through the thickness imposes on the plate at
   * a point, beyond the loads: the free curvature kappa_T (the same in both
   * directions, no twist) that the bending moments are measured from, and
   * the self-equilibrating stress of a nonlinear profile at the two faces,
   * which adds stress but no deflection (doc/model.md, "Temperature");
   * the same of a base's own temperature, where it has one (doc/model.md,
   * "A base layer"). Dimensionless: kappa_T in the solver's curvature D /
   * F0, the stresses in F0 / L^2.
   */
  struct FreeBending
  {
    /// The slab's alpha dT / H_s ...
    double curvature = 0;
    /// ... its stress at the bed-side face (z = +H/2) ...
    double bottom_stress = 0;
    /// ... and at the other (z = -H/2).
    double top_stress = 0;
    /// The base's alpha_b dT_b / H_b and its faces' stresses (its own
    /// modulus), 0 without a temperature of its own.
    double base_curvature = 0, base_bottom_stress = 0, base_top_stress = 0;

    /// Adds `factor` times `other`: loads act together by superposition.
    void
    add(const FreeBending &other, const double factor)
    {
      curvature += factor * other.curvature;
      bottom_stress += factor * other.bottom_stress;
      top_stress += factor * other.top_stress;
      base_curvature += factor * other.base_curvature;
      base_bottom_stress += factor * other.base_bottom_stress;
      base_top_stress += factor * other.base_top_stress;
    }
  };

  /// FreeBending at a point of the plate at one time; empty: none.
  using FreeBendingField = std::function<FreeBending(const Point<2> &)>;
} // namespace liftoff
