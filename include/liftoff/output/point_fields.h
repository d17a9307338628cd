#pragma once

#include <liftoff/base/physical_units.h>

#include <string>
#include <vector>

namespace liftoff
{
  class Discretization;

  /// A field of one value per output point of this rank, in the order of
  /// ResultantSweep::points() (its cells, in each the support points of
  /// FE_DGQ(p)), and what it is, for its unit.
  struct PointField
  {
    std::string             name;
    PhysicalUnits::Quantity quantity;
    std::vector<double>     values;
  };

  /**
   * `fields` as stem.pvtu and its pieces in `directory`, each a FE_DGQ(p)
   * field whose support points are the output points, so that every value
   * is written exactly where it was computed, in the scene's `units` at the
   * time `time` (solver's units), with the moments' sign convention in
   * the metadata if `has_moments`. What the outputs that keep values per
   * output point (Envelopes, FatigueDamage) write. Collective.
   */
  void
  write_point_fields(const std::string             &directory,
                     const Discretization          &discretization,
                     const std::vector<PointField> &fields,
                     const PhysicalUnits           &units,
                     const double                   time,
                     const std::string             &stem,
                     const bool                     has_moments);
} // namespace liftoff
