// Moving loads (issue 33, step 1), against references liftoff does not
// compute itself.
//
// The load vector b at the load's current position, through the identity
// b . I(g) = int p g (g = 1, x, y, xy interpolated in the w component, in
// the element's space, so the identity is exact): a moving point load F
// gives F g(p) at its current point p anywhere in a cell; a moving disc or
// rectangle of pressure gives the closed-form force and first moments of
// the part on the plate (a disc inside: pi r^2 p and pi r^2 p c; across an
// edge: the circular segment); a load off the plate gives nothing. The
// disc's rule (PatchIntegrator's slices in t = asin((x - x_c) / r)) is
// measured against the same slices with 64 points in t.
//
// A vehicle equals the superposition of its wheels (a bilateral bed is
// linear): the probe histories of a vehicle of three point wheels, and of
// two disc wheels, against the sum of runs of each wheel alone as a
// moving point or patch load on the same path, to round-off, while the
// wheels enter the plate.

#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/patch_integrator.h>
#include <liftoff/loads/load_set.h>

#include "pressure_patches.h"
#include "test_tools.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using liftoff_tests::set;
  using pressure_patches::InWComponent;

  /// 7 x 5 cells of degree `degree` on the full plate of aspect ratio 0.8.
  std::string
  mesh(const unsigned int degree)
  {
    return set("Plate/Aspect ratio", 0.8)
           + set("Discretization/Cells along x", 7)
           + set("Discretization/Cells along y", 5)
           + set("Discretization/Polynomial degree", degree);
  }

  /// The plate and mesh of a scene, its Loads entries declared.
  struct Mesh
  {
    explicit Mesh(const std::string &scene)
        : disc(MPI_COMM_WORLD)
    {
      liftoff::MindlinPlate::declare_parameters(prm);
      liftoff::Discretization::declare_parameters(prm);
      liftoff::LoadSet::declare_parameters(prm);
      prm.parse_input_from_string(scene, "test scene");
      plate.parse_parameters(prm);
      disc.parse_parameters(prm, plate);
      disc.setup();
    }

    ParameterHandler        prm;
    liftoff::MindlinPlate   plate;
    liftoff::Discretization disc;
  };

  /// The scene's loads on its mesh: b(tau) . I(x^i y^j) for (i, j) = (0,
  /// 0), (1, 0), (0, 1), (1, 1).
  std::array<double, 4>
  load_moments(const std::string &scene, const double tau)
  {
    Mesh                           mesh_of_scene(scene);
    const liftoff::Discretization &disc = mesh_of_scene.disc;
    liftoff::LoadSet               loads;
    loads.parse_parameters(mesh_of_scene.prm);
    loads.setup(disc);
    liftoff::LA::MPI::Vector b, g;
    disc.reinit_vector(b);
    disc.reinit_vector(g);
    loads.assemble(tau, b);
    std::array<double, 4>                            m;
    const std::array<std::array<unsigned int, 2>, 4> powers = {
      {{{0, 0}}, {{1, 0}}, {{0, 1}}, {{1, 1}}}};
    for (unsigned int k = 0; k < 4; ++k)
      {
        VectorTools::interpolate(disc.mapping(),
                                 disc.dof_handler,
                                 InWComponent(powers[k][0], powers[k][1]),
                                 g);
        m[k] = b * g;
      }
    return m;
  }

  /// Largest |a_k - b_k| relative to the largest |b_k|.
  double
  relative_difference(const std::array<double, 4> &a,
                      const std::array<double, 4> &b)
  {
    double difference = 0, scale = 0;
    for (unsigned int k = 0; k < 4; ++k)
      {
        difference = std::max(difference, std::abs(a[k] - b[k]));
        scale      = std::max(scale, std::abs(b[k]));
      }
    return difference / scale;
  }

  void
  check_point_load(liftoff_tests::Checks &checks, const unsigned int degree)
  {
    // At tau = 0.7 the load is at (0.123, 0.0456): inside a cell, on none
    // of its lines.
    const std::string scene =
      mesh(degree) + set("Loads/Point load 1/Magnitude", 2.5)
      + set("Loads/Point load 1/Path", "-0.5 + 0.89*tau; 0.0456*tau/0.7");
    const double                x = -0.5 + 0.89 * 0.7, y = 0.0456;
    const std::array<double, 4> exact = {{2.5, 2.5 * x, 2.5 * y, 2.5 * x * y}};
    const std::string           label = "Q" + std::to_string(degree) + ": ";
    checks.less(label + "moving point load at (0.123, 0.0456), moments",
                relative_difference(load_moments(scene, 0.7), exact),
                1e-12);
    // At tau = 1.5 it is at x = 0.835, off the plate: nothing.
    const auto off = load_moments(scene, 1.5);
    checks.less(label + "moving point load off the plate, |force|",
                std::abs(off[0]),
                1e-300);
  }

  void
  check_patches(liftoff_tests::Checks &checks, const unsigned int degree)
  {
    const std::string label = "Q" + std::to_string(degree) + ": ";
    const double      p = 3, r = 0.07;
    const auto        disc_at = [&](const std::string &path) {
      return mesh(degree) + set("Loads/Patch load 1/Magnitude", p)
             + set("Loads/Patch load 1/Shape", "disc")
             + set("Loads/Patch load 1/Size", 2 * r)
             + set("Loads/Patch load 1/Path", path);
    };
    // Inside, cutting cells (centre (0.013, 0.021) at tau = 1).
    const double                force        = M_PI * r * r * p;
    const std::array<double, 4> inside_exact = {
      {force, force * 0.013, force * 0.021, force * 0.013 * 0.021}};
    checks.less(label + "moving disc inside the plate, moments",
                relative_difference(load_moments(disc_at("0.013*tau; "
                                                         "0.021*tau"),
                                                 1),
                                    inside_exact),
                1e-12);
    // Across the edge x = 1/2, its centre d = 0.03 inside: the disc less
    // the circular segment beyond the edge.
    const double d = 0.03;
    const double segment =
      r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d);
    const double on_plate = p * (M_PI * r * r - segment);
    checks.less(label + "moving disc across the edge x = 1/2, force",
                std::abs(load_moments(disc_at("0.47*tau; -0.1"), 1)[0]
                         - on_plate)
                  / on_plate,
                1e-12);
    // A rectangle 0.1 x 0.06 centred at (-0.48, 0.38) at tau = 2, across
    // the corner (-1/2, 0.4): the part [-0.5, -0.43] x [0.35, 0.4].
    const std::string rectangle =
      mesh(degree) + set("Loads/Patch load 1/Magnitude", p)
      + set("Loads/Patch load 1/Size", "0.1, 0.06")
      + set("Loads/Patch load 1/Path", "-0.24*tau; 0.19*tau");
    const double                x0 = -0.5, x1 = -0.43, y0 = 0.35, y1 = 0.4;
    const double                area         = (x1 - x0) * (y1 - y0);
    const std::array<double, 4> corner_exact = {
      {p * area,
       p * area * (x0 + x1) / 2,
       p * area * (y0 + y1) / 2,
       p * area * (x0 + x1) * (y0 + y1) / 4}};
    checks.less(label + "moving rectangle across a corner, moments",
                relative_difference(load_moments(rectangle, 2), corner_exact),
                1e-12);
  }

  /// The disc's rule against the same slices with 64 points in t:
  /// max |b - b_fine| / max |b_fine| over discs that cut cells in every
  /// way (inside one cell, over vertices, across the plate's edge).
  void
  check_disc_rule(liftoff_tests::Checks &checks, const unsigned int degree)
  {
    const Mesh                     mesh_of_scene(mesh(degree));
    const liftoff::Discretization &disc = mesh_of_scene.disc;
    const liftoff::PatchIntegrator usual(disc), fine(disc, 64);
    const auto                     unit = [](const Point<2> &) {
      return std::array<double, 3>{{1.0, 0.0, 0.0}};
    };
    double error = 0;
    for (const auto &[centre, radius] :
         std::vector<std::pair<Point<2>, double>>{{Point<2>(0.01, 0.02), 0.03},
                                                  {Point<2>(-0.2143, 0.08),
                                                   0.11},
                                                  {Point<2>(0.45, -0.37), 0.2},
                                                  {Point<2>(0.3, 0.3), 0.0421}})
      {
        liftoff::LA::MPI::Vector b, b_fine;
        disc.reinit_vector(b);
        disc.reinit_vector(b_fine);
        usual.add(unit, {centre, radius}, b);
        fine.add(unit, {centre, radius}, b_fine);
        const double scale = b_fine.linfty_norm();
        b -= b_fine;
        error = std::max(error, b.linfty_norm() / scale);
      }
    checks.less("Q" + std::to_string(degree) + ": disc, "
                  + std::to_string(liftoff::PatchIntegrator::default_arc_points)
                  + " points in t against 64 (max relative entry)",
                error,
                1e-12);
  }

  /// A bilateral plate, the wheels entering it from the left.
  std::string
  vehicle_base()
  {
    return set("Plate/Aspect ratio", 0.5) + set("Foundation/Model", "bilateral")
           + set("Foundation/Stiffness", 1000)
           + set("Discretization/Cells along x", 8)
           + set("Discretization/Cells along y", 4)
           + set("Discretization/Polynomial degree", 2)
           + set("Time integration/Time step", 0.01)
           + set("Time integration/End time", 0.3)
           + set("Output/Probe points", "-0.3, 0; 0, 0.1; 0.25, -0.05");
  }

  void
  check_vehicle(liftoff_tests::Checks                    &checks,
                const std::string                        &shape,
                const std::string                        &path_x,
                const std::string                        &path_y,
                const std::vector<std::array<double, 3>> &wheels)
  {
    const double magnitude = 2;
    const double diameter  = 0.08;
    std::string  wheel_list;
    for (const auto &w : wheels)
      wheel_list += (wheel_list.empty() ? "" : "; ") + std::to_string(w[0])
                    + ", " + std::to_string(w[1]) + ", " + std::to_string(w[2]);
    const std::string vehicle =
      vehicle_base() + set("Loads/Vehicle 1/Magnitude", magnitude)
      + set("Loads/Vehicle 1/Path", path_x + "; " + path_y)
      + set("Loads/Vehicle 1/Wheels", wheel_list)
      + set("Loads/Vehicle 1/Wheel shape", shape)
      + set("Loads/Vehicle 1/Wheel size", diameter);
    const auto together = liftoff_tests::run_scene(vehicle);

    // Each wheel alone, as a moving point load or disc of pressure.
    std::vector<std::vector<double>> sum(together->history().size());
    for (const auto &w : wheels)
      {
        const std::string path = path_x + " + (" + std::to_string(w[0]) + "); "
                                 + path_y + " + (" + std::to_string(w[1]) + ")";
        const double      force = magnitude * w[2];
        const std::string alone =
          shape == "point" ? set("Loads/Point load 1/Magnitude", force)
                               + set("Loads/Point load 1/Path", path)
                           : set("Loads/Patch load 1/Magnitude",
                                 force / (M_PI * diameter * diameter / 4))
                               + set("Loads/Patch load 1/Shape", "disc")
                               + set("Loads/Patch load 1/Size", diameter)
                               + set("Loads/Patch load 1/Path", path);
        const auto run = liftoff_tests::run_scene(vehicle_base() + alone);
        for (unsigned int n = 0; n < sum.size(); ++n)
          {
            sum[n].resize(run->history()[n].probes("w").size());
            for (unsigned int k = 0; k < sum[n].size(); ++k)
              sum[n][k] += run->history()[n].probes("w")[k];
          }
      }
    double difference = 0, scale = 0;
    for (unsigned int n = 0; n < sum.size(); ++n)
      for (unsigned int k = 0; k < sum[n].size(); ++k)
        {
          difference = std::max(difference,
                                std::abs(together->history()[n].probes("w")[k]
                                         - sum[n][k]));
          scale      = std::max(scale, std::abs(sum[n][k]));
        }
    checks.less("vehicle of " + std::to_string(wheels.size()) + " " + shape
                  + " wheels against the sum of its wheels (relative)",
                difference / scale,
                1e-10);
    // The history follows the vehicle: its path's point and how many
    // wheels are on the plate, at the last step.
    const auto &last = together->history().back();
    checks.less("vehicle: history's x of the path at the end",
                std::abs(last["vehicle_1_x"] - (-0.7 + 3 * 0.3)),
                1e-12);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv, 1);
  for (const unsigned int degree : {1u, 2u})
    {
      check_point_load(checks, degree);
      check_patches(checks, degree);
      check_disc_rule(checks, degree);
    }
  check_vehicle(checks,
                "point",
                "-0.7 + 3*tau",
                "0.02",
                {{{0, 0, 1}}, {{-0.15, 0.08, 0.5}}, {{-0.15, -0.08, 0.7}}});
  check_vehicle(checks,
                "disc",
                "-0.7 + 3*tau",
                "-0.01",
                {{{0.05, 0.06, 1}}, {{-0.2, -0.06, 0.6}}});
  return checks.exit_code();
}
