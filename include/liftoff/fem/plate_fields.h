#pragma once

#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <array>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The plate's fields in the components of its finite element: per layer
   * the deflection w and the rotations psi_x, psi_y, the slab's first and,
   * under a base that the slab can lift off (BaseLayer, tensionless), the
   * base's next; and which of them rests on the bed (the lowest layer's
   * w). The one place that knows the component numbers (in the spirit of
   * ASPECT's Introspection): every extractor, mask and component test
   * elsewhere asks it. The number of layers is the element's
   * (n_layers(fe)), so nothing else has to carry it.
   */
  struct PlateFields
  {
    /// The slab's components, in the element's order; a layer's are these
    /// shifted by `per_layer` times its number (0: the slab, 1: the base).
    static constexpr unsigned int w         = 0;
    static constexpr unsigned int psi_x     = 1;
    static constexpr unsigned int psi_y     = 2;
    static constexpr unsigned int per_layer = 3;
    /// The slab's components alone: the fields every load and output of
    /// the slab reads.
    static constexpr unsigned int n_components = per_layer;

    /// The components of an element of `layers` layers.
    static constexpr unsigned int
    n_components_of(const unsigned int layers)
    {
      return per_layer * layers;
    }
    /// The layers of `fe` (1 or 2).
    static unsigned int
    n_layers(const FiniteElement<2> &fe)
    {
      return fe.n_components() / per_layer;
    }

    /// The deflection of layer `layer`.
    static constexpr unsigned int
    w_of(const unsigned int layer)
    {
      return per_layer * layer + w;
    }
    /// The rotation psi_x (axis 0) or psi_y (axis 1) of `layer`: the
    /// rotation whose jump across a joint normal to `axis` is psi . n.
    static constexpr unsigned int
    rotation(const unsigned int axis, const unsigned int layer = 0)
    {
      return per_layer * layer + psi_x + axis;
    }
    /// The deflection the bed's springs act on: the lowest layer's.
    static unsigned int
    bed_component(const FiniteElement<2> &fe)
    {
      return bed_component(fe.n_components());
    }
    /// The same, of an element of `n_components` components.
    static unsigned int
    bed_component(const unsigned int n_components)
    {
      return w_of(n_components / per_layer - 1);
    }

    static FEValuesExtractors::Scalar
    w_extractor(const unsigned int layer = 0)
    {
      return FEValuesExtractors::Scalar(w_of(layer));
    }
    static FEValuesExtractors::Scalar
    rotation_extractor(const unsigned int axis, const unsigned int layer = 0)
    {
      return FEValuesExtractors::Scalar(rotation(axis, layer));
    }

    /// The extractors of one layer's fields.
    struct Extractors
    {
      FEValuesExtractors::Scalar w, psi_x, psi_y;
    };
    static Extractors
    extractors(const unsigned int layer)
    {
      return {w_extractor(layer),
              rotation_extractor(0, layer),
              rotation_extractor(1, layer)};
    }

    /// The mask of the fields named true (w, psi_x, psi_y) in the layers
    /// from `first_layer` on of an element of `layers` layers: a support or
    /// a symmetry plane holds both layers, a symmetry plane that is a
    /// slab's joint the base's alone.
    static ComponentMask
    mask(const bool         of_w,
         const bool         of_psi_x,
         const bool         of_psi_y,
         const unsigned int layers      = 1,
         const unsigned int first_layer = 0)
    {
      std::vector<bool> selected(n_components_of(layers), false);
      for (unsigned int layer = first_layer; layer < layers; ++layer)
        {
          selected[w_of(layer)]        = of_w;
          selected[rotation(0, layer)] = of_psi_x;
          selected[rotation(1, layer)] = of_psi_y;
        }
      return ComponentMask(selected);
    }
    /// The fields' names in the element's order, as the field files and
    /// their readers know them (the base's end in "_base"); `suffix` makes
    /// the names of a rate ("_dot").
    static std::vector<std::string>
    names(const unsigned int layers, const std::string &suffix = "")
    {
      std::vector<std::string> all;
      for (unsigned int layer = 0; layer < layers; ++layer)
        for (const char *field : {"w", "psi_x", "psi_y"})
          all.push_back(field + std::string(layer == 0 ? "" : "_base")
                        + suffix);
      return all;
    }

    /// The mask of one component of the element `fe`.
    static ComponentMask
    component_mask(const FiniteElement<2> &fe, const unsigned int component)
    {
      std::vector<bool> selected(fe.n_components(), false);
      selected[component] = true;
      return ComponentMask(selected);
    }
    /// The mask of the slab's w alone, in the element `fe`.
    static ComponentMask
    w_mask(const FiniteElement<2> &fe)
    {
      std::vector<bool> selected(fe.n_components(), false);
      selected[w] = true;
      return ComponentMask(selected);
    }
  };
} // namespace liftoff
