#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/fe_system.h>

#include <liftoff/fem/plate_fields.h>
#include <liftoff/fem/transverse_shear_strain.h>

#include <memory>
#include <string>

namespace liftoff
{
  using namespace dealii;

  /**
   * The finite element of (w, psi_x, psi_y): FESystem(FE_Q(p), 3) or the
   * paper's eight-node FESystem(FE_Serendipity, 3), and how it integrates
   * the transverse shear energy. The entries that choose them and the
   * combinations liftoff refuses live here.
   */
  class PlateElement
  {
  public:
    /// Entries in "Discretization": Polynomial degree, Element, Shear
    /// integration.
    static void
    declare_parameters(ParameterHandler &prm);
    /// The element of `layers` layers (PlateFields), each (w, psi_x,
    /// psi_y).
    void
    parse_parameters(ParameterHandler &prm, const unsigned int layers = 1);

    /// The element the parameters name (after parse_parameters()).
    const FESystem<2> &
    fe() const;
    unsigned int
    degree() const;
    /// "Q<p>" (Lagrange) or "S2" (serendipity), for logs and summaries.
    std::string
    name() const;
    /// How the element integrates the transverse shear energy (`Shear
    /// integration`).
    TransverseShearStrain::Treatment
    shear_integration() const;
    /// Whether the element has the transfer matrices between a cell and its
    /// children that hanging nodes and SolutionTransfer need (FE_Q has,
    /// FE_Serendipity has not).
    bool
    supports_local_refinement() const;

  private:
    unsigned int                     fe_degree = 1;
    TransverseShearStrain::Treatment shear_treatment =
      TransverseShearStrain::Treatment::mitc;
    /// FE_Serendipity (degree 2) instead of FE_Q(fe_degree).
    bool                         is_serendipity = false;
    std::unique_ptr<FESystem<2>> element;
  };
} // namespace liftoff
