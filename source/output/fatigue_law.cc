#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/output/fatigue_law.h>

#include <cmath>
#include <limits>

namespace liftoff
{
  namespace
  {
    enum class LawKind
    {
      mepdg,
      expression
    };

    const Selection<LawKind> law_kinds = {{"MEPDG", LawKind::mepdg},
                                          {"expression", LawKind::expression}};


    /// `value` of the entry `name` if it is a finite number > 0.
    double
    positive_entry(const ParameterHandler &prm,
                   const std::string      &section,
                   const std::string      &name)
    {
      const double value = prm.get_double(name);
      AssertThrow(std::isfinite(value) && value > 0,
                  ExcMessage(section + "/" + name + " = " + prm.get(name)
                             + " must be a finite number > 0."));
      return value;
    }
  } // namespace


  const FatigueLaw::Entries FatigueLaw::concrete = {"Law",
                                                    "C1",
                                                    "C2",
                                                    "Modulus of rupture",
                                                    "Expression"};


  void
  FatigueLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Law",
                      "MEPDG",
                      law_kinds.pattern(),
                      "The fatigue law, cycles to failure N at a cycle's peak "
                      "tension sigma: MEPDG, log10 N = C1 (MR / sigma)^C2 "
                      "(NCHRP 1-37A, 2004), or an expression of log10 N "
                      "(Expression).");
    prm.declare_entry("C1",
                      "2.0",
                      Patterns::Double(),
                      "The MEPDG law's C1 > 0 (2.0 in the MEPDG)."
                        + quantity("number"));
    prm.declare_entry("C2",
                      "1.22",
                      Patterns::Double(),
                      "The MEPDG law's C2 > 0 (1.22 in the MEPDG)."
                        + quantity("number"));
    prm.declare_entry("Modulus of rupture",
                      "0",
                      Patterns::Double(),
                      "MR > 0, the concrete's flexural strength (Pa in an SI "
                      "scene); must be given."
                        + quantity("pressure"));
    prm.declare_entry("Expression",
                      "",
                      Patterns::Anything(),
                      "With Law = expression: log10 N as a muParser "
                      "expression in sigma (the cycle's peak tension) and MR, "
                      "both in the scene's units (Pa in an SI scene), as "
                      "2.0*(MR/sigma)^1.22."
                        + quantity("text"));
  }


  void
  FatigueLaw::parse_parameters(ParameterHandler  &prm,
                               const std::string &section_name,
                               const double       stress_scale,
                               const Entries     &entries)
  {
    section              = section_name;
    scale                = stress_scale;
    expression_entry     = entries.expression;
    const bool has_mepdg = !entries.law.empty();
    if (has_mepdg)
      {
        c1 = positive_entry(prm, section, entries.c1);
        c2 = positive_entry(prm, section, entries.c2);
      }
    modulus_of_rupture =
      positive_entry(prm, section, entries.modulus_of_rupture);
    parsed     = parsed_expression(prm, section, entries.expression);
    expression = prm.get(entries.expression);
    if (has_mepdg
        && law_kinds.parse(prm.get(entries.law), section + "/" + entries.law)
             == LawKind::mepdg)
      {
        parsed.reset();
        expression.clear();
        return;
      }
    const std::string needs =
      has_mepdg ? section + "/" + entries.law + " = expression"
                : section + "/" + entries.modulus_of_rupture + " given";
    AssertThrow(parsed,
                ExcMessage(needs + " needs " + section + "/"
                           + entries.expression
                           + ": log10 N in sigma and MR."));
    // A law that gives no number at the modulus of rupture itself gives
    // none at the stresses a run meets.
    const double at_mr = log10_cycles(modulus_of_rupture);
    AssertThrow(std::isfinite(at_mr),
                ExcMessage(section + "/" + expression_entry + " = <"
                           + abbreviated(expression)
                           + "> gives log10 N = " + format_number(at_mr)
                           + " at sigma = MR: it must be a finite number."));
  }


  std::shared_ptr<FunctionParser<2>>
  FatigueLaw::parsed_expression(ParameterHandler  &prm,
                                const std::string &section,
                                const std::string &entry)
  {
    const std::string text = prm.get(entry);
    if (text.find_first_not_of(" \t") == std::string::npos)
      return {};
    return parse_expression<2>(
      section + "/" + entry, text, 1, "sigma,MR", false);
  }


  FatigueLaw
  FatigueLaw::mepdg(const double mr, const double c1, const double c2)
  {
    FatigueLaw law;
    law.modulus_of_rupture = mr;
    law.c1                 = c1;
    law.c2                 = c2;
    return law;
  }


  double
  FatigueLaw::log10_cycles(const double sigma) const
  {
    if (!parsed)
      return c1 * std::pow(modulus_of_rupture / sigma, c2);
    return parsed->value(Point<2>(scale * sigma, scale * modulus_of_rupture));
  }


  double
  FatigueLaw::damage(const Rainflow::Cycle &cycle) const
  {
    const double sigma = cycle.peak();
    if (!(sigma > 0))
      return 0;
    const double log_n = log10_cycles(sigma);
    // N beyond any number (a stress far below MR): no damage.
    if (log_n == std::numeric_limits<double>::infinity())
      return 0;
    AssertThrow(std::isfinite(log_n),
                ExcMessage(section + "/" + expression_entry + " = <"
                           + abbreviated(expression)
                           + "> gives no finite log10 N at sigma = "
                           + format_number(scale * sigma) + "."));
    // 10^-log10 N underflows to 0 for a small stress, where N overflows.
    return cycle.count * std::pow(10.0, -log_n);
  }


  std::string
  FatigueLaw::describe(const std::string &stress_unit) const
  {
    const std::string mr =
      "MR = " + format_number(scale * modulus_of_rupture) + " " + stress_unit;
    if (parsed)
      return "log10 N = " + abbreviated(expression) + ", " + mr;
    return "log10 N = " + format_number(c1) + " (MR / sigma)^"
           + format_number(c2) + ", " + mr + " (MEPDG)";
  }
} // namespace liftoff
