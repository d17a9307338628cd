#include <deal.II/base/numbers.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/contact/dowel_bar.h>

#include <cmath>

namespace liftoff
{
  double
  DowelBar::stiffness() const
  {
    const double pi   = numbers::PI;
    const double EI   = modulus * pi * std::pow(diameter, 4) / 64;
    const double beta = std::pow(support_modulus * diameter / (4 * EI), 0.25);
    const double z    = opening;
    const double shear =
      modulus / (2 * (1 + poisson_ratio)) * 0.9 * pi * diameter * diameter / 4;
    const double flexibility = (2 + beta * z) / (2 * std::pow(beta, 3) * EI)
                               + z * (1 + beta * z) / (2 * beta * beta * EI)
                               + std::pow(z, 3) / (12 * EI) + z / shear;
    return 1 / flexibility;
  }


  double
  DowelBar::bearing_stress(const double force) const
  {
    const double EI   = modulus * numbers::PI * std::pow(diameter, 4) / 64;
    const double beta = std::pow(support_modulus * diameter / (4 * EI), 0.25);
    return support_modulus * std::abs(force) * (2 + beta * opening)
           / (4 * std::pow(beta, 3) * EI);
  }


  void
  DowelBar::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Diameter",
                      "0",
                      Patterns::Double(0.0),
                      "The bar's diameter d." + quantity("length"));
    prm.declare_entry("Steel modulus",
                      "0",
                      Patterns::Double(0.0),
                      "The bar's Young's modulus E_d; steel's 200 GPa by "
                      "default in an SI scene."
                        + si_default("200e9") + quantity("pressure"));
    prm.declare_entry("Steel Poisson ratio",
                      "0.3",
                      Patterns::Double(0.0, 0.5),
                      "The bar's Poisson ratio, for its shear modulus."
                        + quantity("number"));
    prm.declare_entry("Modulus of dowel support",
                      "0",
                      Patterns::Double(0.0),
                      "K, the concrete's reaction per unit area of the bar's "
                      "projection per unit deflection of the bar (N/m^3 in "
                      "an SI scene: 0.08e12 to 0.41e12 for concrete, the "
                      "0.3 to 1.5e6 pci of Huang, Pavement analysis and "
                      "design, 2004; by default 407e9, 1.5e6 pci)."
                        + si_default("407e9")
                        + quantity("pressure per length"));
    prm.declare_entry("Joint opening",
                      "0",
                      Patterns::Double(0.0),
                      "z, the width of the open joint the bars span."
                        + quantity("length"));
  }


  void
  DowelBar::parse_parameters(ParameterHandler &prm)
  {
    diameter        = prm.get_double("Diameter");
    modulus         = prm.get_double("Steel modulus");
    poisson_ratio   = prm.get_double("Steel Poisson ratio");
    support_modulus = prm.get_double("Modulus of dowel support");
    opening         = prm.get_double("Joint opening");
  }
} // namespace liftoff
