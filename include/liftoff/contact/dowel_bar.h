#pragma once

#include <deal.II/base/parameter_handler.h>

namespace liftoff
{
  using namespace dealii;

  /**
   * A steel dowel bar across an open joint, embedded in the concrete of
   * both slabs: Friberg's beam on an elastic foundation of modulus K (the
   * modulus of dowel support) on each side, the bare bar across the
   * opening z. A shear force P across the joint moves one slab against the
   * other by Delta = P / C,
   *
   *   1 / C = (2 + beta z) / (2 beta^3 E I) + z (1 + beta z) / (2 beta^2 E I)
   *           + z^3 / (12 E I) + z / (G A_s),
   *
   * beta = (K d / (4 E I))^(1/4): twice the bar's deflection at the face
   * of the concrete, the rotation of the faces carried across the opening,
   * the bar's bending and its shear (A_s = 0.9 A) across it
   * (doc/model.md). The largest bearing stress on the concrete is K times
   * the deflection at the face, K P (2 + beta z) / (4 beta^3 E I).
   */
  struct DowelBar
  {
    double diameter        = 0;
    double modulus         = 0;
    double poisson_ratio   = 0.3;
    double support_modulus = 0;
    double opening         = 0;

    /// Its entries in the current subsection (`Slabs/Dowels`).
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// C, the force per unit relative deflection of the two slabs.
    double
    stiffness() const;
    /// The bearing stress on the concrete at the face of the joint under
    /// a force P.
    double
    bearing_stress(const double force) const;
  };
} // namespace liftoff
