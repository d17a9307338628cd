#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/archive_types.h>
#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/bed.h>
#include <liftoff/contact/contact_law.h>
#include <liftoff/contact/foundation_diagnostics.h>
#include <liftoff/contact/foundation_points.h>
#include <liftoff/contact/spring_term.h>
#include <liftoff/contact/status_term.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/system_term.h>

#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * Winkler springs that push but never pull: the reaction is
   * r = -Gamma max(w, 0). Following eqs. (3.7c)-(3.8), the foundation
   * stiffness is integrated with the (p+1)^2 Gauss rule and a Gauss point
   * contributes only while w_h > 0 there. This class owns that contact
   * status, one flag per Gauss point of the locally owned cells.
   *
   * The `bilateral` model keeps every point active (linear springs), and
   * `none` removes the foundation.
   *
   * An initial gap g(x, y) between the unloaded plate and the bed (g < 0: a
   * pre-compression) shifts the springs: they act where w > g, with the
   * reaction -Gamma (w - g). The reaction is then affine in u,
   * K_f(S) u - f_g(S): the matrix is that of g = 0, and f_g(S), the springs'
   * push on the gap, joins the right-hand side (add_status_load()). A scene
   * without a gap (g = 0 at every Gauss point) takes none of these paths.
   *
   * Dashpots c per unit area beside the springs make the pressure
   * Gamma (w - g) + c v, also only in contact and never tensile. Wherever
   * the velocity is affine in w, v = kappa w - o (Newmark: kappa =
   * gamma / (beta dt), o from the previous state; at a given state kappa =
   * 0, o = -v), the pressure is (Gamma + c kappa) (w - e) with the
   * effective gap e = (Gamma g + c o) / (Gamma + c kappa): the same rule,
   * matrix and right-hand side as a gap, with another stiffness and gap
   * (ContactLaw::pressure(), an argument of the calls that need it).
   *
   * A Pasternak shear layer G_p on the springs adds the energy
   * 1/2 G_p int_S |grad w|^2 and the matrix G_p int_S grad phi_i . grad
   * phi_j over the same points S as the springs (all points when bilateral):
   * the status, the matrix updates and the contact rule stay one code path.
   * Outside contact the layer is not modelled (doc/model.md).
   *
   * The class also keeps a system matrix's foundation term in step with the
   * status: add_to_matrix() adds the whole term once, and update_matrix()
   * adds or removes only the points whose status changed since, so an
   * active-set iteration costs a pass over the flipped points, not a
   * reassembly.
   *
   * It is the façade of four parts with one job each: the Gauss point data
   * (FoundationPoints), the contact law (ContactLaw), the term status k
   * JxW in its uses (SpringTerm) and the diagnostics
   * (FoundationDiagnostics). It owns the contact status, the one state
   * that all of them read.
   *
   * It is a term of the plate's system with a status (StatusTerm, whose
   * law is the ContactRule): the active-set iteration adds and updates its
   * matrix entries.
   */
  class TensionlessWinklerFoundation : public Bed
  {
  public:
    TensionlessWinklerFoundation();

    static void
    declare_parameters(ParameterHandler &prm);
    /// `mass_per_area`: what it carries (ContactLaw::parse_parameters()).
    void
    parse_parameters(ParameterHandler &prm, const double mass_per_area = 1.0);

    /// The Gauss points of the mesh, every one in contact (none without a
    /// foundation), and a matrix taken to hold that status.
    void
    setup(const Discretization &discretization) override;

    /// force += K_f(status) u, the linear part of the springs' (and the
    /// shear layer's) reaction to u (the whole reaction without a gap), at
    /// state.ghosted_u.
    void
    add_force(const TermState &state, LA::MPI::Vector &force) const override;
    /// The springs' and the layer's energy of the status
    /// (FoundationDiagnostics::energy()).
    double
    energy(const TermState &state) const override;
    std::string
    energy_column() const override
    {
      return "foundation";
    }

    /// The law: Gamma, c, G_p, g, and the pressure k (w - e) that the
    /// calls below take for the plate's velocity.
    const ContactLaw &
    law() const override;
    /// Resultant, pressure range, contact area, energies of the current
    /// status.
    const FoundationDiagnostics &
    diagnostics() const override;

    /// Every Gauss point in contact: the first iterate of eq. (3.9).
    void
    activate_all() override;

    /// The contact rule of law(), for the pressure set last: a point comes
    /// into contact where w_h - e > delta and leaves it where w_h - e <
    /// -delta, delta = contact_tolerance * max |w_h - e|; inside the band
    /// it keeps a status.
    const StatusLaw &
    status_law() const override;

    void
    use_pressure(SpringPressure pressure) override;

    /// FoundationDiagnostics::gap_work().
    double
    status_load_work(const LA::MPI::Vector &ghosted_u) const override;

    /// vector += the force whose work the bed takes without storing it:
    /// the dashpots' c int_S v phi_i, and int_S ([in contact] Gamma (w - g)
    /// - p_s(w - g)) phi_i, the springs' force the solver applies less the
    /// part whose potential is the foundation energy (p_s = Gamma
    /// (w - g)^+, tensionless). The springs' part is not zero where the
    /// dashpots decide the status: a point in contact with w < g (the
    /// dashpot pushes harder than the spring pulls) or out of contact with
    /// w > g (it pulls harder than the spring pushes).
    void
    add_dissipative_force(const LA::MPI::Vector &ghosted_solution,
                          const LA::MPI::Vector &ghosted_velocity,
                          LA::MPI::Vector       &vector) const override;

    /// The contact status and the status the system matrix holds: the next
    /// step starts from them, so a resumed run needs them exactly.
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

  protected:
    /// What its springs measure at the points: the bed's w (the lowest
    /// layer's).
    virtual std::vector<FoundationPoints::Part>
    measured_fields(const FiniteElement<2> &fe) const;
    /// Its law, set by a term that is not the bed (InterfaceSprings).
    ContactLaw &
    own_law();

    /// w_h - e at the Gauss points, e of the pressure set last.
    void
    point_values(const LA::MPI::Vector &ghosted_u,
                 std::vector<double>   &values) const override;
    void
    add_point_matrices(const PointFactors    &points,
                       const double           k,
                       LA::MPI::SparseMatrix &matrix) const override;
    void
    add_point_products(const PointFactors    &points,
                       const double           k,
                       const LA::MPI::Vector &ghosted_src,
                       LA::MPI::Vector       &dst) const override;
    void
    add_point_loads(const PointFactors                        &points,
                    const double                               k,
                    const std::function<double(unsigned int)> &value,
                    LA::MPI::Vector &dst) const override;

  private:
    FoundationPoints points;
    ContactLaw       contact_law;
    ContactRule      contact_rule{contact_law};
    SpringTerm       term;

    /// Reads `points`, `contact_law` and the status.
    FoundationDiagnostics foundation_diagnostics;
  };
} // namespace liftoff
