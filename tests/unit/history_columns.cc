// A checkpoint keeps the time history's column names, so that a history of
// other columns (another version of liftoff, or other probes) is refused by
// name instead of its rows being misread: a history saved with the probe
// w(0;0) loads into one of the same columns and is refused, naming both
// lists, by one with the probe w(0.25;0) or with the energy columns off.
// The rows are kept as the values of these columns, so a column's name is
// the whole of its record: nothing else of a row can differ.

#include <liftoff/base/archives.h>
#include <liftoff/output/time_history.h>

#include "test_tools.h"

#include <sstream>

namespace
{
  std::unique_ptr<liftoff::TimeHistory>
  history_with(const std::string &probes, const bool energies)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Output");
    liftoff::TimeHistory::declare_parameters(prm);
    prm.set("Probe points", probes);
    prm.set("Write energies", energies);
    auto history = std::make_unique<liftoff::TimeHistory>();
    history->parse_parameters(prm, liftoff::MindlinPlate());
    prm.leave_subsection();
    return history;
  }


  /// The message of loading `saved` into `history` ("" if it loads).
  std::string
  load_message(const std::string &saved, liftoff::TimeHistory &history)
  {
    std::istringstream    in(saved);
    liftoff::InputArchive archive(in);
    try
      {
        history.load(archive);
      }
    catch (const dealii::ExceptionBase &e)
      {
        return liftoff::message_of(e);
      }
    return "";
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  std::ostringstream out;
  {
    liftoff::OutputArchive archive(out);
    history_with("0, 0", true)->save(archive);
  }
  const std::string saved = out.str();

  const auto same = history_with("0, 0", true);
  checks.within("a history of the same columns loads",
                load_message(saved, *same).empty(),
                1,
                1);

  const std::string other_probe =
    load_message(saved, *history_with("0.25, 0", true));
  checks.within("another probe is refused, naming both columns (" + other_probe
                  + ")",
                other_probe.find("w(0;0)") != std::string::npos
                  && other_probe.find("w(0.25;0)") != std::string::npos,
                1,
                1);

  const std::string no_energies =
    load_message(saved, *history_with("0, 0", false));
  checks.within("a history without the energy columns is refused",
                no_energies.find("balance_error") != std::string::npos,
                1,
                1);
  return checks.exit_code();
}
