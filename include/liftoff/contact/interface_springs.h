#pragma once

#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/base_layer.h>

namespace liftoff
{
  /**
   * The springs between a slab and the base it rests on, where the slab can
   * lift off (BaseLayer, tensionless): a pressure k_i (w_slab - w_base -
   * g_i) that pushes but never pulls, g_i the interface's gap, at the
   * Gauss points of every cell, with a status per point. The bed's rule
   * over other fields: its Gauss points measure w_slab - w_base instead of
   * the bed's w, so the status, the gap's load and work, the matrix
   * updates, the active-set iteration and the diagnostics are the bed's
   * code (TensionlessWinklerFoundation), and the iteration drives
   * the interface and the bed together until neither changes.
   */
  class InterfaceSprings : public TensionlessWinklerFoundation
  {
  public:
    /// The springs k_i of `base` on its gap g_i (its Interface stiffness
    /// and gap).
    void
    use_base(const BaseLayer &base);
    std::string
    energy_column() const override
    {
      return "interface";
    }

  protected:
    /// w_slab - w_base.
    std::vector<FoundationPoints::Part>
    measured_fields(const FiniteElement<2> &fe) const override;
  };
} // namespace liftoff
