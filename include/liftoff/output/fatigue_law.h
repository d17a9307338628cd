#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/output/rainflow.h>

#include <memory>
#include <string>

namespace liftoff
{
  using namespace dealii;

  /**
   * The cycles to failure N of a layer in flexural fatigue (the slab's
   * concrete, a cement-treated base) and what one cycle takes of its life
   * (Miner: count / N), as scripts/liftoff_fatigue.py has them: the MEPDG's
   * concrete law log10 N = C1 (MR / sigma)^C2 (NCHRP 1-37A, 2004, Part 3
   * Chapter 4, C1 = 2.0, C2 = 1.22, MR the modulus of rupture), or log10 N
   * as a muParser expression in sigma and MR, both in the scene's units (Pa
   * in an SI scene).
   *
   * sigma is the cycle's peak, its largest stress (the load's on top of the
   * curl's, as the MEPDG takes it): neither its range nor its mean enters
   * (no mean-stress correction). A cycle whose peak is not a tension
   * (sigma <= 0) does no damage: the law is that of a layer in tension.
   */
  class FatigueLaw
  {
  public:
    /**
     * The names of a law's entries in its subsection, so that one
     * subsection holds the laws of two layers. Without a `law` entry the
     * law is an expression only, and C1 and C2 are not read.
     */
    struct Entries
    {
      std::string law, c1, c2, modulus_of_rupture, expression;
    };
    /// The concrete's: Law, C1, C2, Modulus of rupture, Expression.
    static const Entries concrete;

    /// Its entries, in the subsection of the output that uses it.
    static void
    declare_parameters(ParameterHandler &prm);
    /// `section` names the subsection in messages ("Output/Fatigue
    /// damage"); `stress_scale` is the scene's unit of stress in the
    /// solver's (the expression sees the scene's stresses). Throws naming
    /// the entry.
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &section,
                     const double       stress_scale,
                     const Entries     &entries = concrete);

    /// The entry `entry` (an Expression) read (none if empty), also where
    /// it is not used (Law = MEPDG, the output off), so that a typo shows.
    /// Throws naming it.
    static std::shared_ptr<FunctionParser<2>>
    parsed_expression(ParameterHandler  &prm,
                      const std::string &section,
                      const std::string &entry = concrete.expression);

    /// The MEPDG's law of modulus of rupture `mr` (solver's units).
    static FatigueLaw
    mepdg(const double mr, const double c1 = 2.0, const double c2 = 1.22);

    /// log10 N at the stress sigma > 0 (solver's units).
    double
    log10_cycles(const double sigma) const;
    /// count / N(peak) of `cycle`; 0 unless its peak is a tension. Throws
    /// naming the expression where it gives no finite log10 N.
    double
    damage(const Rainflow::Cycle &cycle) const;

    /// The law in a line, for the summary, MR in the scene's `stress_unit`.
    std::string
    describe(const std::string &stress_unit) const;

  private:
    double      c1 = 2.0, c2 = 1.22;
    double      modulus_of_rupture = 1;
    double      scale              = 1;
    std::string expression, section;
    /// The entry the expression came from, for messages.
    std::string expression_entry = "Expression";
    /// In (sigma, MR); none: the MEPDG's law.
    std::shared_ptr<FunctionParser<2>> parsed;
  };
} // namespace liftoff
