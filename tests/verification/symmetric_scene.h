#pragma once

// A scene symmetric about x = 0 and y = 0 that exercises every kind of load
// (point loads off and on the symmetry planes, a pressure varying in space
// and time, line loads on two edges), supported edges, lift-off and a
// history that changes the contact set: the common input of the symmetry
// and MPI tests. `cells` counts cells per unit length, so every model has the
// same element size.

#include <string>

namespace liftoff_tests
{
  inline std::string
  symmetric_scene(const std::string &symmetry,
                  const unsigned int cells_x,
                  const unsigned int cells_y,
                  const unsigned int degree      = 2,
                  const unsigned int refinements = 0)
  {
    return R"(
subsection Plate
  set Aspect ratio = 0.8
  set Thickness ratio = 0.05
  set Poisson ratio = 0.3
end
subsection Foundation
  set Model = tensionless
  set Stiffness = 300
end
subsection Discretization
  set Symmetry = )"
           + symmetry + R"(
  set Cells along x = )"
           + std::to_string(cells_x) + R"(
  set Cells along y = )"
           + std::to_string(cells_y) + R"(
  set Polynomial degree = )"
           + std::to_string(degree) + R"(
  set Global refinements = )"
           + std::to_string(refinements) + R"(
end
subsection Boundary conditions
  set Left = soft simply supported
  set Right = soft simply supported
end
subsection Loads
  subsection Point load 1
    set Magnitude = 1
    set Position = 0, 0
    set Time history = 20*tau
  end
  subsection Point load 2
    set Magnitude = 0.5
    set Position = 0.2, 0.15
  end
  subsection Point load 3
    set Magnitude = 0.5
    set Position = -0.2, 0.15
  end
  subsection Point load 4
    set Magnitude = 0.5
    set Position = 0.2, -0.15
  end
  subsection Point load 5
    set Magnitude = 0.5
    set Position = -0.2, -0.15
  end
  subsection Point load 6
    set Magnitude = -0.3
    set Position = 0, 0.3
  end
  subsection Point load 7
    set Magnitude = -0.3
    set Position = 0, -0.3
  end
  subsection Pressure 1
    set Magnitude = 2
    set Region = -0.25, 0.25, -0.1, 0.1
    set Intensity = 1 + 4*x*x + cos(20*tau)*y*y
    set Time history = if(tau < 0.02, 1, 0.5)
  end
  subsection Line load 1
    set Magnitude = -0.2
    set Edge = Top
    set Intensity = 1 - x*x
  end
  subsection Line load 2
    set Magnitude = -0.2
    set Edge = Bottom
    set Intensity = 1 - x*x
  end
end
subsection Time integration
  set Time step = 2e-3
  set End time = 0.06
end
subsection Output
  set Probe points = 0, 0; 0.3, 0.2; -0.3, 0.2; 0.3, -0.2; -0.3, -0.2; 0.5, 0.4; 0, 0.4; 0.45, 0
end
)";
  }
} // namespace liftoff_tests
