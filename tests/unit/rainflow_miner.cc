// liftoff::Rainflow (ASTM E1049 rainflow counting, value by value) and
// liftoff::FatigueLaw (Miner's sum under the MEPDG law), the pieces of
// Output/Fatigue damage, against the standard's worked example and a hand
// calculation (the same references as tests/unit/fatigue_rainflow.py, which
// checks scripts/liftoff_fatigue.py):
//
// - ASTM E1049-85 (reapproved 2017), 5.4.4 and Fig. 6: the history -2, 1,
//   -3, 5, -1, 3, -4, 4, -2 (the points A to I) counts, by range, the
//   standard's table of Fig. 6(e): range 3: 0.5, 4: 1.5, 6: 0.5, 8: 1.0,
//   9: 0.5; traced by hand in the order of 5.4.4: A-B half (range 3, mean
//   -0.5), B-C half (4, -1), E-F full (4, 1), C-D half (8, 1), then the
//   residue D-G half (9, 0.5), G-H half (8, 0), H-I half (6, 1). The same
//   history sampled 4 times finer with repeated values counts the same; a
//   counter saved after point E and loaded counts the rest the same.
// - Miner's sum under log10 N = 2.0 (MR / sigma)^1.22, MR = 4.5 MPa, by
//   hand (6 digits): 1/N(4 MPa) = 4.90835e-3, 1/N(3 MPa) = 5.24922e-4,
//   1/N(2 MPa) = 4.17936e-6; a full cycle peaking at 4 MPa, a half at 3, a
//   full at 2 and a full peaking in compression (-1 MPa: none) sum to
//   5.17499e-3. A pass 0 -> 3 MPa -> 0 (two half cycles of range 3 MPa) is
//   1/N(3 MPa); the law as the expression 2.0*(MR/sigma)^1.22 gives the
//   same; bad entries are refused in one line naming the entry.

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/archives.h>
#include <liftoff/output/fatigue_law.h>
#include <liftoff/output/rainflow.h>

#include "test_tools.h"

#include <map>
#include <sstream>

using namespace dealii;

namespace
{
  using Cycle = liftoff::Rainflow::Cycle;

  std::vector<Cycle>
  count_all(const std::vector<double> &history)
  {
    liftoff::Rainflow  counter;
    std::vector<Cycle> cycles;
    for (const double value : history)
      counter.add(value, cycles);
    const std::vector<Cycle> residue = counter.residue();
    cycles.insert(cycles.end(), residue.begin(), residue.end());
    return cycles;
  }


  /// How many cycles differ from (range, mean, count) in `expected`.
  unsigned int
  differing(const std::vector<Cycle>                 &cycles,
            const std::vector<std::array<double, 3>> &expected)
  {
    if (cycles.size() != expected.size())
      return std::max(cycles.size(), expected.size());
    unsigned int wrong = 0;
    for (unsigned int i = 0; i < cycles.size(); ++i)
      wrong += (cycles[i].range() != expected[i][0]
                || cycles[i].mean() != expected[i][1]
                || cycles[i].count != expected[i][2]);
    return wrong;
  }


  /// The message of the exception that parsing `entries` (path, value
  /// within Output/Fatigue damage) throws; empty if none.
  std::string
  refusal(const std::vector<std::pair<std::string, std::string>> &entries)
  {
    ParameterHandler prm;
    liftoff::FatigueLaw::declare_parameters(prm);
    for (const auto &[name, value] : entries)
      prm.set(name, value);
    try
      {
        liftoff::FatigueLaw law;
        law.parse_parameters(prm, "Output/Fatigue damage", 1.0);
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }


  /// Whether `message` names the entry and says what it must be on that
  /// line (deal.II's ExcMessage adds a frame around it).
  bool
  names_in_one_line(const std::string &message, const std::string &entry)
  {
    // deal.II wraps the message's one line: join it again.
    const auto at = message.find("Output/Fatigue damage/" + entry);
    if (at == std::string::npos)
      return false;
    std::string joined;
    for (const char c : message.substr(at))
      if (c != '\n')
        joined += c;
      else if (joined.back() != ' ')
        joined += ' ';
    const std::string sentence = joined.substr(0, joined.find(". "));
    return sentence.find("must") != std::string::npos
           || sentence.find("needs") != std::string::npos;
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  const std::vector<double> astm = {-2, 1, -3, 5, -1, 3, -4, 4, -2};
  const std::vector<std::array<double, 3>> traced = {{{3, -0.5, 0.5}},
                                                     {{4, -1, 0.5}},
                                                     {{4, 1, 1.0}},
                                                     {{8, 1, 0.5}},
                                                     {{9, 0.5, 0.5}},
                                                     {{8, 0, 0.5}},
                                                     {{6, 1, 0.5}}};
  const std::vector<Cycle>                 cycles = count_all(astm);
  checks.less("ASTM E1049 Fig. 6: cycles (range, mean, count) that differ "
              "from 5.4.4 traced by hand",
              differing(cycles, traced),
              0.5);
  std::map<double, double> by_range;
  for (const Cycle &c : cycles)
    by_range[c.range()] += c.count;
  const std::map<double, double> table = {
    {3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  checks.less("ASTM E1049 Fig. 6(e): counts by range differ from the table",
              by_range != table,
              0.5);

  std::vector<double> fine;
  for (unsigned int i = 0; i + 1 < astm.size(); ++i)
    for (unsigned int k = 0; k < 4; ++k)
      {
        fine.push_back(astm[i] + (astm[i + 1] - astm[i]) * k / 4.0);
        if (k == 0)
          fine.push_back(fine.back());
      }
  fine.push_back(astm.back());
  checks.less("sampled 4 times finer, values repeated: cycles that differ",
              differing(count_all(fine), traced),
              0.5);
  checks.less("cycles of an empty and of a one-value history",
              count_all({}).size() + count_all({1.5}).size(),
              0.5);

  // Saved after point E (-1) and loaded into a new counter.
  liftoff::Rainflow  before;
  std::vector<Cycle> resumed;
  for (unsigned int i = 0; i < 5; ++i)
    before.add(astm[i], resumed);
  std::stringstream buffer;
  {
    liftoff::OutputArchive out(buffer);
    before.save(out);
  }
  liftoff::Rainflow after;
  {
    liftoff::InputArchive in(buffer);
    after.load(in);
  }
  for (unsigned int i = 5; i < astm.size(); ++i)
    after.add(astm[i], resumed);
  const std::vector<Cycle> residue = after.residue();
  resumed.insert(resumed.end(), residue.begin(), residue.end());
  checks.less("saved after E and loaded: cycles that differ",
              differing(resumed, traced),
              0.5);

  // Miner's sum under the MEPDG law, in Pa.
  const liftoff::FatigueLaw mepdg       = liftoff::FatigueLaw::mepdg(4.5e6);
  const std::vector<Cycle>  hand_cycles = {{0, 4e6, 1.0},
                                           {3e6, -1e6, 0.5},
                                           {2e6, 1e6, 1.0},
                                           {-3e6, -1e6, 1.0}};
  double                    sum         = 0;
  for (const Cycle &c : hand_cycles)
    sum += mepdg.damage(c);
  checks.less("Miner's sum, MEPDG law: relative error against the hand "
              "5.17499e-3",
              std::abs(sum / 5.17499e-3 - 1),
              2e-6);
  double worst = 0;
  for (const auto &[peak, inverse] : std::vector<std::pair<double, double>>{
         {4e6, 4.90835e-3}, {3e6, 5.24922e-4}, {2e6, 4.17936e-6}})
    worst =
      std::max(worst, std::abs(mepdg.damage({0, peak, 1.0}) / inverse - 1));
  checks.less("1/N at 4, 3 and 2 MPa: relative error against the hand",
              worst,
              2e-6);
  checks.less("damage of cycles peaking in compression or at 0",
              mepdg.damage({-2e6, -1e6, 1.0}) + mepdg.damage({-1e6, 0, 1.0}),
              1e-300);
  double pass = 0;
  for (const Cycle &c : count_all({0, 1.5e6, 3e6, 1e6, 0}))
    pass += mepdg.damage(c);
  checks.less("a pass 0 -> 3 MPa -> 0: relative error against 1/N(3 MPa)",
              std::abs(pass / 5.24922e-4 - 1),
              2e-6);

  // The same law as an expression, through the entries.
  ParameterHandler prm;
  liftoff::FatigueLaw::declare_parameters(prm);
  prm.set("Law", "expression");
  prm.set("Expression", "2.0*(MR/sigma)^1.22");
  prm.set("Modulus of rupture", "4.5");
  liftoff::FatigueLaw expression;
  // In units of 1e6 Pa, with the scene's unit 1e6 Pa: the expression sees
  // Pa.
  expression.parse_parameters(prm, "Output/Fatigue damage", 1e6);
  double by_expression = 0;
  for (const Cycle &c : hand_cycles)
    by_expression += expression.damage({c.from * 1e-6, c.to * 1e-6, c.count});
  checks.less("the law as the expression 2.0*(MR/sigma)^1.22: relative "
              "difference to the MEPDG law",
              std::abs(by_expression / sum - 1),
              1e-12);

  unsigned int unclear = 0;
  for (const auto &[entries, named] :
       std::vector<std::pair<std::vector<std::pair<std::string, std::string>>,
                             std::string>>{
         {{}, "Modulus of rupture"},
         {{{"Modulus of rupture", "-1"}}, "Modulus of rupture"},
         {{{"Modulus of rupture", "1"}, {"C1", "0"}}, "C1"},
         {{{"Modulus of rupture", "1"}, {"C2", "-2"}}, "C2"},
         {{{"Modulus of rupture", "1"},
           {"Law", "expression"},
           {"Expression", "x*sigma"}},
          "Expression"},
         {{{"Modulus of rupture", "1"},
           {"Law", "expression"},
           {"Expression", "sqrt(-sigma)"}},
          "Expression"},
         {{{"Modulus of rupture", "1"}, {"Law", "expression"}}, "Law"},
         {{{"Modulus of rupture", "1"}, {"Expression", "2*(MR/s)"}},
          "Expression"}})
    {
      const std::string message = refusal(entries);
      if (!names_in_one_line(message, named))
        {
          ++unclear;
          std::cout << "not refused in one line naming " << named << ": "
                    << message << std::endl;
        }
    }
  checks.less("bad entries not refused in one line naming the entry",
              unclear,
              0.5);
  return checks.exit_code();
}
