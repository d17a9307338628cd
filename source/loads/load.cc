#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/loads/load.h>
#include <liftoff/loads/mirror_image.h>

#include <algorithm>
#include <cmath>
#include <typeinfo>

namespace liftoff
{
  Load::Load(const std::string              &name,
             const double                    magnitude,
             LoadHistory                   &&history,
             std::shared_ptr<const LoadPath> path,
             const Point<2>                 &standing_point,
             const Tensor<1, 2>             &offset)
      : load_name(name)
      , magnitude(magnitude)
      , history(std::move(history))
      , load_path(std::move(path))
      , standing_point(standing_point)
      , offset(offset)
  {}


  const std::string &
  Load::name() const
  {
    return load_name;
  }


  bool
  Load::is_on() const
  {
    return magnitude != 0.0;
  }


  bool
  Load::is_permanent() const
  {
    return permanent;
  }


  double
  Load::history_at(const double tau) const
  {
    return history.at(tau);
  }


  void
  Load::keep_heading(const Tensor<1, 2> &direction)
  {
    heading = direction;
  }


  const std::optional<Tensor<1, 2>> &
  Load::kept_heading() const
  {
    return heading;
  }


  const LoadPath *
  Load::path() const
  {
    return load_path.get();
  }


  Point<2>
  Load::position_at(const double tau) const
  {
    if (load_path == nullptr)
      return standing_point + offset;
    return load_path->at(tau) + offset;
  }


  Point<2>
  Load::path_point_at(const double tau) const
  {
    return position_at(tau) - offset;
  }


  void
  Load::require_reducible(const std::string &) const
  {}


  void
  Load::use_plate(const MindlinPlate &)
  {}


  bool
  Load::bends_freely() const
  {
    return false;
  }


  FreeBending
  Load::free_bending_at(const Point<2> &, const double) const
  {
    return {};
  }


  std::optional<BoundingBox<2>>
  Load::region_between(const double, const double) const
  {
    return std::nullopt;
  }


  bool
  Load::mirrors_position(const Load                &other,
                         const unsigned int         axis,
                         const std::vector<double> &times) const
  {
    for (const double tau : times)
      if ((mirror_image::mirrored(position_at(tau), axis)
           - other.position_at(tau))
            .norm()
          >= 1e-12)
        return false;
    return true;
  }


  std::vector<double>
  Load::sample_times(const double tau_begin, const double tau_end) const
  {
    // A path over the interval: its positions at nine times (a path that
    // bends between them is covered up to that sampling).
    const unsigned int  n_samples = load_path && load_path->moves() ? 9 : 1;
    std::vector<double> times;
    for (unsigned int k = 0; k < n_samples; ++k)
      times.push_back(n_samples == 1
                        ? tau_begin
                        : tau_begin
                            + (tau_end - tau_begin) * k / (n_samples - 1));
    return times;
  }


  bool
  Load::area_touches(const PlateGeometry         &geometry,
                     const Point<2>              &centre,
                     const std::array<double, 2> &sides,
                     const bool                   is_disc)
  {
    std::vector<Point<2>> samples;
    for (unsigned int i = 0; i <= 16; ++i)
      for (unsigned int j = 0; j <= 16; ++j)
        {
          const Tensor<1, 2> offset(
            {(i / 16.0 - 0.5) * sides[0], (j / 16.0 - 0.5) * sides[1]});
          if (!is_disc || offset.norm() <= sides[0] / 2)
            samples.push_back(centre + offset);
        }
    return std::any_of(samples.begin(), samples.end(), [&](const Point<2> &x) {
      return geometry.is_on_plate(x);
    });
  }


  bool
  Load::is_rebuilt_every_step() const
  {
    return load_path && load_path->moves();
  }


  void
  Load::setup(const Discretization &discretization)
  {
    discretization.reinit_vector(fixed_part);
    if (!is_rebuilt_every_step())
      add_spatial_part(discretization, 0.0, fixed_part);
  }


  const LA::MPI::Vector &
  Load::spatial_part_at(const Discretization &discretization,
                        const double          tau,
                        LA::MPI::Vector      &scratch) const
  {
    if (!is_rebuilt_every_step())
      return fixed_part;
    if (scratch.size() == 0)
      discretization.reinit_vector(scratch);
    scratch = 0;
    add_spatial_part(discretization, tau, scratch);
    return scratch;
  }


  void
  Load::require_finite(const std::vector<double> &times,
                       const BoundingBox<2>      &plate,
                       const Discretization      &discretization) const
  {
    for (const double tau : times)
      AssertThrow(std::isfinite(history.at(tau)),
                  ExcMessage(non_finite_history(tau)));
    require_finite_intensity(times, plate, discretization);
  }


  void
  Load::require_finite_intensity(const std::vector<double> &,
                                 const BoundingBox<2> &,
                                 const Discretization &) const
  {}


  std::string
  Load::non_finite_history(const double tau) const
  {
    return load_name + "/Time history = <" + history.expression() + "> is "
           + format_exact(history.at(tau)) + " at tau = " + time_text(tau)
           + ".";
  }


  std::string
  Load::non_finite_spatial_part(const double) const
  {
    return load_name + ": Magnitude = " + format_exact(magnitude)
           + " is too large to be represented.";
  }


  bool
  Load::is_mirror_image(const Load                &other,
                        const unsigned int         axis,
                        const BoundingBox<2>      &plate,
                        const std::vector<double> &times,
                        const Discretization      &discretization) const
  {
    // Cheap comparisons first; all of these are the same on every rank.
    if (typeid(*this) != typeid(other)
        || !mirror_image::nearly_equal(magnitude, other.magnitude)
        || !mirrors_geometry(other, axis, plate, times))
      return false;
    for (const double tau : times)
      if (!mirror_image::nearly_equal(history.at(tau), other.history.at(tau)))
        return false;
    return mirrors_intensity(other, axis, plate, times, discretization);
  }


  bool
  Load::mirrors_intensity(const Load &,
                          const unsigned int,
                          const BoundingBox<2> &,
                          const std::vector<double> &,
                          const Discretization &) const
  {
    return true;
  }


  void
  declare_load_entries(ParameterHandler            &prm,
                       const std::string           &section,
                       const std::string           &unit,
                       const std::string           &unit_name,
                       const std::function<void()> &declare_own)
  {
    // Every load has a Magnitude (whose unit depends on its kind) and a
    // Time history.
    prm.enter_subsection(section);
    prm.declare_entry("Magnitude",
                      "0",
                      Patterns::Double(),
                      unit + "; 0 switches the load off."
                        + quantity(unit_name));
    declare_own();
    prm.declare_entry(
      "Time history",
      "1",
      Patterns::Anything(),
      "h(tau), a muParser expression in tau (dimensionless time); the load "
      "is Magnitude * h(tau). Examples: 1 (suddenly applied), tau (linear "
      "ramp), sin(2*pi*tau/2.5) (pulsating), if(tau<0.1,1,0) (pulse)."
        + quantity("number"));
    prm.leave_subsection();
  }


  std::string
  plate_named(const PlateGeometry &geometry)
  {
    return geometry.shape() == PlateShape::rectangle
             ? std::string("the plate [-1/2, 1/2] x [-mu/2, mu/2]")
             : geometry.plate_description();
  }


  std::vector<double>
  numbers_or_refuse(const std::string &text, const std::string &message)
  {
    try
      {
        return Utilities::string_to_double(
          Utilities::split_string_list(text, ','));
      }
    catch (...)
      {
        AssertThrow(false, ExcMessage(message));
      }
    return {};
  }
} // namespace liftoff
