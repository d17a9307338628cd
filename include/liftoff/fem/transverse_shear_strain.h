#pragma once

#include <deal.II/base/table.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <memory>

namespace liftoff
{
  using namespace dealii;

  /**
   * The transverse shear strains gamma = grad w - psi of the shape functions
   * of FESystem(FE_Q(p), 3), at the points where the shear energy is
   * integrated, in one of three treatments:
   *
   * - full: gamma itself, integrated with (p+1)^2 Gauss points. Locks as
   *   the plate gets thin: the discrete Kirchhoff constraint gamma = 0 is
   *   imposed at too many points.
   * - reduced: gamma at p^2 Gauss points. Unlocks, but free plates get
   *   zero-energy modes beyond the three rigid ones.
   * - mitc: assumed natural strains of the MITC family (MITC4 for p = 1,
   *   MITC9 for p = 2, the same construction for higher p). The covariant
   *   component gamma_xi is sampled at p Gauss abscissae in xi times p+1
   *   Gauss-Lobatto abscissae in eta (the eta-component the other way
   *   round) and interpolated in between, then integrated with (p+1)^2
   *   points. The space Q(p-1,p) x Q(p,p-1) holds the gradient of every
   *   deflection of Q(p), so the Kirchhoff limit grad w = psi can be met
   *   without locking; the samples on the edges make the tangential strain
   *   continuous between cells, which keeps spurious modes out.
   */
  class TransverseShearStrain
  {
  public:
    enum class Treatment
    {
      full,
      reduced,
      mitc
    };

    TransverseShearStrain(const Mapping<2>       &mapping,
                          const FiniteElement<2> &fe,
                          const Treatment         treatment);
    /// The same strains at the points `points` of the reference cell
    /// instead of the integration points: for mitc the assumed strain
    /// interpolated from the same tying points, at any point (the field
    /// output's points).
    TransverseShearStrain(const Mapping<2>       &mapping,
                          const FiniteElement<2> &fe,
                          const Treatment         treatment,
                          const Quadrature<2>    &points);

    /// The strains of layer `layer`'s fields (PlateFields; 0, the slab,
    /// until set) at the next reinit().
    void
    set_layer(const unsigned int layer);
    void
    reinit(const DoFHandler<2>::active_cell_iterator &cell);

    unsigned int
    n_points() const;
    /// Integration weight (times the Jacobian determinant) of point q.
    double
    JxW(const unsigned int q) const;
    /// Cartesian shear strain of shape function i at point q.
    const Tensor<1, 2> &
    strain(const unsigned int i, const unsigned int q) const;

  private:
    const Treatment treatment;
    unsigned int    layer = 0;
    FEValues<2>     integration_values;
    /// For mitc: values at the tying points of the xi- and eta-components,
    /// and the interpolation weights from tying points to integration
    /// points (rows: integration points, columns: tying points).
    std::array<std::unique_ptr<FEValues<2>>, 2> tying_values;
    std::array<FullMatrix<double>, 2>           interpolation;
    Table<2, Tensor<1, 2>>                      strains;

    Tensor<1, 2>
    cartesian_strain(const FEValues<2> &values,
                     const unsigned int i,
                     const unsigned int q) const;
  };
} // namespace liftoff
