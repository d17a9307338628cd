#pragma once

// Pressure patches whose edges do not follow cell edges (issue 31, item 2).
// The load vector b of a scene's pressures is checked against the exact
// force and first moments of the pressure: b . I(g) = int p g for
// g = 1, x, y, where I(g) is the interpolant of g in the w component (g is
// in the element's space, and satisfies the hanging-node constraints, so
// the identity is exact for the condensed vector too). The exact values are
// closed-form integrals of polynomial intensities over patch ∩ meshed part.
// Patches smaller than a cell, straddling cell edges and the hanging nodes
// of a locally refined mesh, touching the plate's edge, following cell
// edges, on the full plate and on half and quarter models (whose mirror
// images the scene lists), with Q1, Q2 and the serendipity element. And the
// issue's scenes run statically on a bilateral bed: the bed's resultant and
// its centre equal the load's (free plate: statics).
// Before the fix the Gauss points of whole cells sampled the patch's
// indicator: the 0.01 x 0.01 patch on 7 x 7 Q2 cells got 21.7 times
// its force, two others none.

#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/loads/load_set.h>

#include "test_tools.h"

#include <array>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace pressure_patches
{
  using namespace dealii;
  using liftoff_tests::set;

  /// c x^a y^b.
  struct Monomial
  {
    double       c;
    unsigned int a, b;
  };

  struct Patch
  {
    double                x0, x1, y0, y1;
    std::vector<Monomial> intensity = {{1, 0, 0}};
    double                magnitude = 1;

    /// The region as prm text; `digits` 17 keeps every digit.
    std::string
    region(const int digits = 17) const
    {
      std::ostringstream text;
      text << std::setprecision(digits) << x0 << ", " << x1 << ", " << y0
           << ", " << y1;
      return text.str();
    }

    std::string
    expression() const
    {
      std::ostringstream text;
      text << std::setprecision(17) << "0";
      for (const auto &m : intensity)
        text << " + (" << m.c << ")*x^" << m.a << "*y^" << m.b;
      return text.str();
    }

    /// The image in the plane normal to `axis`: the rectangle mirrored, the
    /// intensity's odd powers of that coordinate negated.
    Patch
    mirrored(const unsigned int axis) const
    {
      Patch image = *this;
      if (axis == 0)
        {
          image.x0 = -x1;
          image.x1 = -x0;
        }
      else
        {
          image.y0 = -y1;
          image.y1 = -y0;
        }
      for (auto &m : image.intensity)
        if ((axis == 0 ? m.a : m.b) % 2 == 1)
          m.c = -m.c;
      return image;
    }

    /// magnitude * int p x^i y^j over this patch ∩ box (exact).
    double
    moment(const BoundingBox<2> &box,
           const unsigned int    i,
           const unsigned int    j) const
    {
      const double a0 = std::max(x0, box.lower_bound(0)),
                   a1 = std::min(x1, box.upper_bound(0)),
                   b0 = std::max(y0, box.lower_bound(1)),
                   b1 = std::min(y1, box.upper_bound(1));
      if (a1 <= a0 || b1 <= b0)
        return 0;
      const auto power_integral =
        [](const double lo, const double hi, const unsigned int n) {
          return (std::pow(hi, n + 1) - std::pow(lo, n + 1)) / (n + 1);
        };
      double sum = 0;
      for (const auto &m : intensity)
        sum += m.c * power_integral(a0, a1, m.a + i)
               * power_integral(b0, b1, m.b + j);
      return magnitude * sum;
    }

    /// magnitude * sum |c| * area: bounds int |p| over the patch.
    double
    scale() const
    {
      double sum = 0;
      for (const auto &m : intensity)
        sum += std::abs(m.c);
      return std::abs(magnitude) * sum * (x1 - x0) * (y1 - y0);
    }
  };

  /// A scene: the full plate's patches (with their mirror images on a half
  /// or quarter model) and a discretization.
  struct Case
  {
    std::string        label;
    std::string        discretization; // prm text
    std::vector<Patch> patches;
    /// Refine the cells whose centre has x + y below this once (hanging
    /// nodes); none if it is -infinity.
    double refine_below = -1e300;

    std::string
    scene() const
    {
      std::string text = discretization;
      for (unsigned int k = 0; k < patches.size(); ++k)
        {
          const std::string section =
            "Loads/Pressure " + std::to_string(k + 1) + "/";
          text += set(section + "Magnitude", patches[k].magnitude)
                  + set(section + "Region", patches[k].region())
                  + set(section + "Intensity", patches[k].expression());
        }
      return text;
    }
  };

  inline std::string
  mesh(const std::string &symmetry,
       const unsigned int cells_x,
       const unsigned int cells_y,
       const std::string &element,
       const double       aspect_ratio = 1)
  {
    const bool serendipity = (element == "S2");
    return set("Plate/Aspect ratio", aspect_ratio)
           + set("Discretization/Symmetry", symmetry)
           + set("Discretization/Cells along x", cells_x)
           + set("Discretization/Cells along y", cells_y)
           + set("Discretization/Polynomial degree",
                 serendipity       ? 2
                 : element == "Q1" ? 1
                                   : 2)
           + set("Discretization/Element",
                 serendipity ? "serendipity" : "lagrange")
           + (serendipity ? set("Discretization/Shear integration", "full")
                          : "");
  }

  /// g(x, y) in the w component, zero rotations.
  class InWComponent : public Function<2>
  {
  public:
    InWComponent(const unsigned int i, const unsigned int j)
        : Function<2>(3)
        , i(i)
        , j(j)
    {}

    double
    value(const Point<2> &p, const unsigned int component) const override
    {
      return component == 0 ? std::pow(p[0], i) * std::pow(p[1], j) : 0.0;
    }

  private:
    const unsigned int i, j;
  };

  /// int p, int p x, int p y of the assembled load vector (of the meshed
  /// part) and their exact values; and the scale of the load.
  struct Moments
  {
    std::array<double, 3> assembled, exact;
    double                scale = 0;
  };

  /// A scene's discretization (the cells whose centre has x + y below
  /// `refine_below` refined once) and the load vector of its loads at tau,
  /// checked (mirror images) and assembled as a run does.
  struct AssembledLoad
  {
    std::unique_ptr<liftoff::Discretization> disc;
    liftoff::LA::MPI::Vector                 vector;

    /// vector . I(x^i y^j), I the interpolant in the w component: the
    /// integral of the load against x^i y^j where that is in the
    /// element's space.
    double
    moment(const unsigned int i, const unsigned int j) const
    {
      liftoff::LA::MPI::Vector g;
      disc->reinit_vector(g);
      VectorTools::interpolate(disc->mapping(),
                               disc->dof_handler,
                               InWComponent(i, j),
                               g);
      return vector * g;
    }
  };

  inline AssembledLoad
  assemble_load(const std::string &scene,
                const double       refine_below,
                const double       tau,
                const MPI_Comm     comm)
  {
    ParameterHandler prm;
    liftoff::MindlinPlate::declare_parameters(prm);
    liftoff::Discretization::declare_parameters(prm);
    liftoff::LoadSet::declare_parameters(prm);
    prm.parse_input_from_string(scene, "test scene");
    liftoff::MindlinPlate plate;
    plate.parse_parameters(prm);
    AssembledLoad result{std::make_unique<liftoff::Discretization>(comm), {}};
    liftoff::Discretization &disc = *result.disc;
    disc.parse_parameters(prm, plate);
    disc.setup();
    if (refine_below > -1e300)
      {
        for (const auto &cell : disc.triangulation.active_cell_iterators())
          if (cell->is_locally_owned()
              && cell->center()[0] + cell->center()[1] < refine_below)
            cell->set_refine_flag();
        disc.triangulation.execute_coarsening_and_refinement();
        disc.distribute_dofs();
      }
    liftoff::LoadSet loads;
    loads.parse_parameters(prm);
    // The symmetry check (mirror images) as a run does it.
    loads.check_against(disc, 0.01, 1);
    loads.setup(disc);
    disc.reinit_vector(result.vector);
    loads.assemble(tau, result.vector);
    return result;
  }

  inline Moments
  load_moments(const Case &c, const MPI_Comm comm)
  {
    const AssembledLoad load =
      assemble_load(c.scene(), c.refine_below, 0, comm);
    Moments                                          m;
    const std::array<std::array<unsigned int, 2>, 3> powers = {
      {{{0, 0}}, {{1, 0}}, {{0, 1}}}};
    for (unsigned int k = 0; k < 3; ++k)
      {
        m.assembled[k] = load.moment(powers[k][0], powers[k][1]);
        m.exact[k]     = 0;
        for (const auto &patch : c.patches)
          m.exact[k] += patch.moment(load.disc->geometry().modelled_box(),
                                     powers[k][0],
                                     powers[k][1]);
      }
    for (const auto &patch : c.patches)
      m.scale += patch.scale();
    return m;
  }

  /// The patches with their images in the planes of `symmetry`.
  inline std::vector<Patch>
  with_images(const std::vector<Patch> &patches, const std::string &symmetry)
  {
    std::vector<Patch> all = patches;
    if (symmetry != "full")
      for (const auto &p : patches)
        all.push_back(p.mirrored(0));
    if (symmetry == "quarter")
      for (const auto &p : std::vector<Patch>(all))
        all.push_back(p.mirrored(1));
    return all;
  }

  /// The cases of the load vector checks.
  inline std::vector<Case>
  cases()
  {
    std::vector<Case> list;
    // The scenes: 7 x 7 Q2 cells, unit pressure on a small patch
    // (21.7 times the force before; none; none), and a 0.1 x 0.1 patch on
    // 16 x 16 and 32 x 32 cells.
    for (const Patch &p : {Patch{0.3, 0.31, 0.3, 0.31},
                           Patch{0.28, 0.29, 0.28, 0.29},
                           Patch{0.1, 0.11, -0.2, 0.2}})
      list.push_back({"issue 31, 7 x 7 Q2, Region " + p.region(6),
                      mesh("full", 7, 7, "Q2"),
                      {p}});
    for (const unsigned int n : {16u, 32u})
      list.push_back({"issue 31, " + std::to_string(n) + " x "
                        + std::to_string(n) + " Q2, 0.1 x 0.1 patch",
                      mesh("full", n, n, "Q2"),
                      {Patch{0.2, 0.3, 0.2, 0.3}}});

    // Patches anywhere, with a polynomial intensity of degree 3 in x and 2
    // in y (within the rule's exactness for Q1: p + 3 = 4), on a plate
    // 0.8 wide, 5 x 4 cells, the cells with x + y < 0 refined once.
    const std::vector<Monomial> polynomial = {
      {1, 0, 0}, {2, 1, 0}, {-3, 0, 1}, {4, 1, 1}, {5, 3, 2}, {-2, 2, 0}};
    const std::vector<Patch> anywhere = {
      {0.013, 0.037, 0.021, 0.029, polynomial, 1.5}, // inside one cell
      {-0.17, 0.23, -0.31, 0.07, polynomial, 1},     // across many cells
      {0.41, 0.5, -0.4, -0.33, polynomial, -0.7},    // in a corner of the
                                                     // plate
      {-0.5, 0.5, 0.18, 0.2, polynomial, 0.3},       // a strip, edge to edge
      {-0.1, 0.1, -0.2, 0.2, polynomial, 2}};        // on cell edges
    for (const std::string element : {"Q1", "Q2", "S2"})
      list.push_back({"full plate, 5 x 4 " + element + ", hanging nodes",
                      mesh("full", 5, 4, element, 0.8),
                      anywhere,
                      0.0});

    // Half and quarter models: patches off the planes with their images,
    // and one across both planes (its own image when its intensity is even
    // in x and y).
    const std::vector<Monomial> even       = {{1, 0, 0}, {3, 2, 0}, {-2, 2, 2}};
    const std::vector<Patch>    off_planes = {
         {0.07, 0.19, 0.11, 0.16, polynomial, 1},
         {0.33, 0.5, -0.4, 0.02, polynomial, 0.5}};
    for (const std::string element : {"Q1", "Q2", "S2"})
      for (const std::string symmetry : {"half", "quarter"})
        {
          // At most 8 pressures: a quarter model takes one patch off the
          // planes (4 images) and one on the plane x = 0 (2 images).
          std::vector<Patch> patches =
            with_images(symmetry == "half"
                          ? off_planes
                          : std::vector<Patch>{off_planes.back()},
                        symmetry);
          patches.push_back({-0.043, 0.043, -0.061, 0.061, even, 3});
          if (symmetry == "quarter")
            {
              const Patch on_plane = {
                -0.12, 0.12, 0.2, 0.31, {{1, 0, 0}, {2, 0, 1}, {1, 2, 1}}, 1};
              patches.push_back(on_plane);
              patches.push_back(on_plane.mirrored(1));
            }
          const unsigned int cells_x = 3,
                             cells_y = (symmetry == "quarter" ? 2 : 5);
          list.push_back({symmetry + " model, " + std::to_string(cells_x)
                            + " x " + std::to_string(cells_y) + " " + element
                            + ", hanging nodes",
                          mesh(symmetry, cells_x, cells_y, element, 0.8),
                          patches,
                          0.15});
        }
    return list;
  }

  /// Every case's force and moments against the exact values.
  inline void
  check_load_vectors(liftoff_tests::Checks &checks, const MPI_Comm comm)
  {
    const std::array<std::string, 3> names = {
      {"force", "x moment", "y moment"}};
    for (const auto &c : cases())
      {
        const Moments m = load_moments(c, comm);
        if (c.label.rfind("issue", 0) == 0)
          checks.less(c.label + ": |assembled / exact force - 1|",
                      std::abs(m.assembled[0] / m.exact[0] - 1),
                      1e-12);
        for (unsigned int k = 0; k < 3; ++k)
          checks.less(c.label + ": |" + names[k] + " - exact| / scale",
                      std::abs(m.assembled[k] - m.exact[k]) / m.scale,
                      1e-12);
      }
  }

  /// The scenes run: static, bilateral bed, free plate. The bed's
  /// resultant must be the load and its centre the load's centroid. On the
  /// issue's soft bed (Gamma = 1) the rigid-body part of the static solution
  /// carries round-off that grows like 1 / h^2 (doc/reliability.md, soft
  /// foundations): 1e-10 of the force on 7 x 7 cells, 2.5e-9 on 32 x 32.
  inline void
  check_static_resultants(liftoff_tests::Checks &checks, const MPI_Comm comm)
  {
    for (const auto &c : cases())
      if (c.label.rfind("issue", 0) == 0)
        {
          const Patch &p    = c.patches.front();
          const double area = (p.x1 - p.x0) * (p.y1 - p.y0);
          const auto   run  = liftoff_tests::run_scene(
            c.scene() + set("Analysis/Type", "static")
              + set("Foundation/Model", "bilateral")
              + set("Output/Write foundation resultant", "true"),
            nullptr,
            comm);
          const auto &row = run->history().back();
          checks.less(c.label + ": static run, |bed resultant / load - 1|",
                      std::abs(row["resultant"] / area - 1),
                      1e-8);
          checks.less(c.label
                        + ": static run, |centre of resultant - "
                          "centre of patch|",
                      std::hypot(row["resultant_x"] - 0.5 * (p.x0 + p.x1),
                                 row["resultant_y"] - 0.5 * (p.y0 + p.y1)),
                      1e-9);
        }
  }
} // namespace pressure_patches
