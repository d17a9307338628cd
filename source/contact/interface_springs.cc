#include <liftoff/contact/interface_springs.h>
#include <liftoff/fem/plate_fields.h>

namespace liftoff
{
  void
  InterfaceSprings::use_base(const BaseLayer &base)
  {
    if (base.n_layers() == 1)
      return;
    // The bed's law with tensionless springs k_i on the gap g_i alone (no
    // dashpots or layer), read as the bed reads its own so that it is
    // checked alike.
    ParameterHandler springs;
    ContactLaw::declare_parameters(springs);
    springs.enter_subsection("Foundation");
    springs.set("Model", "tensionless");
    springs.set("Stiffness", base.interface_stiffness);
    springs.set("Initial gap", base.interface_gap);
    springs.leave_subsection();
    own_law().parse_parameters(springs, 1.0, "Base/Interface gap");
  }


  std::vector<FoundationPoints::Part>
  InterfaceSprings::measured_fields(const FiniteElement<2> &) const
  {
    return {{PlateFields::w_of(0), 1.0}, {PlateFields::w_of(1), -1.0}};
  }
} // namespace liftoff
