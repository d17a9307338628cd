#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>

#include <liftoff/fem/system_term.h>

#include <array>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  struct Joint;
  class SlabLayout;

  /**
   * What the joints between slabs pass that are not tied: aggregate
   * interlock as springs of stiffness AGG per unit length of joint against
   * the jump of w across it, and, if given, springs of stiffness R per unit
   * length against the jump of the rotation psi . n about the joint's line
   * (a moment). Energy 1/2 int_joint AGG [w]^2 + R [psi . n]^2 ds; a joint
   * with both stiffnesses 0 is free. The springs are integrated on the
   * finer face of each pair of faces across a joint, at its Gauss points
   * and at the same points of the cell opposite, so meshes refined
   * differently on the two sides are coupled exactly.
   */
  class JointSprings : public SystemTerm
  {
  public:
    /// `Slabs/Shear stiffness` and `Slabs/Rotational stiffness`.
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
    /// Refuse a list of stiffnesses that gives neither one value, nor one
    /// per joint of the whole plate, nor one per joint of the modelled
    /// part of `slabs`.
    void
    check_against(const SlabLayout &slabs) const;

    void
    setup(const Discretization &discretization) override;
    void
    add_to_matrix(const MatrixFactors   &factors,
                  LA::MPI::SparseMatrix &matrix) override;
    void
    add_force(const TermState &state, LA::MPI::Vector &force) const override;
    double
    energy(const TermState &state) const override;
    std::string
    energy_column() const override
    {
      return "joint_springs";
    }
    /// Each joint's AGG and R that are not 0.
    std::vector<Coupling>
    couplings() const override;

    /// Where the larger side moves by less than this fraction of the
    /// plate's largest load deflection, the load is too far from the joint
    /// for a load transfer to mean anything (a truck 5 m from a joint:
    /// ratios of -0.57 and 0.43), and none is given.
    static constexpr double far_load_fraction = 0.1;

    /// The load transfer of the changes a and b of w since rest on the two
    /// sides of a joint, the smaller over the larger; NaN (written empty)
    /// where the larger is below far_load_fraction of `reference`, the
    /// plate's largest change of w, or `reference` is 0.
    static double
    load_transfer(const double a, const double b, const double reference);
    /// The largest |w - w_rest| over the plate, or 0 where it is below
    /// 1e-6 of the largest |w_rest|, round-off (collective).
    double
    largest_load_deflection(const LA::MPI::Vector &ghosted_u,
                            const LA::MPI::Vector &ghosted_rest) const;

    /// What a joint passes at ghosted_u: the shear force from its lower to
    /// its upper slab, int AGG (w_lower - w_upper) ds over the whole joint
    /// (its mirror images included), and its load transfer efficiency of
    /// the load's part, w - w_rest (load_transfer()), at the Gauss point
    /// of the joint where the larger change of its two sides is largest.
    struct Transfer
    {
      double shear_force = 0;
      double efficiency  = 1;
    };
    /// One per joint of the layout (tied ones: 0 and 1; collective).
    std::vector<Transfer>
    transfer(const LA::MPI::Vector &ghosted_u,
             const LA::MPI::Vector &ghosted_rest) const;

    /// w on both sides of a joint at a Gauss point of its faces, their
    /// load transfer (load_transfer() with the plate's largest change),
    /// and the aggregate interlock's shear force per length there, from
    /// the lower slab to the upper one.
    struct JointPoint
    {
      unsigned int joint;
      Point<2>     x;
      double       w_lower;
      double       w_upper;
      double       lte;
      double       shear;
    };
    /// The points of the joints' pieces this rank integrates (not
    /// collective).
    std::vector<JointPoint>
    points_along(const LA::MPI::Vector &ghosted_u,
                 const LA::MPI::Vector &ghosted_rest) const;

  private:
    std::vector<double> shear_stiffness;
    std::vector<double> rotational_stiffness;

    /// One face of a joint with the points of the cell opposite: the dofs
    /// of both cells (this side's first) and the jumps of w and psi . n
    /// of each of them at each Gauss point, times sqrt(JxW).
    struct Segment
    {
      unsigned int                         joint;
      int                                  sign;
      std::vector<types::global_dof_index> dofs;
      std::vector<std::vector<double>>     w_jump;
      std::vector<std::vector<double>>     rotation_jump;
      std::vector<Point<2>>                points;
    };
    std::vector<Segment> segments;
    /// The locally owned entries of w.
    IndexSet              w_dofs;
    const Discretization *discretization = nullptr;
    LA::MPI::SparseMatrix springs;
    bool                  has_springs = false;

    double
    stiffness_of(const std::vector<double> &values,
                 const unsigned int         joint) const;
    /// The segment of `cell`'s face `face` on `joint`.
    Segment
    make_segment(const DoFHandler<2>::active_cell_iterator &cell,
                 const unsigned int                         face,
                 const unsigned int                         joint) const;
    void
    assemble();
    /// At a Gauss point of `segment` (its row of w_jump): this side's w,
    /// the opposite side's w, each times sqrt(JxW), and sqrt(JxW).
    static std::array<double, 3>
    sides(const Segment             &segment,
          const std::vector<double> &jump,
          const LA::MPI::Vector     &ghosted_u);
  };
} // namespace liftoff
