// A checkpoint keeps the time history's column names, so that a history of
// other columns (another version of liftoff, or other probes) is refused by
// name instead of its rows being misread: a history saved with the probe
// w(0;0) loads into one of the same columns and is refused, naming both
// lists, by one with the probe w(0.25;0) or with the energy columns off.
// The rows are kept as the values of these columns, so a column's name is
// the whole of its record: nothing else of a row can differ.

#include <liftoff/base/archives.h>
#include <liftoff/output/time_history.h>
#include <liftoff/run/simulator.h>

#include "test_tools.h"

#include <sstream>

namespace
{
  // A time history of the default scene with the given probes and energy
  // columns, set up on its mesh as a run sets it up (its columns are made
  // then), with the parts it reads.
  struct HistoryOfScene
  {
    liftoff::SectionTimer      timer;
    liftoff::SceneParts        parts{MPI_COMM_WORLD, timer};
    liftoff::PhysicalUnits     units;
    dealii::ConditionalOStream quiet{std::cout, false};
    dealii::ParameterHandler   prm;
    liftoff::TimeHistory       history;

    HistoryOfScene(const std::string &probes, const bool energies)
    {
      liftoff::Simulator::declare_parameters(prm);
      units.watch(prm);
      prm.enter_subsection("Output");
      prm.set("Probe points", probes);
      prm.set("Write energies", energies);
      prm.leave_subsection();
      units.parse_parameters(prm, liftoff::SceneParts::outline_for_units(prm));
      dealii::ParameterHandler &scene =
        units.solver_scene(prm, liftoff::Simulator::declare_parameters);
      parts.parse_parameters(scene, units);
      parts.setup_mesh();
      const liftoff::SceneView view = parts.view(units, quiet);
      scene.enter_subsection("Output");
      history.parse_parameters(scene, view);
      scene.leave_subsection();
      history.write_in_units_of(units);
      history.setup(view, "");
    }
  };


  std::unique_ptr<HistoryOfScene>
  history_with(const std::string &probes, const bool energies)
  {
    return std::make_unique<HistoryOfScene>(probes, energies);
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
    history_with("0, 0", true)->history.save(archive);
  }
  const std::string saved = out.str();

  const auto same = history_with("0, 0", true);
  checks.within("a history of the same columns loads",
                load_message(saved, same->history).empty(),
                1,
                1);

  const std::string other_probe =
    load_message(saved, history_with("0.25, 0", true)->history);
  checks.within("another probe is refused, naming both columns (" + other_probe
                  + ")",
                other_probe.find("w(0;0)") != std::string::npos
                  && other_probe.find("w(0.25;0)") != std::string::npos,
                1,
                1);

  const std::string no_energies =
    load_message(saved, history_with("0, 0", false)->history);
  checks.within("a history without the energy columns is refused",
                no_energies.find("balance_error") != std::string::npos,
                1,
                1);
  return checks.exit_code();
}
