#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace liftoff
{
  using namespace dealii;

  /// The largest principal stress at one face of a section, in units of
  /// F0 / L^2: `per_moment` times the principal moment that puts the face in
  /// the more tension (M_1 where it is positive, M_2 where negative), plus
  /// `per_free_moment` times the free moment D_s (1 + nu) alpha dT / H_s of
  /// the slab's temperature and `per_base_free_moment` times the base's
  /// D_b (1 + nu_b) alpha_b dT_b / H_b, all measured as the moments M the
  /// section carries (doc/model.md, "A base layer").
  struct FaceStressLaw
  {
    double per_moment           = 0;
    double per_free_moment      = 0;
    double per_base_free_moment = 0;
  };


  /// The coefficients of a cell's energies in the plate's units (D, rho H
  /// and F0 of the plate), for its slab's section (with the base under it,
  /// where there is one).
  struct SectionCoefficients
  {
    /// D_s / D = (E_s / E) (H_s / H)^3; the composite's with a base.
    double bending;
    /// chi G_s H_s L^2 / D; chi sum G_i H_i L^2 / D with a base.
    double shear;
    /// rho H_s / (rho H), also the self-weight's factor; with the base's.
    double mass;
    /// rho H_s^3 / 12 over rho H L^2; with a base, the layers' about the
    /// axis they bend about.
    double rotary;
    /// H_s / L, the slab's.
    double thickness_ratio;
    /// A temperature's moment D_s (1 + nu) alpha dT / H_s over the plate's
    /// D (1 + nu) alpha dT / H: (E_s / E) (H_s / H)^2. A linear profile
    /// has no axial force, so its moment is the same about any axis: the
    /// base does not change it.
    double thermal_moment;
    /// The base's temperature moment D_b (1 + nu_b) alpha_b dT_b / H_b
    /// over the plate's D (1 + nu) alpha_b dT_b / H_b, where the section
    /// holds the base (a composite, or the base's own); 0 else.
    double base_thermal_moment = 0;
    /// E_s / E, the factor of a temperature's stresses.
    double modulus;
    /// The slab's faces (top: away from the bed) and, with a base, the
    /// base's.
    FaceStressLaw top, bottom, base_top, base_bottom;
    bool          has_base = false;
  };


  /**
   * A base layer under the slabs (cement- or asphalt-treated, lean
   * concrete, granular) and how the slabs rest on it: bonded (one
   * composite section bending about its neutral axis) or unbonded without
   * separation (w shared, each layer bending about its own mid-plane, so
   * D = D_s + D_b and the moment is shared by stiffness), or unbonded and
   * tensionless (the base a second plate layer with its own w, psi_x,
   * psi_y, joined to the slab by springs k_i that push but never pull,
   * InterfaceSprings). The bed acts under the base. Slip and friction
   * between the layers are not modelled: bonded is full shear transfer,
   * the others none.
   */
  class BaseLayer
  {
  public:
    enum class Interface
    {
      none,
      bonded,
      unbonded,
      tensionless
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    bool
    present() const
    {
      return interface != Interface::none;
    }
    /// Whether the slab and base are one section (bonded, unbonded): one
    /// layer of fields.
    bool
    is_composite() const
    {
      return interface == Interface::bonded || interface == Interface::unbonded;
    }
    /// The layers of fields: 2 where the slab can lift off the base (its
    /// own w, psi_x, psi_y), else 1.
    unsigned int
    n_layers() const
    {
      return interface == Interface::tensionless ? 2 : 1;
    }
    /// The base's own section, as a layer of its own (tensionless), in the
    /// plate's units; nu, chi and delta the plate's.
    SectionCoefficients
    own_section(const double nu, const double chi, const double delta) const;

    /// The section of a slab (its coefficients alone, `slab`) on this
    /// base; nu and chi are the plate's, delta its H / L.
    SectionCoefficients
    under(const SectionCoefficients &slab,
          const double               nu,
          const double               chi,
          const double               delta) const;

    Interface interface = Interface::none;
    /// H_b / L.
    double thickness = 0;
    /// E_b / E.
    double modulus_ratio = 1;
    double poisson_ratio = 0.2;
    /// rho_b / rho.
    double density_ratio = 1;
    /// k_i, the interface springs' modulus (per unit area, per unit of
    /// w_slab - w_base), in the plate's units D / L^4 (tensionless).
    double interface_stiffness = 0;
    /// g_i(x, y), the interface springs' gap (muParser in x, y of the full
    /// plate, in the unit of w; tensionless).
    std::string interface_gap = "0";
  };
} // namespace liftoff
