#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>

#include <liftoff/contact/dowel_bar.h>
#include <liftoff/contact/dowel_law.h>
#include <liftoff/contact/dowel_layout.h>
#include <liftoff/contact/status_term.h>

#include <map>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class SlabLayout;
  class PlateGeometry;
  struct Joint;

  /**
   * Dowels at points along the joints between slabs: each a spring of
   * stiffness C between the two slabs' w at its point, with a looseness g:
   * no force while the jump [w] = w_lower - w_upper is within g, and
   * F = C ([w] - g sign [w]) beyond. Energy 1/2 C (|[w]| - g)^2 where
   * |[w]| > g. A dowel's status is slack, engaged with [w] > g, or engaged
   * with [w] < -g; within a status its force is affine in u, and the
   * active-set iteration drives it with the foundation's contact set
   * (StatusTerm, whose law is the DowelLaw). With g = 0 a dowel is always
   * engaged: a linear spring.
   *
   * A dowel belongs to the rank that owns the cell on the finer side of
   * the joint where it sits (the side JointSprings integrates on), and is
   * evaluated there and at the same point of the cell opposite. On a half
   * or quarter model the dowels of the mirror images are left out, and a
   * dowel on a symmetry plane acts with the modelled part's share of its
   * stiffness (1/2 per plane; its force is the whole dowel's).
   */
  class JointDowels : public StatusTerm
  {
  public:
    /// Subsection `Slabs/Dowels`.
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
    /// Places the dowels on the joints of `geometry`'s slabs, refusing a
    /// joint that is not there or is tied, a position off the joint, and
    /// dowels that are not mirror images across a symmetry plane.
    void
    place_on(const PlateGeometry &geometry);

    /// The dowels (none: the scene has no dowels), in the order of
    /// forces().
    const std::vector<DowelSite> &
    sites() const;
    /// The stiffness C of each dowel.
    double
    stiffness() const;
    /// The bar, if the stiffness comes from it (Stiffness = 0).
    const DowelBar *
    bar() const;

    void
    setup(const Discretization &discretization) override;
    void
    add_force(const TermState &state, LA::MPI::Vector &force) const override;
    double
    energy(const TermState &state) const override;
    std::string
    energy_column() const override
    {
      return "dowels";
    }

    /// Its play: slack within g, engaged one way or the other beyond (a
    /// dowel engaged both ways in a union acts without play).
    const StatusLaw &
    status_law() const override;
    double
    status_load_work(const LA::MPI::Vector &ghosted_u) const override;

    /// Each dowel's force F (from the lower slab to the upper one) at
    /// ghosted_u with the current status, on every rank (collective).
    std::vector<double>
    forces(const LA::MPI::Vector &ghosted_u) const;

    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

  protected:
    /// [w] at each dowel of this rank.
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
    /// The dowels' C, every dowel engaged; reached through SystemTerm
    /// (StiffnessLimit) only.
    std::vector<Coupling>
    couplings() const override;

    DowelLayout layout;
    double      given_stiffness = 0;
    DowelBar    dowel_bar;
    double      looseness = 0;
    DowelLaw    law;

    std::vector<DowelSite> dowel_sites;

    /// A dowel of this rank: its number, the dofs of the two cells, and
    /// [w] at its point as their coefficients.
    struct Local
    {
      unsigned int                         index;
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  jump;
    };
    std::vector<Local>    local;
    const Discretization *discretization = nullptr;

    /// Dowel d, on the piece `face` of `cell` (a piece of its joint).
    Local
    make_local(const DoFHandler<2>::active_cell_iterator &cell,
               const unsigned int                         face,
               const unsigned int                         d) const;
    /// [w] of local dowel i at ghosted_u.
    double
    jump_of(const unsigned int i, const LA::MPI::Vector &ghosted_u) const;
    /// matrix += factor b b^T of local dowel i (no compress).
    void
    add_dowel(const unsigned int     i,
              const double           factor,
              LA::MPI::SparseMatrix &matrix) const;
    /// vector += factor b of local dowel i (no compress).
    void
    add_vector(const unsigned int i,
               const double       factor,
               LA::MPI::Vector   &vector) const;
  };
} // namespace liftoff
