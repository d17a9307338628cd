#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/discretization.h>

#include <limits>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * Adaptive meshes (`Mesh refinement`): which cells to refine and coarsen,
   * and the move of the state to the new mesh. The difficulty of the
   * paper's scenes sits in two places, under a point load (w grows like
   * ln(1/h) there) and along the contact front, which travels; a uniform
   * mesh pays everywhere for what a band needs.
   *
   * Cells are chosen by up to three indicators: deal.II's Kelly estimate of
   * the gradient jumps of w, psi_x and psi_y (refine and coarsen by
   * fractions of the cells, as step-26 does); the contact front, cells
   * whose Gauss points are partly in contact and those within `Front band`
   * layers of them; and the cells under a load (a point or a patch, and the
   * stretch of a moving load's path until the next adaptation, so the fine
   * cells wait for the load and are coarsened behind it). The last two are
   * always refined up to `Maximum level` and not coarsened while they hold
   * the front or a load; without Kelly every other cell is flagged for
   * coarsening, so the band moves with the front. Levels count
   * from the uniform mesh of `Discretization`.
   *
   * The Kelly indicators are rounded to six digits of their maximum before
   * the thresholds are found: the indicators of symmetric cells are equal
   * in exact arithmetic, and round-off (which depends on the number of
   * ranks) must not decide which of them is refined.
   */
  class MeshRefinement
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Refuse a discretization that cannot be refined locally (checks that
    /// need the Discretization's parameters).
    void
    check_against(const Discretization &discretization) const;

    bool
    is_enabled() const;
    /// Whether the mesh is adapted after step `step` of a time loop.
    bool
    is_due(const unsigned int step) const;
    /// Refine-and-solve cycles after the first solve of a static analysis.
    unsigned int
    n_static_cycles() const;
    /// `Initial refinements` (0 when not adaptive).
    unsigned int
    n_initial_refinements() const;

    /// Where the loads act in consecutive windows of the time ahead, each
    /// as long as the time between two adaptations
    /// (LoadSet::regions_in_windows). A cell under window k is refined up
    /// to `Maximum level` - k: a cell gains one level per adaptation, so a
    /// moving load finds its cells at Maximum level when it arrives.
    using Windows = std::vector<std::vector<BoundingBox<2>>>;

    /// Before the first step: refine the cells under the loads
    /// `Initial refinements` times (no state to move yet).
    void
    refine_around_loads(Discretization &discretization,
                        const Windows  &windows) const;
    /// The number of steps from one adaptation to the next: the length of
    /// a window.
    unsigned int
    steps_between_adaptations() const;
    /// The number of windows the loads are looked ahead: the levels a cell
    /// may have to gain.
    unsigned int
    n_windows() const;

    /// Flag cells for refinement and coarsening from the deflection and
    /// the contact status, given as the fraction of each owned cell in
    /// contact (indexed by active cell index: the front runs through the
    /// cells strictly between 0 and 1); returns whether the mesh would
    /// change on any rank (collective).
    bool
    mark_cells(Discretization        &discretization,
               const Vector<float>   &contact_fraction,
               const Windows         &windows,
               const LA::MPI::Vector &ghosted_solution) const;

    /// Refine and coarsen as flagged, rebuild the dofs and carry `vectors`
    /// (owned entries, constraints distributed) to the new mesh by
    /// interpolation; they are owned vectors of the new mesh afterwards,
    /// with the new hanging-node constraints distributed.
    void
    execute(Discretization                       &discretization,
            const std::vector<LA::MPI::Vector *> &vectors) const;

  private:
    /// Entries on when the mesh adapts (Adaptive, Interval, Static cycles,
    /// Initial refinements), and on where (Indicators and their limits).
    static void
    declare_when_parameters(ParameterHandler &prm);
    static void
                 declare_where_parameters(ParameterHandler &prm);
    bool         enabled          = false;
    unsigned int interval         = 10;
    unsigned int static_cycles    = 3;
    double       refine_fraction  = 0.3;
    double       coarsen_fraction = 0.1;
    /// `Maximum number of cells` (0: no limit), unless it is `auto`.
    unsigned int max_n_cells     = 0;
    bool         cell_limit_auto = true;
    /// The limit on the number of cells for refine_and_coarsen_fixed_number.
    unsigned int
                 cell_limit(const Discretization &discretization) const;
    int          min_level           = 0;
    unsigned int max_level           = 3;
    unsigned int front_band          = 1;
    unsigned int initial_refinements = 0;
    bool         uses_kelly          = true;
    bool         uses_front          = true;
    bool         uses_loads          = true;

    /// The Kelly estimate per active cell, rounded (see the class comment).
    Vector<float>
    kelly_indicators(const Discretization  &discretization,
                     const LA::MPI::Vector &ghosted_solution) const;
    /// 1 on the owned cells cut by the contact front or within the band,
    /// indexed by active cell index.
    std::vector<bool>
    front_cells(const Discretization &discretization,
                const Vector<float>  &contact_fraction) const;
    /// Unflag for coarsening, and with `refine` flag for refinement, every
    /// owned cell where `is_wanted` holds.
    template <class Predicate>
    void
    force_refinement(Discretization  &discretization,
                     const Predicate &is_wanted,
                     const bool       refine = true) const;
    /// Keep the cells under the loads' windows from coarsening and, with
    /// `refine`, flag those below their window's level for refinement.
    void
    keep_loads_fine(Discretization &discretization,
                    const Windows  &windows,
                    const bool      refine) const;
    /// Clear the flags that would leave [min level, max level].
    void
    limit_levels(Discretization &discretization) const;
  };
} // namespace liftoff
