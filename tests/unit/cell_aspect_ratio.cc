// PlateGeometry::largest_cell_aspect_ratio(), which the hint of an
// ill-conditioned solve quotes, against the aspect ratios of cells known
// in closed form (it returned 1 for every shape but the rectangle):
// - tests/meshes/thin_strip.msh, rectangles 0.2 x 0.008: 25;
// - tests/meshes/sheared_strip.msh, parallelograms of edges a = (0.2, 0)
//   and b = (0.3, 0.01): the Jacobian [a b] has singular values with
//   s1 s2 = |det| = 0.002 and s1^2 + s2^2 = |a|^2 + |b|^2 = 0.1301, so
//   r + 1 / r = 0.1301 / 0.002 for r = s1 / s2;
// - an annulus of 4 coarse cells (R_i = 0.05, R = 0.5: hyper_shell's
//   trapezoids, corners at the angles k pi / 2 on both circles): the
//   bilinear map's Jacobian at the 2 x 2 Gauss points, written out here;
// - the rectangle's width / height, as before (Aspect ratio 0.1 on 4 x 4
//   cells: 10).
// The same measure on every rank: the coarse mesh, not the distributed one.

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/physical_units.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_geometry.h>

#include <test_tools.h>

#include <algorithm>
#include <cmath>

using namespace liftoff_tests;

namespace
{
  double
  ratio_of(const std::string &scene, const double aspect_ratio = 1)
  {
    ParameterHandler prm;
    liftoff::PlateGeometry::declare_parameters(prm);
    prm.parse_input_from_string(scene);
    liftoff::MindlinPlate plate;
    plate.aspect_ratio = aspect_ratio;
    liftoff::PlateGeometry geometry;
    geometry.parse_parameters(prm, plate, liftoff::PhysicalUnits());
    return geometry.largest_cell_aspect_ratio();
  }

  std::string
  mesh_file(const std::string &name)
  {
    return set("Discretization/Shape", "mesh file")
           + set("Discretization/Mesh file",
                 std::string(LIFTOFF_SOURCE_DIR) + "/tests/meshes/" + name);
  }

  // s1 / s2 of the 2 x 2 matrix [[a, b], [c, d]] from its Frobenius norm
  // and determinant: r + 1 / r = (a^2 + b^2 + c^2 + d^2) / |ad - bc|.
  double
  singular_value_ratio(const double a,
                       const double b,
                       const double c,
                       const double d)
  {
    const double t = (a * a + b * b + c * c + d * d) / std::abs(a * d - b * c);
    return (t + std::sqrt(t * t - 4)) / 2;
  }

  // The cell between the angles -pi/n and pi/n of a ring of n cells (all
  // are this one turned): x(xi, eta) = r(xi) (cos(pi/n), sin(pi/n) (2 eta
  // - 1)), r(xi) = R_i + xi (R - R_i), mapped bilinearly.
  double
  ring_cell_ratio(const double inner, const double outer, const unsigned int n)
  {
    const double c = std::cos(M_PI / n), s = std::sin(M_PI / n);
    double       largest = 0;
    for (const double xi : {0.5 - 0.5 / std::sqrt(3), 0.5 + 0.5 / std::sqrt(3)})
      for (const double eta :
           {0.5 - 0.5 / std::sqrt(3), 0.5 + 0.5 / std::sqrt(3)})
        {
          const double r = inner + xi * (outer - inner);
          largest =
            std::max(largest,
                     singular_value_ratio((outer - inner) * c,
                                          0,
                                          (outer - inner) * s * (2 * eta - 1),
                                          2 * s * r));
        }
    return largest;
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  Checks checks(argc, argv);

  const double thin = ratio_of(mesh_file("thin_strip.msh"));
  checks.less("rectangles 0.2 x 0.008 of a mesh file: ratio "
                + std::to_string(thin) + " against 25, relative difference",
              std::abs(thin / 25 - 1),
              1e-12);

  const double sheared  = ratio_of(mesh_file("sheared_strip.msh"));
  const double expected = singular_value_ratio(0.2, 0.3, 0, 0.01);
  checks.less("parallelograms (0.2, 0), (0.3, 0.01) of a mesh file: ratio "
                + std::to_string(sheared) + " against "
                + std::to_string(expected) + ", relative difference",
              std::abs(sheared / expected - 1),
              1e-12);

  const double ring = ratio_of(set("Discretization/Shape", "annulus")
                               + set("Discretization/Radius", 0.5)
                               + set("Discretization/Inner radius", 0.05));
  // At least 8 cells round the ring (PlateGeometry::n_ring_cells()).
  const double ring_expected = ring_cell_ratio(0.05, 0.5, 8);
  checks.less("annulus R_i = 0.05, R = 0.5 (8 cells): ratio "
                + std::to_string(ring) + " against "
                + std::to_string(ring_expected) + ", relative difference",
              std::abs(ring / ring_expected - 1),
              1e-12);

  const double rectangle = ratio_of(set("Discretization/Cells along x", 4)
                                      + set("Discretization/Cells along y", 4),
                                    0.1);
  checks.less("rectangle, Aspect ratio 0.1 on 4 x 4 cells: ratio "
                + std::to_string(rectangle)
                + " against 10, relative difference",
              std::abs(rectangle / 10 - 1),
              1e-14);
  return checks.exit_code();
}
