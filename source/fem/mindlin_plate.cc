#include <deal.II/base/utilities.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_geometry.h>

#include <cmath>

namespace liftoff
{
  void
  MindlinPlate::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Plate");
    prm.declare_entry("Aspect ratio",
                      "1",
                      Patterns::Double(1e-3, 1e3),
                      "mu: width of the plate (along y) over its length L "
                      "(along x). Lengths are measured in units of L, so "
                      "the plate is [-1/2,1/2] x [-mu/2,mu/2]. Within "
                      "[1e-3, 1e3]: a narrower plate is a beam (model it "
                      "as a strip along x with mu >= 1e-3), and cells "
                      "stretched by more than 1e3 would multiply the "
                      "condition number by the square of their stretch."
                        + quantity("mu"));
    prm.declare_entry("Thickness ratio",
                      "0.05",
                      Patterns::Double(1e-5, 1.0),
                      "Delta = H / L, H the plate thickness. Within "
                      "[1e-5, 1]: the shear stiffness 6 chi (1 - nu) / "
                      "Delta^2 over the bending stiffness sets the "
                      "condition number, about 6 chi (1 - nu) / (pi^4 "
                      "Delta^2 h^2) for node spacing h, so the round-off "
                      "error of the answer grows like 1 / Delta^2: a "
                      "simply supported square under pressure (Q2, 64 x 64 "
                      "cells) is off the Kirchhoff value by 5e-6 at Delta = "
                      "1e-4, 6e-4 at 1e-5, 1.5e-2 at 1e-6 and has the wrong "
                      "sign at 1e-7 (doc/reliability.md). A plate thicker "
                      "than long is no plate: Mindlin's kinematics need H "
                      "below the span."
                        + quantity("Delta"));
    prm.declare_entry("Poisson ratio",
                      "0.1",
                      Patterns::Double(-1.0, 0.5),
                      "nu, in (-1, 0.5); concrete's 0.15 by default in an "
                      "SI scene."
                        + si_default("0.15") + quantity("number"));
    prm.declare_entry("Shear correction factor",
                      "0.8333333333333333",
                      Patterns::Double(0.0, 1.0),
                      "chi of Mindlin's theory, in (0, 1]; 5/6 by default. "
                      "It corrects the constant shear strain of the "
                      "kinematics downwards (5/6, pi^2/12); above 1 it "
                      "would stiffen the plate like a thinner one."
                        + quantity("number"));
    prm.leave_subsection();

    declare_slab_parameters(prm);
    BaseLayer::declare_parameters(prm);
  }


  void
  MindlinPlate::declare_slab_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Slabs");
    prm.declare_entry(
      "Thicknesses",
      "",
      Patterns::List(Patterns::Double(), 0, 1024),
      "H of each slab (a widened lane, a thinner shoulder): one value for "
      "every slab or one per slab in the order of their numbers (along x "
      "first, from the bottom left: slab 1 is the left bottom one; in a mesh "
      "file its physical surfaces by their numbers); empty: "
      "the plate's. In m in an SI scene, in units of L (as Plate/Thickness "
      "ratio) in a dimensionless one; within [1e-5, 1] L. The slabs share "
      "the plate's density and Poisson ratio; a temperature load curls each "
      "slab by alpha dT / H_s with its own D_s."
        + quantity("length"));
    prm.declare_entry(
      "Modulus ratios",
      "",
      Patterns::List(Patterns::Double(), 0, 1024),
      "E_s / E, Young's modulus of each slab over the plate's, as "
      "Thicknesses: one value or one per slab; empty: 1. Within [1e-6, "
      "1e6]."
        + quantity("number"));
    prm.leave_subsection();
  }


  void
  MindlinPlate::describe_for_units(ParameterHandler            &scene,
                                   PhysicalUnits::SceneOutline &outline)
  {
    scene.enter_subsection("Plate");
    outline.poisson_ratio = scene.get_double("Poisson ratio");
    scene.leave_subsection();
  }


  void
  MindlinPlate::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Plate");
    aspect_ratio     = prm.get_double("Aspect ratio");
    thickness_ratio  = prm.get_double("Thickness ratio");
    poisson_ratio    = prm.get_double("Poisson ratio");
    shear_correction = prm.get_double("Shear correction factor");
    prm.leave_subsection();

    // Patterns::Double admits the closed interval; the model needs it open.
    AssertThrow(poisson_ratio > -1.0 && poisson_ratio < 0.5,
                ExcMessage("Plate/Poisson ratio must lie in (-1, 0.5)."));
    AssertThrow(shear_correction > 0,
                ExcMessage("Plate/Shear correction factor must be > 0."));
    base.parse_parameters(prm);
  }


  void
  MindlinPlate::parse_slab_sections(ParameterHandler    &prm,
                                    const PlateGeometry &geometry)
  {
    prm.enter_subsection("Slabs");
    const unsigned int n_slabs = geometry.slabs().n_slabs();
    // One value per slab, from an empty entry (1), one value or n.
    const auto per_slab = [&](const std::string &entry,
                              const double       scale,
                              const double       low,
                              const double       high) {
      const std::string         text = prm.get(entry);
      const std::vector<double> values =
        Utilities::string_to_double(Utilities::split_string_list(text));
      const std::string name = "Slabs/" + entry + " = " + text;
      AssertThrow(values.empty() || n_slabs > 1,
                  ExcMessage(name
                             + ": the plate is one slab (Slabs along x "
                               "and y are 1, one physical surface in a "
                               "mesh file); give its section in Plate (or "
                               "Units)."));
      AssertThrow(values.size() <= 1 || values.size() == n_slabs,
                  ExcMessage(name
                             + ": give one value for every slab or one "
                               "per slab ("
                             + std::to_string(n_slabs) + ")."));
      for (const double v : values)
        AssertThrow(std::isfinite(v) && v >= low && v <= high,
                    ExcMessage(name + ": each value must lie in ["
                               + format_number(low) + ", " + format_number(high)
                               + "]."));
      std::vector<double> ratios(n_slabs, 1.0);
      for (unsigned int s = 0; s < n_slabs && !values.empty(); ++s)
        ratios[s] = values[values.size() == 1 ? 0 : s] / scale;
      return ratios;
    };
    const std::vector<double> thickness =
      per_slab("Thicknesses", thickness_ratio, 1e-5, 1.0);
    const std::vector<double> modulus =
      per_slab("Modulus ratios", 1.0, 1e-6, 1e6);
    prm.leave_subsection();

    slab_sections.clear();
    for (unsigned int s = 0; s < n_slabs; ++s)
      slab_sections.push_back({thickness[s], modulus[s]});
    if (!has_slab_sections())
      slab_sections.clear();
    const std::vector<unsigned int> axes = geometry.symmetry_axes();
    geometry.slabs().require_symmetric(slab_sections,
                                       axes,
                                       axes.size() == 1 ? "half" : "quarter");
  }


  bool
  MindlinPlate::has_slab_sections() const
  {
    for (const SlabSection &s : slab_sections)
      if (s.thickness != 1.0 || s.modulus != 1.0)
        return true;
    return false;
  }


  SectionCoefficients
  MindlinPlate::section(const unsigned int slab) const
  {
    double t = 1.0, e = 1.0;
    if (!slab_sections.empty())
      {
        AssertIndexRange(slab, slab_sections.size());
        t = slab_sections[slab].thickness;
        e = slab_sections[slab].modulus;
      }
    // A uniform plate's are its own numbers, not products with 1.
    const bool          uniform = slab_sections.empty();
    SectionCoefficients alone;
    alone.bending = uniform ? 1.0 : e * t * t * t;
    alone.shear   = uniform ? shear_stiffness() : e * t * shear_stiffness();
    alone.mass    = uniform ? 1.0 : t;
    alone.rotary  = uniform ? rotary_inertia() : t * t * t * rotary_inertia();
    alone.thickness_ratio = uniform ? thickness_ratio : t * thickness_ratio;
    alone.thermal_moment  = uniform ? 1.0 : e * t * t;
    alone.modulus         = uniform ? 1.0 : e;
    // 6 M / H_s^2 at the bed-side face, its negative at the top.
    const double per_moment =
      6.0 / (alone.thickness_ratio * alone.thickness_ratio);
    alone.top    = {-per_moment, 0};
    alone.bottom = {per_moment, 0};
    if (!base.is_composite())
      return alone;
    return base.under(alone, poisson_ratio, shear_correction, thickness_ratio);
  }


  SectionCoefficients
  MindlinPlate::base_section() const
  {
    return base.own_section(poisson_ratio, shear_correction, thickness_ratio);
  }


  SectionCoefficients
  MindlinPlate::layer_section(const unsigned int slab,
                              const unsigned int layer) const
  {
    return layer == 0 ? section(slab) : base_section();
  }


  double
  MindlinPlate::shear_stiffness() const
  {
    return 6.0 * shear_correction * (1.0 - poisson_ratio)
           / (thickness_ratio * thickness_ratio);
  }


  double
  MindlinPlate::rotary_inertia() const
  {
    return thickness_ratio * thickness_ratio / 12.0;
  }


  double
  MindlinPlate::twisting_stiffness() const
  {
    return 0.5 * (1.0 - poisson_ratio);
  }
} // namespace liftoff
