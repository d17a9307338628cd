#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/plate_matrices.h>
#include <liftoff/fem/plate_term.h>

namespace liftoff
{
  PlateTerm::PlateTerm(PlateMatrices &matrices, const MindlinPlate &plate)
      : matrices(matrices)
      , plate(plate)
  {}


  void
  PlateTerm::setup(const Discretization &discretization)
  {
    matrices.assemble(discretization, plate);
  }


  void
  PlateTerm::add_to_matrix(const MatrixFactors   &factors,
                           LA::MPI::SparseMatrix &matrix)
  {
    // A static solve's matrix has no mass term: not even 0 M (a pass over
    // the matrix).
    matrix.add(1.0, matrices.stiffness);
    if (factors.mass != 0)
      matrix.add(factors.mass, matrices.mass);
  }


  void
  PlateTerm::add_force(const TermState &state, LA::MPI::Vector &force) const
  {
    matrices.stiffness.vmult(state.scratch, state.u);
    force += state.scratch;
  }


  double
  PlateTerm::energy(const TermState &state) const
  {
    return 0.5
           * matrices.quadratic_form(matrices.stiffness,
                                     state.u,
                                     state.scratch);
  }


  SystemTerm::Stores
  PlateTerm::stores() const
  {
    return Stores::strain;
  }


  double
  PlateTerm::kinetic_energy(const TermState &state) const
  {
    return 0.5 * matrices.quadratic_form(matrices.mass, state.u, state.scratch);
  }
} // namespace liftoff
