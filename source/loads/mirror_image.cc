#include <liftoff/loads/mirror_image.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace mirror_image
  {
    Point<2>
    mirrored(const Point<2> &p, const unsigned int axis)
    {
      Point<2> q = p;
      q[axis]    = -q[axis];
      return q;
    }


    bool
    nearly_equal(const double a, const double b)
    {
      return std::abs(a - b)
             <= 1e-10 * std::max(1.0, std::abs(a) + std::abs(b));
    }


    bool
    is_mirrored_rectangle(const BoundingBox<2> &a,
                          const BoundingBox<2> &b,
                          const unsigned int    axis)
    {
      const Point<2> lo = a.get_boundary_points().first;
      const Point<2> hi = a.get_boundary_points().second;
      // Mirroring swaps the roles of the corners along the axis.
      Point<2> image_lo = lo, image_hi = hi;
      image_lo[axis] = -hi[axis];
      image_hi[axis] = -lo[axis];
      return (image_lo - b.get_boundary_points().first).norm() <= 1e-12
             && (image_hi - b.get_boundary_points().second).norm() <= 1e-12;
    }


    bool
    is_mirrored_segment(const PatchIntegrator::Segment &a,
                        const PatchIntegrator::Segment &b,
                        const unsigned int              axis)
    {
      const Point<2> start = mirrored(a.start, axis),
                     end   = mirrored(a.end, axis);
      const auto near      = [](const Point<2> &p, const Point<2> &q) {
        return p.distance(q) < 1e-12;
      };
      return (near(start, b.start) && near(end, b.end))
             || (near(start, b.end) && near(end, b.start));
    }
  } // namespace mirror_image
} // namespace liftoff
