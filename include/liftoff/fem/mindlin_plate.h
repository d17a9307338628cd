#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/physical_units.h>
#include <liftoff/fem/base_layer.h>

#include <vector>

namespace liftoff
{
  using namespace dealii;

  class PlateGeometry;

  /// One slab's cross-section against the plate's (Plate, Units): H_s / H
  /// and E_s / E. The density and Poisson ratio are the plate's.
  struct SlabSection
  {
    double thickness = 1.0;
    double modulus   = 1.0;
  };


  /**
   * Material and geometry of the Mindlin plate in the dimensionless form of
   * the paper's section 4 (doc/model.md, "Reading the paper" and "Units").
   * Lengths are scaled by L, the full side length along x, so the plate
   * occupies [-1/2, 1/2] x [-mu/2, mu/2]; the bending stiffness D, the
   * translational mass rho H and the load scale F0 are one.
   */
  class MindlinPlate
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
    /// nu of the scene as written, for the SI conversion's D.
    static void
    describe_for_units(ParameterHandler            &scene,
                       PhysicalUnits::SceneOutline &outline);

    /// Aspect ratio mu: width (along y) over length L (along x).
    double aspect_ratio = 1.0;
    /// Delta = H / L.
    double thickness_ratio  = 0.05;
    double poisson_ratio    = 0.1;
    double shear_correction = 5.0 / 6.0;

    /// chi G H L^2 / D = 6 chi (1 - nu) / Delta^2.
    double
    shear_stiffness() const;
    /// Rotary inertia rho H^3 / 12 over rho H L^2, i.e. Delta^2 / 12.
    double
    rotary_inertia() const;
    /// Twisting stiffness G H^3 / 12 over D, i.e. (1 - nu) / 2.
    double
    twisting_stiffness() const;

    /// The sections of the slabs (Slabs/Thicknesses, Modulus ratios) by
    /// slab number, the cells' material id; empty where every slab is the
    /// plate.
    std::vector<SlabSection> slab_sections;
    /// The base under the slabs (Base), if any.
    BaseLayer base;
    /// Whether some slab's section is not the plate's.
    bool
    has_slab_sections() const;
    /// The coefficients of the cells of slab `slab`; the plate's own where
    /// the slabs are alike, so a uniform plate computes the same numbers;
    /// with the base under it where there is one.
    SectionCoefficients
    section(const unsigned int slab) const;
    /// The base's own section, where it is a layer of its own (BaseLayer,
    /// tensionless).
    SectionCoefficients
    base_section() const;
    /// The section of `layer` (0: the slab's, 1: a base of its own) over
    /// the cells of slab `slab`.
    SectionCoefficients
    layer_section(const unsigned int slab, const unsigned int layer) const;
    /// The slabs' sections (Slabs/Thicknesses, Modulus ratios) for the
    /// slabs of `geometry`, parsed after it; refused where the count is
    /// wrong, or where mirror slabs of a symmetric model differ.
    void
    parse_slab_sections(ParameterHandler &prm, const PlateGeometry &geometry);

  private:
    /// The slabs' sections, in the subsection Slabs.
    static void
    declare_slab_parameters(ParameterHandler &prm);
  };
} // namespace liftoff
