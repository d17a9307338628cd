#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/loads/free_bending.h>
#include <liftoff/loads/load_history.h>
#include <liftoff/loads/load_path.h>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * One load of a scene: Magnitude * h(tau) * b(tau), b the integral of its
   * distribution against the shape functions. A kind of load (PointLoad,
   * Pressure, LineLoad, PatchLoad; a Vehicle's wheels are point or patch
   * loads) says where it acts, checks itself against the plate, builds
   * b(tau) and knows its mirror image; LoadSet keeps the list, the tracks
   * of the moving loads, and adds the loads up.
   *
   * Whatever does not change in time is built once (setup()): only a load
   * that moves, or whose intensity names tau, builds b(tau) at every step.
   */
  class Load
  {
  public:
    virtual ~Load() = default;

    /// E.g. "Loads/Point load 2", for messages.
    const std::string &
    name() const;
    /// Whether it is switched on (Magnitude is not 0).
    bool
    is_on() const;
    /// Acts from before tau = 0 with h = 1 (the self-weight).
    bool
    is_permanent() const;
    double
    history_at(const double tau) const;

    /// Its path (shared by a vehicle's wheels), or nullptr: it stands.
    const LoadPath *
    path() const;
    /// Where it is at tau: a point load, a patch's centre, the shift of a
    /// line's Segment (a wheel: its path's point plus its offset).
    Point<2>
    position_at(const double tau) const;
    /// The point of its path at tau (a wheel's position less its offset).
    Point<2>
    path_point_at(const double tau) const;

    /// A wheel of a vehicle's axles faces the direction its path heads at
    /// tau = 0, `heading`: its offset is turned to it, and the path must
    /// keep it (LoadSet refuses one that turns).
    void
    keep_heading(const Tensor<1, 2> &heading);
    /// That direction; none for a load whose offset is in the plate's axes.
    const std::optional<Tensor<1, 2>> &
    kept_heading() const;

    /// Whether some of it acts on the plate at tau: exactly on the
    /// rectangle; on other shapes a load is on the plate if one of 17 x
    /// 17 points over its area (65 along a line) is.
    virtual bool
    touches(const PlateGeometry &geometry, const double tau) const = 0;
    /// Refuse a load without a path that is not (wholly) on the plate; a
    /// path is checked by LoadSet, once for the loads that share it.
    virtual void
    require_on_plate(const PlateGeometry &geometry) const = 0;
    /// Refuse what the symmetry check cannot compare on a `symmetry`
    /// ("half", "quarter") model.
    virtual void
    require_reducible(const std::string &symmetry) const;
    /// The box it covers from tau_begin to tau_end (a moving load: at nine
    /// times), which mesh refinement keeps fine; none for what covers whole
    /// stretches of the plate (pressures, lines along edges).
    virtual std::optional<BoundingBox<2>>
    region_between(const double tau_begin, const double tau_end) const;

    /// Build b once if it does not change in time.
    void
    setup(const Discretization &discretization);
    /// b(tau) (without Magnitude's h): the one built by setup(), or built
    /// in `scratch` (sized here if empty) and returned.
    const LA::MPI::Vector &
    spatial_part_at(const Discretization &discretization,
                    const double          tau,
                    LA::MPI::Vector      &scratch) const;

    /// Throw, naming the expression and the first tau, if the Time history
    /// or (Pressure, LineLoad) the intensity times Magnitude at the points
    /// of the full plate it acts on is not finite at one of `times`.
    /// Collective.
    void
    require_finite(const std::vector<double> &times,
                   const BoundingBox<2>      &plate,
                   const Discretization      &discretization) const;
    /// The messages of a Time history and of a b(tau) that are not finite
    /// at tau, shared by the check before the run and the one at a step.
    std::string
    non_finite_history(const double tau) const;
    virtual std::string
    non_finite_spatial_part(const double tau) const;

    /// Whether `other` is its image in the symmetry plane normal to `axis`
    /// (a load on the plane may be its own image), at `times` and at the
    /// points of the full plate's mesh. Collective.
    bool
    is_mirror_image(const Load                &other,
                    const unsigned int         axis,
                    const BoundingBox<2>      &plate,
                    const std::vector<double> &times,
                    const Discretization      &discretization) const;

    /// The plate's section, for a kind that needs it (a temperature's
    /// moment needs nu and H); the others ignore it.
    virtual void
    use_plate(const MindlinPlate &plate);
    /// Whether it bends the plate freely (a temperature) ...
    virtual bool
    bends_freely() const;
    /// ... and how at x at tau, h(tau) excluded (none by default).
    virtual FreeBending
    free_bending_at(const Point<2> &x, const double tau) const;

  protected:
    Load(const std::string              &name,
         const double                    magnitude,
         LoadHistory                   &&history,
         std::shared_ptr<const LoadPath> path,
         const Point<2>                 &standing_point = Point<2>(),
         const Tensor<1, 2>             &offset         = Tensor<1, 2>());

    /// Moving loads and intensities that name tau; the others' b is built
    /// once.
    virtual bool
    is_rebuilt_every_step() const;
    /// vector += b(tau).
    virtual void
    add_spatial_part(const Discretization &discretization,
                     const double          tau,
                     LA::MPI::Vector      &vector) const = 0;
    /// The parts of is_mirror_image() after the kind and the Magnitude:
    /// where it acts (`other` is of the same class) ...
    virtual bool
    mirrors_geometry(const Load                &other,
                     const unsigned int         axis,
                     const BoundingBox<2>      &plate,
                     const std::vector<double> &times) const = 0;
    /// ... and after the Time history, its intensity (default: none).
    virtual bool
    mirrors_intensity(const Load                &other,
                      const unsigned int         axis,
                      const BoundingBox<2>      &plate,
                      const std::vector<double> &times,
                      const Discretization      &discretization) const;
    /// The part of require_finite() after the Time history (default:
    /// nothing to check).
    virtual void
    require_finite_intensity(const std::vector<double> &times,
                             const BoundingBox<2>      &plate,
                             const Discretization      &discretization) const;

    /// Whether `other` stands at the mirror image of its position at each
    /// of `times` (a moving load's image follows the mirrored path).
    bool
    mirrors_position(const Load                &other,
                     const unsigned int         axis,
                     const std::vector<double> &times) const;
    /// The times at which region_between() samples the position.
    std::vector<double>
    sample_times(const double tau_begin, const double tau_end) const;
    /// Whether one of 17 x 17 points over the rectangle of `sides` (or the
    /// disc of diameter sides[0]) about `centre` is on the plate.
    static bool
    area_touches(const PlateGeometry         &geometry,
                 const Point<2>              &centre,
                 const std::array<double, 2> &sides,
                 const bool                   is_disc);

    std::string load_name;
    double      magnitude;
    LoadHistory history;
    bool        permanent = false;

  private:
    std::shared_ptr<const LoadPath> load_path;
    /// A point load's Position when it stands.
    Point<2> standing_point;
    /// A wheel's from its vehicle's path.
    Tensor<1, 2> offset;
    /// keep_heading().
    std::optional<Tensor<1, 2>> heading;
    LA::MPI::Vector             fixed_part;
  };

  /// Subsection `section` of a load: Magnitude (`unit`, its quantity
  /// `unit_name`), the entries `declare_own` adds, and Time history.
  void
  declare_load_entries(ParameterHandler            &prm,
                       const std::string           &section,
                       const std::string           &unit,
                       const std::string           &unit_name,
                       const std::function<void()> &declare_own);

  /// The plate as messages about loads off it name it.
  std::string
  plate_named(const PlateGeometry &geometry);

  /// The comma-separated numbers of `text`, or refused with `message`.
  std::vector<double>
  numbers_or_refuse(const std::string &text, const std::string &message);
} // namespace liftoff
