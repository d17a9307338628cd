#include <liftoff/base/scene_input.h>
#include <liftoff/loads/distributed_load.h>
#include <liftoff/loads/mirror_image.h>

#include <cmath>

namespace liftoff
{
  Intensity::Intensity(const std::string &expression,
                       const std::string &parameter)
      : text(expression)
      , function(parse_expression<2>(parameter, expression, 1, "x,y,tau", true))
      , names_tau_(names_tau(expression))
  {}


  double
  Intensity::at(const Point<2> &p, const double tau) const
  {
    function->set_time(tau);
    return function->value(p);
  }


  bool
  Intensity::depends_on_time() const
  {
    return names_tau_;
  }


  const std::string &
  Intensity::expression() const
  {
    return text;
  }


  DistributedLoad::DistributedLoad(const std::string              &name,
                                   const double                    magnitude,
                                   LoadHistory                   &&history,
                                   std::shared_ptr<const LoadPath> path,
                                   Intensity                     &&intensity)
      : Load(name, magnitude, std::move(history), std::move(path))
      , intensity(std::move(intensity))
  {}


  bool
  DistributedLoad::is_rebuilt_every_step() const
  {
    return intensity.depends_on_time() || Load::is_rebuilt_every_step();
  }


  void
  DistributedLoad::add_spatial_part(const Discretization &discretization,
                                    const double          tau,
                                    LA::MPI::Vector      &vector) const
  {
    const auto density = [&](const Point<2> &x) {
      return std::array<double, 3>{
        {magnitude * intensity.at(x, tau) * density_factor(discretization, x),
         0.0,
         0.0}};
    };
    integrate(PatchIntegrator(discretization),
              density,
              discretization.geometry().plate_box(),
              tau,
              vector);
  }


  double
  DistributedLoad::density_factor(const Discretization &,
                                  const Point<2> &) const
  {
    return 1.0;
  }


  const Intensity &
  DistributedLoad::intensity_function() const
  {
    return intensity;
  }


  std::string
  DistributedLoad::non_finite_spatial_part(const double tau) const
  {
    return load_name + "/Intensity = <" + intensity.expression()
           + "> times Magnitude is not a finite number at some quadrature "
             "point at tau = "
           + time_text(tau) + ".";
  }


  std::vector<Point<2>>
  DistributedLoad::full_plate_points(const BoundingBox<2> &plate,
                                     const Discretization &disc) const
  {
    // The full plate's mesh is the meshed part and its mirror images, and
    // the points of a region (or a line) on a mirrored cell are the images
    // of those of the mirrored region on the meshed cell.
    const PatchIntegrator           integrator(disc);
    const std::vector<unsigned int> axes = disc.geometry().symmetry_axes();
    std::vector<Point<2>>           points;
    for (unsigned int planes = 0; planes < (1u << axes.size()); ++planes)
      {
        const std::function<Point<2>(const Point<2> &)> image =
          [&](const Point<2> &p) {
            Point<2> q = p;
            for (unsigned int k = 0; k < axes.size(); ++k)
              if (planes & (1u << k))
                q = mirror_image::mirrored(q, axes[k]);
            return q;
          };
        for (const auto &p :
             quadrature_points_of_image(integrator, image, plate))
          points.push_back(image(p));
      }
    return points;
  }


  bool
  DistributedLoad::mirrors_intensity(const Load                &other_load,
                                     const unsigned int         axis,
                                     const BoundingBox<2>      &plate,
                                     const std::vector<double> &times,
                                     const Discretization      &disc) const
  {
    // Intensities at every quadrature point the load covers, at every step
    // time if either names tau (otherwise once).
    const auto &other = static_cast<const DistributedLoad &>(other_load);
    const bool  time_dependent =
      intensity.depends_on_time() || other.intensity.depends_on_time();
    const auto   n_times  = time_dependent ? times.size() : 1;
    unsigned int is_image = 1;
    for (const auto &p : full_plate_points(plate, disc))
      for (unsigned int k = 0; k < n_times && is_image; ++k)
        is_image = mirror_image::nearly_equal(
          intensity.at(p, times[k]),
          other.intensity.at(mirror_image::mirrored(p, axis), times[k]));
    return Utilities::MPI::min(is_image, disc.mpi_communicator) == 1;
  }


  void
  DistributedLoad::require_finite_intensity(const std::vector<double> &times,
                                            const BoundingBox<2>      &plate,
                                            const Discretization &disc) const
  {
    const auto   n_times = intensity.depends_on_time() ? times.size() : 1;
    unsigned int first_bad_time = n_times;
    for (const auto &p : full_plate_points(plate, disc))
      for (unsigned int k = 0; k < first_bad_time; ++k)
        if (!std::isfinite(magnitude * intensity.at(p, times[k])))
          first_bad_time = k;
    first_bad_time = Utilities::MPI::min(first_bad_time, disc.mpi_communicator);
    AssertThrow(first_bad_time == n_times,
                ExcMessage(non_finite_spatial_part(times[first_bad_time])));
  }
} // namespace liftoff
