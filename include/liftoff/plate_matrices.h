#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/discretization.h>
#include <liftoff/linear_algebra.h>
#include <liftoff/mindlin_plate.h>
#include <liftoff/transverse_shear_strain.h>

namespace liftoff
{
  using namespace dealii;

  /**
   * The parts of eq. (2.6) that do not depend on contact: the plate
   * stiffness K (bending, twisting, transverse shear) and the consistent
   * mass M (translational and rotary inertia). Assembled once per mesh.
   */
  class PlateMatrices
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    void
    assemble(const Discretization &discretization, const MindlinPlate &plate);

    /// Solve M x = b (conjugate gradients with Jacobi: the consistent mass
    /// matrix is well conditioned on any mesh, so no factorisation is
    /// needed for the initial acceleration).
    void
    solve_with_mass(LA::MPI::Vector &x, const LA::MPI::Vector &b) const;

    TransverseShearStrain::Treatment shear_integration =
      TransverseShearStrain::Treatment::mitc;

    LA::MPI::SparseMatrix stiffness;
    LA::MPI::SparseMatrix mass;
  };
} // namespace liftoff
