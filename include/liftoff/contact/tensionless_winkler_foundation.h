#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/discretization.h>

#include <functional>
#include <memory>
#include <string>
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
   * push on the gap, joins the right-hand side (add_gap_load()). A scene
   * without a gap (g = 0 at every Gauss point) takes none of these paths.
   *
   * Dashpots c per unit area beside the springs make the pressure
   * Gamma (w - g) + c v, also only in contact and never tensile. Wherever
   * the velocity is affine in w, v = kappa w - o (Newmark: kappa =
   * gamma / (beta dt), o from the previous state; at a given state kappa =
   * 0, o = -v), the pressure is (Gamma + c kappa) (w - e) with the
   * effective gap e = (Gamma g + c o) / (Gamma + c kappa): the same rule,
   * matrix and right-hand side as a gap, with another stiffness and gap
   * (set_dashpot_velocity()).
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
   */
  class TensionlessWinklerFoundation
  {
  public:
    enum class Model
    {
      tensionless,
      bilateral,
      none
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    void
    setup(const Discretization &discretization);

    /// Every Gauss point in contact: the first iterate of eq. (3.9).
    void
    activate_all();

    /// Status from w_h at the Gauss points: a point comes into contact where
    /// w_h > delta and leaves it where w_h < -delta, delta =
    /// contact_tolerance * max |w_h|. Returns the number of points (over all
    /// ranks) whose status changed.
    unsigned long
    update_contact_status(const LA::MPI::Vector &ghosted_solution);

    /// Give the points whose w_h lay inside the round-off band at the last
    /// update_contact_status() the status they have in `earlier`: inside
    /// the band the rule keeps a status, and this says which. Returns the
    /// number of points (over all ranks) whose status changed.
    unsigned long
    keep_status_in_band(const std::vector<unsigned char> &earlier);

    /// Add the foundation stiffness K_f of the current status to `matrix`
    /// and remember that `matrix` now holds it.
    void
    add_to_matrix(LA::MPI::SparseMatrix &matrix);
    /// Add the K_f of `status` (a contact_status() of this mesh) to
    /// `matrix`, which then holds no status that update_matrix() knows of:
    /// to build again a matrix that was built from that status.
    void
    add_to_matrix(const std::vector<unsigned char> &status,
                  LA::MPI::SparseMatrix            &matrix) const;

    /// The status whose K_f the matrix of add_to_matrix() and
    /// update_matrix() holds.
    const std::vector<unsigned char> &
    status_in_matrix() const;

    /// dst += (K_f(status_in_matrix()) - K_f(reference)) src: the product
    /// with the change of the matrix since it held the status `reference`,
    /// from the cells whose status differs. `ghosted_src` must satisfy the
    /// constraints (GhostUpdate::distribute()); `dst` has no ghosts.
    /// Collective.
    void
    add_change_product(const std::vector<unsigned char> &reference,
                       const LA::MPI::Vector            &ghosted_src,
                       LA::MPI::Vector                  &dst) const;

    /// Bring the K_f held in `matrix` (by add_to_matrix()) up to date with
    /// the status: only the points that changed are touched. Returns the
    /// number of points updated over all ranks (0: `matrix` is unchanged).
    unsigned long
    update_matrix(LA::MPI::SparseMatrix &matrix);

    /// vector += K_f(status) u, the linear part of the springs' (and the
    /// shear layer's) reaction to u (the whole reaction without a gap).
    void
    add_reaction(const LA::MPI::Vector &ghosted_solution,
                 LA::MPI::Vector       &vector) const;

    /// Whether some Gauss point has g != 0 or there are dashpots: then the
    /// reaction is K_f(S) u - f_g(S), and f_g(S) belongs to every
    /// right-hand side.
    bool
    has_gap() const;

    /// vector += f_g(status) = k int_S e phi_i, the part of the foundation's
    /// force that does not depend on u (k = Gamma, e = g without dashpots).
    /// Call only if has_gap().
    void
    add_gap_load(LA::MPI::Vector &vector) const;

    /// Whether some Gauss point has g != 0 (an initial gap, not dashpots).
    bool
    has_initial_gap() const;

    /// Whether the bed pushes an unloaded plate (g < 0 at some Gauss point:
    /// a pre-compression), so that a scene without loads still moves.
    bool
    is_pressing_plate() const;

    /// g at a point of the meshed part (0 without a gap), for output.
    double
    gap_at(const Point<2> &p) const;

    /// Whether there is a shear layer (Shear modulus > 0).
    bool
    has_layer() const;

    /// sqrt(Gamma): the angular frequency of the plate (unit mass per
    /// area) moving as a rigid body on the springs.
    double
    rigid_body_frequency() const;

    /// Whether there are dashpots (Damping > 0).
    bool
    has_damping() const;

    /// From now on, the system matrices this class adds to hold the
    /// stiffness Gamma + c kappa (kappa = 0: a static solve, or
    /// gamma / (beta dt) in a time step). Before add_to_matrix().
    void
    set_matrix_velocity_factor(const double kappa);

    /// The velocity at the points is v = kappa w - o (o from
    /// `ghosted_offset`): sets the effective gap e and stiffness
    /// Gamma + c kappa of the contact rule and of add_gap_load(). Only with
    /// dashpots.
    void
    set_dashpot_velocity(const double           kappa,
                         const LA::MPI::Vector &ghosted_offset);

    /// vector += c int_S v phi_i, the dashpots' force at the velocity v.
    void
    add_dashpot_force(const LA::MPI::Vector &ghosted_velocity,
                      LA::MPI::Vector       &vector) const;

    /// The pressure Gamma (w - g) + c v at the Gauss points: its smallest
    /// value at a point in contact, its largest at a point out of contact,
    /// and its largest magnitude (collective; for tests).
    struct PressureRange
    {
      double smallest_in_contact    = 0;
      double largest_out_of_contact = 0;
      double largest_magnitude      = 0;
    };
    PressureRange
    pressure_range(const LA::MPI::Vector &ghosted_solution,
                   const LA::MPI::Vector &ghosted_velocity) const;

    /// Gamma int_S g (g - w): with a gap, Clapeyron's theorem for an
    /// equilibrium K u + K_f(S) u - f_g(S) = F reads
    /// E = 1/2 (F.u + gap_work(u)), the springs' energy being
    /// 1/2 Gamma int_S (w - g)^2. 0 without a gap.
    double
    gap_work(const LA::MPI::Vector &ghosted_solution) const;

    /// Energy stored in the springs, 1/2 Gamma int max(w - g, 0)^2 (or
    /// (w - g)^2 when bilateral), and in the shear layer,
    /// 1/2 G_p int_S |grad w|^2, on the meshed part.
    double
    energy(const LA::MPI::Vector &ghosted_solution) const;

    /// The bed's normal reaction on the full plate: the force of the
    /// springs and dashpots int_S (Gamma (w - g) + c v) over the points in
    /// contact, its centre (the point about which it has no moment), and
    /// the area in contact; a symmetric part's values times its copies, the
    /// centre on the symmetry planes. The shear layer adds no force (its
    /// G_p int_S grad w . grad 1 vanishes) and is left out. Without a
    /// force the centre is (0, 0). `ghosted_velocity` is read only with
    /// dashpots (collective).
    struct Resultant
    {
      double   force = 0;
      Point<2> centre;
      double   contact_area = 0;
    };
    Resultant
    resultant(const LA::MPI::Vector &ghosted_solution,
              const LA::MPI::Vector &ghosted_velocity) const;

    /// Area in contact over the area of the meshed part.
    double
    contact_area_fraction() const;

    /// How firmly the springs in contact hold the rigid-body motions that
    /// nothing else holds on a plate with free edges (w = 1, and w = x,
    /// w = y unless x = 0 or y = 0 is a symmetry plane): the smallest
    /// eigenvalue of the contact set's moment matrix int_S r_i r_j over
    /// that of the whole meshed part, in [0, 1]. Zero exactly when the set
    /// is empty or lies on a line, i.e. when K + K_f(S) is singular for a
    /// free plate (collective).
    double
    rigid_body_restraint() const;

    /// Fraction of each locally owned cell's Gauss points in contact,
    /// indexed by active cell index, for output.
    Vector<float>
    contact_fraction_per_cell() const;

    /// The status of the locally owned Gauss points (1: in contact), and
    /// its replacement; the layout is this class's own, the same between
    /// calls on one mesh.
    const std::vector<unsigned char> &
    contact_status() const;
    void
    set_contact_status(const std::vector<unsigned char> &status);
    /// The contact status and the status the system matrix holds: the next
    /// step starts from them, so a resumed run needs them exactly.
    void
    save(OutputArchive &archive) const;
    void
    load(InputArchive &archive);

    Model  model             = Model::tensionless;
    double stiffness         = 1.0;
    double contact_tolerance = 1e-9;
    /// g(x, y) in full plate coordinates.
    std::string gap_expression = "0";
    /// c, dashpots per unit area.
    double damping = 0;
    /// G_p, the Pasternak shear layer's modulus (0: none).
    double shear_modulus = 0;

  private:
    const Discretization *discretization = nullptr;
    unsigned int          n_q_points     = 0;
    /// Local indices (within a cell) of the w shape functions.
    std::vector<unsigned int> w_dofs;
    /// phi_i(x_q) for the w shape functions: the same on every cell.
    FullMatrix<double> shape_values;
    /// grad phi_k(x_q) for the w shape functions per (owned cell, q, k):
    /// only with a shear layer.
    std::vector<Tensor<1, 2>> shape_gradients;
    /// Flat per (owned cell, q) or per (owned cell, w dof) data.
    std::vector<types::global_dof_index> cell_w_dof_indices;
    std::vector<unsigned int>            cell_index;
    std::vector<double>                  jxw;
    std::vector<Point<2>>                gauss_points;
    std::vector<unsigned char>           in_contact;
    /// g at the points, if is_gapped: some point on some rank has g != 0.
    std::vector<double> gap;
    bool                is_gapped        = false;
    bool                is_precompressed = false;
    /// g(x, y), kept for evaluation off the Gauss points (if is_gapped).
    std::unique_ptr<FunctionParser<2>> gap_function;
    /// has_gap(): a gap or dashpots.
    bool is_affine = false;
    /// The effective gap e of the contact rule and of add_gap_load() and
    /// its stiffness, and the stiffness the matrix holds: g and Gamma
    /// without dashpots.
    std::vector<double> effective_gap;
    double              effective_stiffness = 1.0;
    double              matrix_stiffness    = 1.0;
    /// w_h at the points, kept between the two passes of a status update.
    std::vector<double> w_at_points;
    /// The half-width of the round-off band at the last status update.
    double band = 0;
    /// The status that the matrix given to add_to_matrix() holds, and the
    /// points whose status may differ from it.
    std::vector<unsigned char> in_matrix;
    std::vector<unsigned int>  points_to_update;
    /// Whether dof i (by local w index within a cell c) is constrained;
    /// constrained rows and columns carry no foundation term.
    std::vector<unsigned char> cell_w_dof_is_constrained;
    /// Whether an owned cell has a hanging w node (an adaptive mesh).
    std::vector<unsigned char> cell_has_hanging_node;

    /// Record a status change of point i for update_matrix().
    void
    set_status(const unsigned int i, const unsigned char status);

    /// matrix += sum_q weight[q] phi(x_q) phi(x_q)^T + layer_weight[q]
    /// grad phi(x_q) grad phi(x_q)^T on owned cell c (the second term only
    /// with a layer), without the constrained rows and columns.
    void
    add_cell_term(const unsigned int         c,
                  const std::vector<double> &weight,
                  const std::vector<double> &layer_weight,
                  LA::MPI::SparseMatrix     &matrix) const;

    /// add_cell_term() for a cell with hanging nodes: the cell matrix
    /// condensed with the constraints.
    void
    add_condensed(const unsigned int        c,
                  const FullMatrix<double> &cell_matrix,
                  LA::MPI::SparseMatrix    &matrix) const;

    /// Where the entries of cell_w_dof_indices sit in the local storage
    /// (owned and ghost entries) of ghosted vectors of one layout. Epetra
    /// finds a global index in a ghosted layout through a hash table, one
    /// lookup per cell and w dof at every contact update; the Example 2
    /// pulse's contact updates took 0.083 s before and 0.071 s after.
    /// Kept per layout: the copy of the map holds Epetra's map data, so its
    /// address, which identifies the layout, cannot pass to another map.
    struct LocalPositions
    {
      std::unique_ptr<Epetra_BlockMap> map;
      /// -1 stands for the entries `map` does not hold (positions_in()).
      bool             owned_only = false;
      std::vector<int> positions;
    };
    mutable std::vector<LocalPositions> local_positions;

    /// The positions of cell_w_dof_indices in the storage of u, which
    /// must hold every one of them (a ghosted vector); with `owned_only`,
    /// -1 for those it does not hold (a vector without ghosts).
    const int *
    positions_in(const LA::MPI::Vector &u, const bool owned_only = false) const;

    /// w_h at the Gauss points of owned cell c.
    void
    deflection_at_gauss_points(const LA::MPI::Vector &ghosted_solution,
                               const unsigned int     c,
                               std::vector<double>   &w) const;

    /// grad w_h at the Gauss points of owned cell c (with a layer).
    void
    deflection_gradient_at_gauss_points(
      const LA::MPI::Vector     &ghosted_solution,
      const unsigned int         c,
      std::vector<Tensor<1, 2>> &gradient) const;

    /// 1/2 G_p int_S |grad w_h|^2 over this rank's cells.
    double
    layer_energy(const LA::MPI::Vector &ghosted_solution) const;

    /// w_h - g at the Gauss points of owned cell c: how far the plate
    /// presses into the bed.
    void
    compression_at_gauss_points(const LA::MPI::Vector &ghosted_solution,
                                const unsigned int     c,
                                std::vector<double>   &compression) const;

    /// vector += the cell vectors f(c, cell_vector) (zeroed before) of
    /// the owned cells, condensed. Collective (compress).
    void
    add_cell_vectors(
      const std::function<void(const unsigned int, Vector<double> &)> &f,
      LA::MPI::Vector &vector) const;

    /// vector += coefficient int_S f phi_i, f at the Gauss points of owned
    /// cell c given by f(c, values). Collective (compress).
    void
    add_contact_integral(
      const double coefficient,
      const std::function<void(const unsigned int, std::vector<double> &)> &f,
      LA::MPI::Vector &vector) const;

    /// Fill `gap` from gap_expression at the Gauss points (left empty if
    /// g = 0 at all of them on all ranks), refusing a g that is not finite
    /// or, on a half or quarter model, not symmetric. Collective.
    void
    evaluate_gap();
  };
} // namespace liftoff
