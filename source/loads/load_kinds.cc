#include <liftoff/loads/deflectometer.h>
#include <liftoff/loads/line_load.h>
#include <liftoff/loads/load_kinds.h>
#include <liftoff/loads/patch_load.h>
#include <liftoff/loads/point_load.h>
#include <liftoff/loads/pressure.h>
#include <liftoff/loads/temperature_load.h>
#include <liftoff/loads/vehicle.h>

namespace liftoff
{
  namespace
  {
    // A kind whose subsection is one load, kept if it is on.
    template <typename LoadClass>
    LoadKind
    single_load(const std::string &section)
    {
      return {section,
              &LoadClass::declare_parameters,
              [](ParameterHandler &prm, const std::string &name) {
                std::vector<std::unique_ptr<Load>> loads;
                std::unique_ptr<Load> load = LoadClass::read(prm, name);
                if (load->is_on())
                  loads.push_back(std::move(load));
                return loads;
              },
              false};
    }
  } // namespace


  const std::vector<LoadKind> &
  load_kinds()
  {
    static const std::vector<LoadKind> kinds = {
      single_load<PointLoad>("Point load"),
      single_load<Pressure>("Pressure"),
      single_load<LineLoad>("Line load"),
      single_load<PatchLoad>("Patch load"),
      {"Vehicle", &Vehicle::declare_parameters, &Vehicle::read, true},
      single_load<TemperatureLoad>("Temperature load"),
      single_load<Deflectometer>("Deflectometer")};
    return kinds;
  }
} // namespace liftoff
