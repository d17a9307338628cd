#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>

#include <liftoff/fem/patch_integrator.h>

namespace liftoff
{
  using namespace dealii;

  /// The comparisons of the symmetry check of loads on a reduced model.
  namespace mirror_image
  {
    /// p mirrored in the plane normal to `axis`.
    Point<2>
    mirrored(const Point<2> &p, const unsigned int axis);

    /// Equal up to round-off, relative to the larger (or to 1).
    bool
    nearly_equal(const double a, const double b);

    /// Whether rectangle b is rectangle a mirrored normal to `axis`.
    bool
    is_mirrored_rectangle(const BoundingBox<2> &a,
                          const BoundingBox<2> &b,
                          const unsigned int    axis);

    /// Whether segment b is segment a mirrored normal to `axis`, either
    /// way round.
    bool
    is_mirrored_segment(const PatchIntegrator::Segment &a,
                        const PatchIntegrator::Segment &b,
                        const unsigned int              axis);
  } // namespace mirror_image
} // namespace liftoff
