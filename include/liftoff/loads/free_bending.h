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
   * which adds stress but no deflection (doc/model.md, "Temperature").
   * Dimensionless: kappa_T in the solver's curvature D / F0, the stresses
   * in F0 / L^2.
   */
  struct FreeBending
  {
    double curvature = 0;
    /// At the bed-side face (z = +H/2) ...
    double bottom_stress = 0;
    /// ... and at the other (z = -H/2).
    double top_stress = 0;
  };

  /// FreeBending at a point of the plate at one time; empty: none.
  using FreeBendingField = std::function<FreeBending(const Point<2> &)>;
} // namespace liftoff
