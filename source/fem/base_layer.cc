#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/fem/base_layer.h>

#include <cmath>

namespace liftoff
{
  namespace
  {
    const Selection<BaseLayer::Interface> interfaces = {
      {"none", BaseLayer::Interface::none},
      {"bonded", BaseLayer::Interface::bonded},
      {"unbonded", BaseLayer::Interface::unbonded},
      {"tensionless", BaseLayer::Interface::tensionless}};

    /// One layer of a section through the thickness, z along w (into the
    /// bed), in units of L and of the plate's E / (1 - nu^2) and rho.
    struct Layer
    {
      double top, thickness, plane_modulus, shear_modulus, density;
      /// The axis it bends about.
      double axis;

      double
      middle() const
      {
        return top + 0.5 * thickness;
      }
      /// Its bending stiffness about its axis.
      double
      bending() const
      {
        const double offset = middle() - axis;
        return plane_modulus
               * (thickness * thickness * thickness / 12.0
                  + thickness * offset * offset);
      }
      double
      rotary() const
      {
        const double offset = middle() - axis;
        return density
               * (thickness * thickness * thickness / 12.0
                  + thickness * offset * offset);
      }
      /// The stress law at depth z of the layer in a section of stiffness
      /// D; `slab_alone`, `base_alone`: the stress per moment at z of the
      /// slab's own section and of the base's (0 in the other layer): a
      /// layer's own free moment stresses it as its section alone would.
      FaceStressLaw
      face(const double z,
           const double D,
           const double slab_alone,
           const double base_alone) const
      {
        const double per_moment = plane_modulus * (z - axis) / D;
        return {per_moment, slab_alone - per_moment, base_alone - per_moment};
      }
    };

    /// The base as a layer whose top lies at `top`, bending about its own
    /// mid-plane (a composite moves the axis), in the plate's units:
    /// E / (1 - nu^2) = 12 / delta^3, rho = 1 / delta.
    Layer
    layer_of(const BaseLayer &base,
             const double     top,
             const double     nu,
             const double     delta)
    {
      const double nu_b = base.poisson_ratio;
      const double e    = 12.0 / (delta * delta * delta) * base.modulus_ratio
                       * (1 - nu * nu) / (1 - nu_b * nu_b);
      return {top,
              base.thickness,
              e,
              0.5 * e * (1 - nu_b),
              base.density_ratio / delta,
              top + 0.5 * base.thickness};
    }


    /// The springs of Interface = tensionless: their modulus and gap.
    void
    declare_interface_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Interface stiffness",
        "0",
        Patterns::Double(0.0, 1e12),
        "k_i of tensionless: the pressure between slab and "
        "base per unit of w_slab - w_base where they touch "
        "(Pa/m in an SI scene; in units of D / L^4, as "
        "Foundation/Stiffness, in a dimensionless one); > 0 "
        "with Interface = tensionless, and at most 1e12 D / "
        "L^4 for the reason Foundation/Stiffness is. A stiff interface "
        "(k_i large against the base's k_b = E_b / H_b) "
        "approaches unbonded without separation where the "
        "slab is pressed."
          + quantity("pressure per length"));
      prm.declare_entry(
        "Interface gap",
        "0",
        Patterns::Anything(),
        "g_i(x, y) of tensionless, muParser in x, y of the full plate: the "
        "distance between the unloaded slab and the base, in the unit of w, "
        "F0 L^2 / D, as Foundation/Initial gap (m in an SI scene). The "
        "springs act where "
        "w_slab - w_base > g_i with the pressure k_i (w_slab - w_base - "
        "g_i): g_i > 0 is a void under the slab (an eroded base, a curl set "
        "in), g_i < 0 a pre-compression. Must be finite on the plate, and "
        "symmetric on a half or quarter model; 0 with another Interface."
          + quantity("deflection"));
    }


    /// The base's free moment D_b (1 + nu_b) per unit of its free
    /// curvature, over the plate's D (1 + nu): SectionCoefficients::
    /// base_thermal_moment.
    double
    base_thermal_moment(const BaseLayer &base,
                        const double     nu,
                        const double     delta)
    {
      return layer_of(base, 0, nu, delta).bending() * (1 + base.poisson_ratio)
             / (1 + nu);
    }
  } // namespace


  void
  BaseLayer::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Base");
    prm.declare_entry(
      "Interface",
      "none",
      interfaces.pattern(),
      "How the slabs rest on a base layer under them, on the bed. none: no "
      "base. bonded: one composite section (the layers bend about its "
      "neutral axis; full shear transfer). unbonded: w shared, each layer "
      "bends about its own mid-plane (D = D_slab + D_base, the moment shared "
      "by stiffness; no shear transfer). tensionless: the base is a plate "
      "of its own (w_base, psi_x_base, psi_y_base) and the slab rests on it "
      "by springs of Interface stiffness that push but never pull, so the "
      "slab lifts off the base where it curls or rebounds. Slip and "
      "friction between the layers are not modelled."
        + quantity("text"));
    declare_interface_parameters(prm);
    prm.declare_entry("Thickness",
                      "0",
                      Patterns::Double(0.0, 1.0),
                      "H_b of the base: in m in an SI scene, in units of L "
                      "(as Plate/Thickness ratio) in a dimensionless one; "
                      "within (0, 1] L where there is a base."
                        + quantity("length"));
    prm.declare_entry("Modulus ratio",
                      "1",
                      Patterns::Double(1e-6, 1e6),
                      "E_b / E, the base's Young's modulus over the plate's "
                      "(Units/Young's modulus in an SI scene), within [1e-6, "
                      "1e6]."
                        + quantity("number"));
    prm.declare_entry("Poisson ratio",
                      "0.2",
                      Patterns::Double(-1.0, 0.5),
                      "nu_b of the base, in (-1, 0.5). The plate's Poisson "
                      "ratio couples the composite's moments; nu_b sets "
                      "the base's plane modulus E_b / (1 - nu_b^2) and its "
                      "shear modulus."
                        + quantity("number"));
    prm.declare_entry("Density ratio",
                      "1",
                      Patterns::Double(0.0, 1e3),
                      "rho_b / rho; the base weighs in Loads' self-weight."
                        + quantity("number"));
    prm.leave_subsection();
  }


  void
  BaseLayer::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Base");
    interface     = interfaces.parse(prm.get("Interface"), "Base/Interface");
    thickness     = prm.get_double("Thickness");
    modulus_ratio = prm.get_double("Modulus ratio");
    poisson_ratio = prm.get_double("Poisson ratio");
    density_ratio = prm.get_double("Density ratio");
    interface_stiffness              = prm.get_double("Interface stiffness");
    interface_gap                    = prm.get("Interface gap");
    const std::string thickness_text = prm.get("Thickness");
    prm.leave_subsection();

    AssertThrow(present() || thickness == 0,
                ExcMessage("Base/Thickness = " + thickness_text
                           + " is given but Base/Interface = none: name the "
                             "interface (bonded or unbonded), or leave the "
                             "thickness at 0."));
    AssertThrow(!present() || thickness > 0,
                ExcMessage("Base/Thickness must be > 0 with a base "
                           "(Base/Interface is not none)."));
    AssertThrow((interface == Interface::tensionless)
                  == (interface_stiffness > 0),
                ExcMessage("Base/Interface stiffness is the springs of "
                           "Base/Interface = tensionless: give it (> 0) "
                           "with that interface and leave it at 0 with "
                           "another."));
    // Any expression but 0 is refused: the gap of a shared w is the bed's.
    AssertThrow(interface == Interface::tensionless || interface_gap == "0",
                ExcMessage("Base/Interface gap = <" + abbreviated(interface_gap)
                           + "> is the gap of the springs of Base/Interface "
                             "= tensionless: leave it at 0 with another "
                             "interface (a void under a slab that shares "
                             "the base's w is Foundation/Initial gap)."));
    AssertThrow(poisson_ratio > -1.0 && poisson_ratio < 0.5,
                ExcMessage("Base/Poisson ratio must lie in (-1, 0.5)."));
  }


  SectionCoefficients
  BaseLayer::own_section(const double nu,
                         const double chi,
                         const double delta) const
  {
    const double        h     = thickness;
    const Layer         layer = layer_of(*this, 0, nu, delta);
    SectionCoefficients own;
    own.bending             = layer.bending();
    own.shear               = chi * layer.shear_modulus * h;
    own.mass                = density_ratio * h / delta;
    own.rotary              = layer.rotary();
    own.thickness_ratio     = h;
    own.thermal_moment      = 0;
    own.base_thermal_moment = base_thermal_moment(*this, nu, delta);
    own.modulus             = modulus_ratio;
    own.top                 = {-6.0 / (h * h), 0, 0};
    own.bottom              = {6.0 / (h * h), 0, 0};
    return own;
  }


  SectionCoefficients
  BaseLayer::under(const SectionCoefficients &slab,
                   const double               nu,
                   const double               chi,
                   const double               delta) const
  {
    // The plate's E / (1 - nu^2) is 12 / delta^3 and its rho is 1 / delta
    // in the plate's units (D = 1, rho H = 1).
    const double plate_modulus = 12.0 / (delta * delta * delta);
    const double h_s           = slab.thickness_ratio;
    const double h_b           = thickness;
    const double e_s           = plate_modulus * slab.modulus;
    Layer slab_layer{-0.5 * h_s, h_s, e_s, 0.5 * e_s * (1 - nu), 1 / delta, 0};
    Layer base_layer = layer_of(*this, 0.5 * h_s, nu, delta);
    const double e_b = base_layer.plane_modulus;
    if (interface == Interface::bonded)
      {
        const double axis =
          e_b * h_b * base_layer.middle() / (e_s * h_s + e_b * h_b);
        slab_layer.axis = base_layer.axis = axis;
      }

    SectionCoefficients composite = slab;
    const double        D         = slab_layer.bending() + base_layer.bending();
    composite.bending             = D;
    composite.shear =
      chi * (slab_layer.shear_modulus * h_s + base_layer.shear_modulus * h_b);
    composite.mass                = (h_s + density_ratio * h_b) / delta;
    composite.rotary              = slab_layer.rotary() + base_layer.rotary();
    composite.base_thermal_moment = base_thermal_moment(*this, nu, delta);
    const double alone            = 6.0 / (h_s * h_s);
    const double base_alone       = 6.0 / (h_b * h_b);
    composite.top                 = slab_layer.face(-0.5 * h_s, D, -alone, 0);
    composite.bottom              = slab_layer.face(0.5 * h_s, D, alone, 0);
    composite.base_top    = base_layer.face(0.5 * h_s, D, 0, -base_alone);
    composite.base_bottom = base_layer.face(0.5 * h_s + h_b, D, 0, base_alone);
    composite.has_base    = true;
    return composite;
  }
} // namespace liftoff
