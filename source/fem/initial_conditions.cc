#include <deal.II/base/utilities.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/fem/initial_conditions.h>
#include <liftoff/fem/plate_fields.h>

#include <cstdlib>

namespace liftoff
{
  namespace
  {
    /// The slab's (w, psi_x, psi_y) of a Function given for them, in each
    /// of `layers` layers: a base of its own starts where the slab does, in
    /// contact with it.
    class InEveryLayer : public Function<2>
    {
    public:
      InEveryLayer(const Function<2> &slab, const unsigned int layers)
          : Function<2>(PlateFields::n_components_of(layers))
          , slab(slab)
      {}

      void
      vector_value(const Point<2> &p, Vector<double> &out) const override
      {
        Vector<double> values(PlateFields::n_components);
        slab.vector_value(p, values);
        for (unsigned int c = 0; c < out.size(); ++c)
          out[c] = values[c % PlateFields::per_layer];
      }

      double
      value(const Point<2> &p, const unsigned int component) const override
      {
        return slab.value(p, component % PlateFields::per_layer);
      }

    private:
      const Function<2> &slab;
    };
  } // namespace


  void
  InitialConditions::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    prm.declare_entry("Displacement",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "w; psi_x; psi_y at tau = 0 as muParser expressions "
                      "in x, y: w in units of F0 L^2 / D, the rotations in "
                      "F0 L / D."
                        + quantity("deflection, rotation, rotation"));
    prm.declare_entry("Velocity",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "Velocities of w; psi_x; psi_y at tau = 0, in x, y, "
                      "in the units of Displacement per t0."
                        + quantity(
                          "velocity, angular velocity, angular velocity"));
    prm.leave_subsection();
  }


  void
  InitialConditions::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    fields[0].name = "Displacement";
    fields[1].name = "Velocity";
    for (Field &field : fields)
      {
        field.text     = prm.get(field.name);
        field.function = parse_expression<2>(
          "Initial conditions/" + field.name, field.text, 3, "x,y", false);
        field.is_zero = true;
        for (const std::string &component :
             Utilities::split_string_list(field.text, ';'))
          {
            char        *end   = nullptr;
            const double value = std::strtod(component.c_str(), &end);
            field.is_zero &=
              (end != component.c_str() && *end == '\0' && value == 0.0);
          }
      }
    prm.leave_subsection();
  }


  void
  InitialConditions::interpolate(const Discretization &disc,
                                 const Field          &field,
                                 LA::MPI::Vector      &values) const
  {
    if (field.is_zero)
      values = 0;
    else
      VectorTools::interpolate(disc.mapping(),
                               disc.dof_handler,
                               InEveryLayer(*field.function,
                                            PlateFields::n_layers(
                                              disc.dof_handler.get_fe())),
                               values);
    disc.constraints.distribute(values);
  }


  void
  InitialConditions::interpolate(const Discretization &disc,
                                 LA::MPI::Vector      &u,
                                 LA::MPI::Vector      &v) const
  {
    LA::MPI::Vector *values[2] = {&u, &v};
    for (unsigned int k = 0; k < 2; ++k)
      {
        interpolate(disc, fields[k], *values[k]);
        AssertThrow(is_finite(*values[k]),
                    ExcMessage("Initial conditions/" + fields[k].name + " = <"
                               + fields[k].text
                               + "> is not a finite number at every node of "
                                 "the plate."));
      }
  }


  bool
  InitialConditions::is_at_rest(const Discretization &disc) const
  {
    LA::MPI::Vector values;
    disc.reinit_vector(values);
    for (const Field &field : fields)
      {
        interpolate(disc, field, values);
        if (values.linfty_norm() != 0.0)
          return false;
      }
    return true;
  }
} // namespace liftoff
