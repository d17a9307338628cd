#pragma once

#include <liftoff/fem/system_term.h>

namespace liftoff
{
  class MindlinPlate;
  class PlateMatrices;

  /**
   * The plate as the first term of its system: its stiffness K and, in a
   * time step, the mass term mass_factor M (PlateMatrices, assembled on
   * each mesh), its force K u and its strain energy 1/2 u.K u. The kinetic
   * energy 1/2 v.M v is its; the mass solves stay with PlateMatrices.
   */
  class PlateTerm : public SystemTerm
  {
  public:
    PlateTerm(PlateMatrices &matrices, const MindlinPlate &plate);

    void
    setup(const Discretization &discretization) override;
    void
    add_to_matrix(const MatrixFactors   &factors,
                  LA::MPI::SparseMatrix &matrix) override;
    void
    add_force(const TermState &state, LA::MPI::Vector &force) const override;
    double
    energy(const TermState &state) const override;
    Stores
    stores() const override;
    std::string
    energy_column() const override
    {
      return "strain";
    }
    /// 1/2 v.M v, v = state.u.
    double
    kinetic_energy(const TermState &state) const override;

  private:
    PlateMatrices      &matrices;
    const MindlinPlate &plate;
  };
} // namespace liftoff
