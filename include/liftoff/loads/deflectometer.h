#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <liftoff/loads/load.h>

#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * A falling-weight deflectometer test: a pulse of force on a circular
   * loading plate, and the sensors (geophones) at offsets from its centre
   * along one direction. The pulse is a disc PatchLoad of the pressure
   * Peak force / (pi a^2) with the pulse's time history; the sensors are
   * read by the output DeflectometerSensors from the same subsection.
   */
  class Deflectometer
  {
  public:
    enum class Pulse
    {
      half_sine,
      haversine,
      constant
    };

    static void
    declare_parameters(ParameterHandler &prm, const std::string &section);
    /// The pulse as a load (Loads/`section` is the current subsection).
    static std::unique_ptr<Load>
    read(ParameterHandler &prm, const std::string &section);
    /// The test of the current subsection Loads/`section`; refuses a bad
    /// entry naming it.
    static Deflectometer
    parse(ParameterHandler &prm, const std::string &section);

    /// Peak force is not 0.
    bool
    is_on() const;
    /// h(tau) of the pulse as a muParser expression.
    std::string
    history_expression() const;
    /// The sensors' points for offsets (along Sensor direction, from the
    /// loading plate's centre); an empty list: the entry's.
    std::vector<Point<2>>
    sensor_points(const std::vector<double> &offsets) const;

    /// E.g. "Loads/Deflectometer 1".
    std::string name;
    double      radius     = 0.15;
    Pulse       pulse      = Pulse::half_sine;
    double      duration   = 1;
    double      peak_force = 0;
    Point<2>    centre;
    /// Sensor offsets as given (empty: the SHRP set of an SI scene).
    std::vector<double> offsets;
    Tensor<1, 2>        direction;
  };
} // namespace liftoff
