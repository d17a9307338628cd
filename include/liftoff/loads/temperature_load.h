#pragma once

#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/loads/distributed_load.h>
#include <liftoff/loads/free_bending.h>
#include <liftoff/loads/temperature_profile.h>

namespace liftoff
{
  /**
   * A temperature difference through the thickness on the whole plate:
   * dT = Magnitude * f(x, y, tau) * h(tau), top minus bed side, with the
   * coefficient of expansion alpha. It bends the plate as the free
   * curvature kappa_T = alpha dT / H in both directions (w into the bed):
   * the moments are measured from it, M = -D ((kappa - kappa_T) + nu
   * (kappa - kappa_T)), so its load on the rotations is the thermal moment
   * D (1 + nu) kappa_T against the divergence of their shape functions.
   * A Profile through the thickness gives dT as its equivalent linear
   * difference and adds its self-equilibrating stress at the faces. A
   * Permanent one (built-in curl, moisture warping as an equivalent dT)
   * acts from before tau = 0, as the self-weight does. On slabs of other
   * sections (Slabs/Thicknesses, Modulus ratios) the same dT curls a slab
   * by alpha dT / H_s with the moment D_s (1 + nu) of it, and stresses it
   * with E_s. doc/model.md,
   * "Temperature", has the signs.
   */
  class TemperatureLoad : public DistributedLoad
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, const std::string &section);
    static std::unique_ptr<Load>
    read(ParameterHandler &prm, const std::string &section);

    void
    use_plate(const MindlinPlate &plate) override;
    bool
    bends_freely() const override;
    FreeBending
    free_bending_at(const Point<2> &x, const double tau) const override;

    bool
    touches(const PlateGeometry &geometry, const double tau) const override;
    void
    require_on_plate(const PlateGeometry &geometry) const override;

  protected:
    void
    add_spatial_part(const Discretization &discretization,
                     const double          tau,
                     LA::MPI::Vector      &vector) const override;
    /// The whole plate, as a Pressure on it (the checks of the intensity).
    void
    integrate(const PatchIntegrator          &integrator,
              const PatchIntegrator::Density &density,
              const BoundingBox<2>           &plate,
              const double                    tau,
              LA::MPI::Vector                &vector) const override;
    std::vector<Point<2>>
    quadrature_points_of_image(
      const PatchIntegrator                           &integrator,
      const std::function<Point<2>(const Point<2> &)> &image,
      const BoundingBox<2>                            &plate) const override;
    bool
    mirrors_geometry(const Load                &other,
                     const unsigned int         axis,
                     const BoundingBox<2>      &plate,
                     const std::vector<double> &times) const override;

  private:
    /// The free moments of the layers that `section` holds, over the
    /// plate's D: D_i (1 + nu_i) kappa_T,i summed.
    double
    moment_in(const SectionCoefficients &section,
              const FreeBending         &bending) const;
    /// `moment` against div psi_i of `layer` at point q, into `cell_rhs`.
    static void
    add_moment(const FEValues<2> &values,
               const unsigned int q,
               const unsigned int layer,
               const double       moment,
               Vector<double>    &cell_rhs);

    TemperatureLoad(const std::string        &name,
                    const double              magnitude,
                    LoadHistory             &&history,
                    Intensity               &&intensity,
                    const double              expansion,
                    const TemperatureProfile &profile);

    /// alpha (the solver's: alpha D / (F0 L), alpha itself with F0 = D/L).
    double             expansion;
    TemperatureProfile profile;
    /// The base's own profile and alpha_b (solver's units; 0: no
    /// temperature of the base's own).
    TemperatureProfile base_profile   = TemperatureProfile({0.0, 0.0}, "");
    double             base_expansion = 0;
    /// (1 + nu) and Delta = H / L of the plate (use_plate()).
    double one_plus_nu = 1, thickness_ratio = 1;
    /// The plate, whose slabs' sections scale the thermal moment.
    MindlinPlate plate;
  };
} // namespace liftoff
