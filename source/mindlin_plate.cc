#include <liftoff/mindlin_plate.h>

namespace liftoff
{
  void
  MindlinPlate::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Plate");
    prm.declare_entry("Aspect ratio",
                      "1",
                      Patterns::Double(0.0),
                      "mu: width of the plate (along y) over its length L "
                      "(along x). Lengths are measured in units of L, so "
                      "the plate is [-1/2,1/2] x [-mu/2,mu/2].");
    prm.declare_entry("Thickness ratio",
                      "0.05",
                      Patterns::Double(0.0),
                      "Delta = H / L, H the plate thickness.");
    prm.declare_entry("Poisson ratio",
                      "0.1",
                      Patterns::Double(-1.0, 0.5),
                      "nu, in (-1, 0.5).");
    prm.declare_entry("Shear correction factor",
                      "0.8333333333333333",
                      Patterns::Double(0.0),
                      "chi of Mindlin's theory; 5/6 by default.");
    prm.leave_subsection();
  }


  void
  MindlinPlate::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Plate");
    aspect_ratio     = prm.get_double("Aspect ratio");
    thickness_ratio  = prm.get_double("Thickness ratio");
    poisson_ratio    = prm.get_double("Poisson ratio");
    shear_correction = prm.get_double("Shear correction factor");
    prm.leave_subsection();

    // Patterns::Double admits the closed interval; the model needs it open.
    AssertThrow(aspect_ratio > 0,
                ExcMessage("Plate/Aspect ratio must be > 0."));
    AssertThrow(thickness_ratio > 0,
                ExcMessage("Plate/Thickness ratio (Delta) must be > 0."));
    AssertThrow(poisson_ratio > -1.0 && poisson_ratio < 0.5,
                ExcMessage("Plate/Poisson ratio must lie in (-1, 0.5)."));
    AssertThrow(shear_correction > 0,
                ExcMessage("Plate/Shear correction factor must be > 0."));
  }


  double
  MindlinPlate::shear_stiffness() const
  {
    return 6.0 * shear_correction * (1.0 - poisson_ratio)
           / (thickness_ratio * thickness_ratio);
  }


  double
  MindlinPlate::rotary_inertia() const
  {
    return thickness_ratio * thickness_ratio / 12.0;
  }


  double
  MindlinPlate::twisting_stiffness() const
  {
    return 0.5 * (1.0 - poisson_ratio);
  }
} // namespace liftoff
