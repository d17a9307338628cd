#include <deal.II/fe/fe_q.h>

#include <liftoff/base/selection.h>
#include <liftoff/fem/fe_serendipity.h>
#include <liftoff/fem/plate_element.h>

namespace liftoff
{
  namespace
  {
    using Treatment = TransverseShearStrain::Treatment;
    // true: FE_Serendipity.
    const Selection<bool>      elements   = {{"lagrange", false},
                                             {"serendipity", true}};
    const Selection<Treatment> treatments = {{"full", Treatment::full},
                                             {"reduced", Treatment::reduced},
                                             {"mitc", Treatment::mitc}};
  } // namespace


  void
  PlateElement::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    prm.declare_entry("Polynomial degree",
                      "1",
                      Patterns::Integer(1, 6),
                      "Degree p of FE_Q(p) used for w, psi_x and psi_y "
                      "(2 with Element = serendipity).");
    prm.declare_entry(
      "Element",
      "lagrange",
      elements.pattern(),
      "Finite element for w, psi_x and psi_y: lagrange, FE_Q(p) with "
      "(p+1)^2 nodes per cell (p = 2: the nine-node element); serendipity, "
      "the paper's eight-node quadrilateral (vertices and edge mid-points, "
      "no centre node), only with Polynomial degree = 2 and Shear "
      "integration = full or reduced (doc/model.md).");
    prm.declare_entry("Shear integration",
                      "mitc",
                      treatments.pattern(),
                      "Treatment of the transverse shear term: full, "
                      "(p+1)^2 Gauss points, locks as the plate gets thin; "
                      "reduced, p^2 points, gives free plates spurious "
                      "zero-energy modes; mitc, assumed natural shear "
                      "strains (MITC4 for p = 1, MITC9 for p = 2), neither "
                      "locks nor has spurious modes (doc/thin-plates.md).");
    prm.leave_subsection();
  }


  void
  PlateElement::parse_parameters(ParameterHandler  &prm,
                                 const unsigned int layers)
  {
    const unsigned int n_components = PlateFields::n_components_of(layers);
    prm.enter_subsection("Discretization");
    fe_degree       = prm.get_integer("Polynomial degree");
    shear_treatment = treatments.parse(prm.get("Shear integration"),
                                       "Discretization/Shear integration");
    is_serendipity =
      elements.parse(prm.get("Element"), "Discretization/Element");
    prm.leave_subsection();
    if (!is_serendipity)
      {
        element =
          std::make_unique<FESystem<2>>(FE_Q<2>(fe_degree), n_components);
        return;
      }
    AssertThrow(fe_degree == 2,
                ExcMessage("Discretization/Element = serendipity is the "
                           "eight-node element of degree 2: it needs "
                           "Discretization/Polynomial degree = 2, not "
                           + std::to_string(fe_degree) + "."));
    // The assumed strains of Shear integration = mitc are tied at the
    // points of the nine-node element's strain space; the eight-node
    // element would need its own scheme (MITC8), which liftoff lacks.
    AssertThrow(shear_treatment != TransverseShearStrain::Treatment::mitc,
                ExcMessage("Discretization/Element = serendipity works "
                           "with Discretization/Shear integration = full "
                           "or reduced, not mitc (its tying points "
                           "belong to the nine-node Lagrange element)."));
    element = std::make_unique<FESystem<2>>(FE_Serendipity(), n_components);
  }


  const FESystem<2> &
  PlateElement::fe() const
  {
    Assert(element, ExcMessage("PlateElement::fe() before parse_parameters()"));
    return *element;
  }


  unsigned int
  PlateElement::degree() const
  {
    return fe_degree;
  }


  std::string
  PlateElement::name() const
  {
    return is_serendipity ? "S2" : "Q" + std::to_string(fe_degree);
  }


  TransverseShearStrain::Treatment
  PlateElement::shear_integration() const
  {
    return shear_treatment;
  }


  bool
  PlateElement::supports_local_refinement() const
  {
    return !is_serendipity;
  }
} // namespace liftoff
