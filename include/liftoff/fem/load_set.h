#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/fem/patch_integrator.h>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace liftoff
{
  using namespace dealii;

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
   */
  class LoadSet
  {
  public:
    static constexpr unsigned int max_loads_per_kind = 8;

    /// What a patch load or a vehicle's wheel covers.
    enum class Shape
    {
      point,
      rectangle,
      disc
    };

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

  private:
    /// The entries of the i-th point load, pressure and line load.
    static void
    declare_numbered_loads(ParameterHandler &prm, const unsigned int i);
    enum class Kind
    {
      point,
      pressure,
      line,
      patch
    };

    struct Load
    {
      Kind         kind;
      std::string  name; // e.g. "Loads/Point load 2", for messages
      double       magnitude = 0;
      std::string  history_expression;
      std::string  intensity_expression;
      Point<2>     position; // fixed point loads
      std::string  region;   // pressures
      unsigned int edge = 0; // line loads
      /// A line load's ends (offsets from the path's point if it moves);
      /// none: it lies along `edge`.
      std::optional<std::array<Point<2>, 2>> segment;
      std::unique_ptr<FunctionParser<1>>     history;   // h(tau)
      std::unique_ptr<FunctionParser<2>>     intensity; // f(x, y, tau)
      bool                                   intensity_depends_on_time = false;
      /// (x, y)(tau) of point loads, patches and vehicles (one path for
      /// all the wheels of a vehicle); none: the point load stands at
      /// `position`.
      std::string path_expression;
      std::string path_owner; // the subsection of Path, for messages
      std::shared_ptr<FunctionParser<1>> path;
      bool                               moves = false; // the path names tau
      Tensor<1, 2>                       offset; // a wheel's, from the path
      Shape                              shape = Shape::rectangle; // patches
      /// Patches: width along x and y (a disc: its diameter twice).
      std::array<double, 2> size = {{0, 0}};
      /// Acts from before tau = 0 with h = 1 (the self-weight).
      bool            is_permanent = false;
      LA::MPI::Vector spatial_part; // b_k

      double
      intensity_at(const Point<2> &p, const double tau) const;
      /// Where the point load or the patch's centre is at tau.
      Point<2>
      position_at(const double tau) const;
      /// Whether some of it acts on the plate at tau: exactly on the
      /// rectangle; on other shapes a load is on the plate if one of 17 x
      /// 17 points over its area (65 along a line) is.
      bool
      touches(const PlateGeometry &geometry, const double tau) const;
      /// Where a line load lies at tau (the plate's box places an Edge) ...
      PatchIntegrator::Segment
      line_at(const BoundingBox<2> &plate, const double tau) const;
      /// ... and one given by its Segment.
      PatchIntegrator::Segment
      segment_at(const double tau) const;
    };

    /// A moving load or a vehicle as history.csv reports it: the loads
    /// (indices into `loads`) that share its path.
    struct Track
    {
      std::string               name;
      std::vector<unsigned int> members;
    };

    std::vector<Load>     loads;
    std::vector<Track>    tracks;
    const Discretization *discretization = nullptr;
    Function<2>          *body_force     = nullptr;

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
    /// Rectangle of a pressure, in full plate coordinates.
    static BoundingBox<2>
    region_of(const Load &load, const BoundingBox<2> &plate);
    /// Name, Magnitude, Time history and (point and patch loads) Path of
    /// subsection `section` of Loads, for every kind and the vehicles.
    static Load
    read_timed(ParameterHandler  &prm,
               const Kind         kind,
               const std::string &section);
    /// The load of subsection `section` of Loads, its expressions parsed.
    Load
    read_load(ParameterHandler  &prm,
              const Kind         kind,
              const std::string &section) const;
    /// The wheels of subsection `section` (a vehicle), added to `loads`
    /// if its Magnitude is not 0, with their track.
    void
    read_vehicle(ParameterHandler &prm, const std::string &section);
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

    /// b_k(tau) = magnitude * int f(x, y, tau) phi_i (without h).
    void
    assemble_spatial_part(const Load      &load,
                          const double     tau,
                          LA::MPI::Vector &vector) const;
    /// Moving loads and intensities that name tau; the others' b_k is
    /// built once.
    static bool
    is_rebuilt_every_step(const Load &load);
    /// vector += b_k(tau) of a point load, and of a patch load.
    void
    add_point_load(const Load      &load,
                   const double     tau,
                   LA::MPI::Vector &vector) const;
    void
    add_patch(const Load      &load,
              const double     tau,
              LA::MPI::Vector &vector) const;

    /// The points at which the full plate's mesh (this rank's share)
    /// evaluates a pressure on its region or a standing line load.
    static std::vector<Point<2>>
    full_plate_points_on(const Load           &load,
                         const BoundingBox<2> &plate,
                         const Discretization &discretization);

    /// Whether `other` is the image of `load` in the symmetry plane normal
    /// to `axis` (a load on the plane may be its own image), at `times` and
    /// `points`. Collective.
    static bool
    is_mirror_image(const Load                &load,
                    const Load                &other,
                    const unsigned int         axis,
                    const BoundingBox<2>      &plate,
                    const std::vector<double> &times,
                    const Discretization      &discretization);
    /// Throw, naming the expression and the first tau, if the Time history
    /// of `load` or its intensity times Magnitude (at the `points` it acts
    /// on) is not finite at one of `times`. Collective.
    static void
    require_finite_values(const Load                &load,
                          const std::vector<double> &times,
                          const BoundingBox<2>      &plate,
                          const Discretization      &discretization);
    /// The messages of a Time history and of an Intensity that are not
    /// finite at tau, shared by the check before the run and the one at a
    /// step.
    static std::string
    non_finite_history(const Load &load, const double tau);
    static std::string
    non_finite_intensity(const Load &load, const double tau);
    /// The intensities of `load` at the `candidates` against those of
    /// `other` at their mirror images, at `times`. Collective.
    static bool
    have_mirrored_intensities(const Load                  &load,
                              const Load                  &other,
                              const unsigned int           axis,
                              const std::vector<Point<2>> &candidates,
                              const std::vector<double>   &times,
                              const MPI_Comm               comm);
  };
} // namespace liftoff
