#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/fem/discretization.h>

#include <memory>
#include <string>

namespace liftoff
{
  using namespace dealii;

  /**
   * The state at tau = 0: w, psi_x, psi_y and their velocities as muParser
   * expressions in x, y, parsed when read and evaluated at the nodes once
   * the mesh exists.
   */
  class InitialConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    /// Throws, naming the entry, if an expression does not parse.
    void
    parse_parameters(ParameterHandler &prm);

    /// u and v at the nodes, constraints distributed; refuses a value that
    /// is not a finite number (sqrt(x) on x < 0), naming the entry.
    void
    interpolate(const Discretization &discretization,
                LA::MPI::Vector      &u,
                LA::MPI::Vector      &v) const;

    /// Whether both fields vanish at every node: a plate at rest.
    bool
    is_at_rest(const Discretization &discretization) const;

  private:
    struct Field
    {
      std::string                        name, text;
      std::unique_ptr<FunctionParser<2>> function;
      /// Every component is the number 0: the field is set to 0 instead of
      /// interpolated (0.7 s per field at a million unknowns, and a run
      /// asks up to three times).
      bool is_zero = false;
    };
    /// Displacement, then velocity.
    std::array<Field, 2> fields;

    void
    interpolate(const Discretization &discretization,
                const Field          &field,
                LA::MPI::Vector      &values) const;
  };
} // namespace liftoff
