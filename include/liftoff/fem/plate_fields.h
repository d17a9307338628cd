#pragma once

#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <array>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The plate's fields in the components of its finite element: the
   * deflection w and the rotations psi_x, psi_y, and which of them rests
   * on the bed. The one place that knows the component numbers (in the
   * spirit of ASPECT's Introspection): every extractor, mask and component
   * test elsewhere asks it, so that a second layer's fields change this
   * file, not the classes that read them.
   */
  struct PlateFields
  {
    /// The components, in the element's order.
    static constexpr unsigned int w            = 0;
    static constexpr unsigned int psi_x        = 1;
    static constexpr unsigned int psi_y        = 2;
    static constexpr unsigned int n_components = 3;
    /// The deflection the bed's springs act on.
    static constexpr unsigned int bed_component = w;

    /// The rotation psi_x (axis 0) or psi_y (axis 1): the rotation whose
    /// jump across a joint normal to `axis` is psi . n.
    static constexpr unsigned int
    rotation(const unsigned int axis)
    {
      return psi_x + axis;
    }

    static FEValuesExtractors::Scalar
    w_extractor()
    {
      return FEValuesExtractors::Scalar(w);
    }
    static FEValuesExtractors::Scalar
    rotation_extractor(const unsigned int axis)
    {
      return FEValuesExtractors::Scalar(rotation(axis));
    }

    /// The mask of the fields named true: w, psi_x, psi_y.
    static ComponentMask
    mask(const bool of_w, const bool of_psi_x, const bool of_psi_y)
    {
      std::vector<bool> selected(n_components, false);
      selected[w]     = of_w;
      selected[psi_x] = of_psi_x;
      selected[psi_y] = of_psi_y;
      return ComponentMask(selected);
    }
    /// The fields' names in the element's order, as the field files and
    /// their readers know them; `suffix` makes the names of a rate
    /// ("_dot").
    static std::vector<std::string>
    names(const std::string &suffix = "")
    {
      return {"w" + suffix, "psi_x" + suffix, "psi_y" + suffix};
    }

    /// The mask of w alone.
    static ComponentMask
    w_mask()
    {
      return mask(true, false, false);
    }
  };
} // namespace liftoff
