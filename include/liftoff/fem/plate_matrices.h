#pragma once

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>

#include <functional>

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
    void
    assemble(const Discretization &discretization, const MindlinPlate &plate);

    /// x^T A x for A = stiffness or mass and x a state vector (constraints
    /// distributed): twice the strain or kinetic energy, also on a mesh
    /// with hanging nodes. `product` is scratch of x's layout.
    double
    quadratic_form(const LA::MPI::SparseMatrix &A,
                   const LA::MPI::Vector       &x,
                   LA::MPI::Vector             &product) const;

    /// Solve M x = b (conjugate gradients with Jacobi: the consistent mass
    /// matrix is well conditioned on any mesh, so no factorisation is
    /// needed for the initial acceleration).
    void
    solve_with_mass(LA::MPI::Vector &x, const LA::MPI::Vector &b) const;

    /// An estimate from below of the largest eigenvalue of M^-1 (K + A),
    /// omega_max^2, by power iteration with the Rayleigh quotient, where
    /// `add_extra(x, y)` adds A x to y (the foundation); constrained
    /// entries are kept at zero. Each iteration costs one mass solve.
    double
    largest_eigenvalue(
      const Discretization &discretization,
      const std::function<void(const LA::MPI::Vector &, LA::MPI::Vector &)>
        &add_extra) const;

    LA::MPI::SparseMatrix stiffness;
    LA::MPI::SparseMatrix mass;

  private:
    const Discretization *discretization = nullptr;
  };
} // namespace liftoff
