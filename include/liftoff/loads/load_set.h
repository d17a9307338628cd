#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/loads/load.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  struct LoadKind;

  /**
   * The loads of a scene: concentrated forces at arbitrary points, pressures
   * on rectangles, line loads along edges or any straight segment, uniform
   * patch loads (a rectangle
   * or a disc, a tyre's contact area) and vehicles (groups of point or
   * patch loads at fixed offsets from one path), any number of each up to
   * max_loads_per_kind, each scaled by its own time history h(tau).
   * Positive loads press the plate into the foundation (w > 0).
   *
   * Point loads, patch loads, line loads on a segment and vehicles may
   * move: their position is a path (x(tau), y(tau)), and their vector is
   * built anew at every step at the current position (a point load by the
   * shape functions at the point, a patch or a line by PatchIntegrator
   * over the part of each cell it covers). The part of a load off the
   * plate carries nothing.
   *
   * The scene describes the full plate. On a half or quarter model only the
   * part of each load that falls on the meshed part is applied; a point on
   * a symmetry plane carries its share.
   *
   * Whatever does not change in time is assembled once: the load vector at
   * time tau is sum_k h_k(tau) b_k. Only pressures and line loads whose
   * intensity names tau (and the body force of set_body_force()) are
   * integrated again at every step.
   *
   * Each kind of load is a class of its own (PointLoad, Pressure,
   * LineLoad, PatchLoad, the wheels of a Vehicle) behind Load, listed in
   * load_kinds(); the set keeps the loads, the tracks that history.csv
   * follows and the body force, and names no kind.
   */
  class LoadSet
  {
  public:
    static constexpr unsigned int max_loads_per_kind = 8;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// No load is on (every Magnitude is 0) and no body force is set.
    bool
    is_empty() const;

    /// Some load acts from before tau = 0 (Loads/Self weight != 0): a time
    /// integration then starts from the static equilibrium under it.
    bool
    has_permanent_loads() const;

    /// The load vector of the permanent loads alone (owned entries,
    /// constraints applied).
    void
    assemble_permanent(LA::MPI::Vector &load_vector) const;

    /// Some load is of the plate at rest: permanent, or a temperature load
    /// (the curl a deflectometer's reading starts from).
    bool
    has_rest_loads() const;
    /// The load vector of those loads at tau = 0.
    void
    assemble_rest(LA::MPI::Vector &load_vector) const;

    /// Where the point and patch loads act in n_windows consecutive
    /// windows of time from tau, each `window` long: for each window, boxes
    /// in plate coordinates (a point load that stands: the box of its
    /// point; one that moves: the box of its path over the window; a
    /// patch: widened by its half size). Mesh refinement keeps their cells
    /// fine (MeshRefinement::Windows).
    std::vector<std::vector<BoundingBox<2>>>
    regions_in_windows(const double       tau,
                       const double       window,
                       const unsigned int n_windows) const;

    /// The moving loads (and vehicles) that history.csv follows: for each
    /// a name (`point_load_2`, `patch_load_1`, `vehicle_1`) ...
    std::vector<std::string>
    moving_load_names() const;
    /// ... and, in that order, x and y of its path at tau and how many of
    /// its loads touch the plate (0 or 1; a vehicle: its wheels). After
    /// setup().
    std::vector<double>
    moving_load_positions(const double tau) const;

    /// Loads inside the plate, and symmetric where the model relies on it:
    /// on a half or quarter model every load must have a mirror image whose
    /// history agrees at the `n_steps + 1` times k * time_step and whose
    /// intensity agrees at every quadrature point of the full plate's mesh
    /// (at every one of those times if it names tau). Collective.
    void
    check_against(const Discretization &discretization,
                  const double          time_step,
                  const unsigned int    n_steps) const;

    /// Precompute the time independent parts on this discretization.
    void
    setup(const Discretization &discretization);

    /// The load vector F(tau) (owned entries, constraints applied).
    void
    assemble(const double tau, LA::MPI::Vector &load_vector) const;

    /// After assemble() gave a non-finite number at `tau`: which load did
    /// it, and how (its time history, its intensity, an overflow), for an
    /// error message. Collective.
    std::string
    non_finite_load(const double tau) const;

    /// A distributed force on all three equations (force on w, moments on
    /// psi_x and psi_y), f(x, y) with time set by set_time(tau); it is
    /// integrated at every step. Not part of a scene: manufactured-solution
    /// tests use it. Pass nullptr to remove it.
    void
    set_body_force(Function<2> *force);

    /// Hand the plate's section to the loads that need it (a temperature
    /// load's moment); after parse_parameters().
    void
    use_plate(const MindlinPlate &plate);
    /// The free curvature and face stresses of the temperature loads at
    /// tau (each times its h(tau)), summed; empty if no load has any.
    FreeBendingField
    free_bending(const double tau) const;

  private:
    /// A moving load or a vehicle as history.csv reports it: the loads
    /// (indices into `loads`) that share its path.
    struct Track
    {
      std::string               name;
      std::vector<unsigned int> members;
    };

    std::vector<std::unique_ptr<Load>> loads;
    std::vector<Track>                 tracks;
    const Discretization              *discretization = nullptr;
    Function<2>                       *body_force     = nullptr;

    /// Subsection `section` of Loads read by `kind`, its loads added.
    void
    read_section(ParameterHandler  &prm,
                 const LoadKind    &kind,
                 const std::string &section);
    void
    add_body_force(const double tau, LA::MPI::Vector &load_vector) const;

    /// load_vector = sum of h_k(tau) b_k over the loads that `selected`
    /// accepts.
    void
    assemble_selected(const double                             tau,
                      const std::function<bool(const Load &)> &selected,
                      LA::MPI::Vector &load_vector) const;

    /// regions_in_windows() for one window.
    std::vector<BoundingBox<2>>
    regions_under_loads(const double tau_begin, const double tau_end) const;
    /// The parts of check_against(): every load on the plate (at some of
    /// the step `times`, if it moves), and the mirror images on a reduced
    /// model. Collective.
    void
    require_on_plate(const std::vector<double> &times,
                     const PlateGeometry       &geometry) const;
    void
    check_symmetry(const std::vector<double> &times,
                   const Discretization      &disc) const;
    /// Refuse the path of `load` if it is not finite at one of `times` or
    /// never brings a load on it (a vehicle: one of its wheels) onto the
    /// plate.
    void
    require_path_on_plate(const Load                &load,
                          const std::vector<double> &times,
                          const PlateGeometry       &geometry) const;
    /// Refuse the path of `load`, whose offset keeps a heading (a tyre of
    /// Axles), if it heads another way at one of `times`.
    void
    require_heading_kept(const Load                &load,
                         const std::vector<double> &times) const;
  };
} // namespace liftoff
