#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/output_files.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/run/output_directory.h>
#include <liftoff/run/simulator.h>
#include <liftoff/run/stop_signal.h>
#include <liftoff/version.h>

#include <sys/resource.h>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <vector>

namespace
{
  const char *usage =
    "usage: liftoff SCENE.prm            run a scene (refused if its output\n"
    "                                    directory holds an earlier run's\n"
    "                                    results or another run is using it)\n"
    "       liftoff -                    read the scene from standard input\n"
    "       liftoff --overwrite SCENE    the same, replacing the results of\n"
    "                                    an earlier run in the directory\n"
    "       liftoff --resume SCENE       continue the scene from the newest\n"
    "                                    checkpoint in its output directory\n"
    "                                    (same number of ranks; the end time\n"
    "                                    may be changed)\n"
    "       liftoff --batch SCENE...     run the scenes one after the other "
    "in\n"
    "                                    this process, each into its own\n"
    "                                    output directory as if run alone; a\n"
    "                                    scene that fails does not stop the\n"
    "                                    others (exit code 1 if any failed);\n"
    "                                    after each, one line on standard\n"
    "                                    output: its name, exit code, wall\n"
    "                                    and CPU seconds\n"
    "       liftoff --batch -            the same with the scenes' file names\n"
    "                                    read from standard input, one a\n"
    "                                    line, each run as it arrives (a\n"
    "                                    tool's worker)\n"
    "       liftoff --quiet ...          no progress line, and one status\n"
    "                                    line instead of the summary, which\n"
    "                                    stays in summary.txt (also -q; with\n"
    "                                    any of the above)\n"
    "       liftoff --parameters         print every parameter with its "
    "default and documentation\n"
    "       liftoff --parameters json    the same as JSON, with the values\n"
    "                                    each parameter allows (its pattern)\n"
    "       liftoff --version            print the version and the git commit\n"
    "                                    it was built from\n"
    "       liftoff --help, -h           print this text\n"
    "\n"
    "SIGINT (Ctrl-C) or SIGTERM ends a run after the current step with\n"
    "complete files, a checkpoint and the exit code 128 + signal. Under\n"
    "mpirun, signal the liftoff processes (pkill -INT -x liftoff): mpirun,\n"
    "when signalled itself, kills them a second later and exits 1.\n"
    "README.md and doc/ describe scenes, outputs and tools.";

  // deal.II spreads its messages over indented lines; one line reads
  // better and stays one line in a log.
  std::string
  one_line(const std::string &message)
  {
    std::istringstream words(message);
    std::string        line, word;
    while (words >> word)
      line += (line.empty() ? "" : " ") + word;
    // deal.II quotes a value that does not match its pattern whole, however
    // long; keep the start and the end, which names the pattern.
    constexpr std::size_t head = 400, tail = 300;
    if (line.size() > head + tail + 100)
      line = line.substr(0, head) + " ... ("
             + std::to_string(line.size() - head - tail)
             + " characters left out) ... " + line.substr(line.size() - tail);
    return line;
  }


  // Rank 0 reads the scene (from a file or stdin) and the files its
  // include lines name; all ranks parse the same text, so every rank fails
  // alike on bad input.
  liftoff::SceneText
  read_scene(const std::string &name, const MPI_Comm comm)
  {
    liftoff::SceneText scene;
    std::string        error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          scene = liftoff::SceneText::read(name);
        }
      catch (const std::exception &e)
        {
          error = liftoff::message_of(e);
        }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), dealii::ExcMessage(error));
    scene.text    = dealii::Utilities::MPI::broadcast(comm, scene.text, 0);
    scene.origins = dealii::Utilities::MPI::broadcast(comm, scene.origins, 0);
    return scene;
  }

  // Open MPI started without a launcher (a singleton) otherwise brings up
  // its UCX network layer and a helper daemon: 0.2 to 0.4 s of every run's
  // start on the 2-core machine (benchmarks/start_up.sh), for one process
  // that talks to nobody. A launcher's processes keep what it chose, and
  // a user's own setting of these variables wins.
  void
  prefer_local_transport_when_alone()
  {
#ifdef OPEN_MPI
    for (const char *launcher_mark :
         {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
      if (std::getenv(launcher_mark) != nullptr)
        return;
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
#endif
  }


  // Under mpirun every rank gets the option; one answers. Read from the
  // launcher's environment, as MPI is not started for these options.
  bool
  is_first_process()
  {
    for (const char *rank : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
      if (const char *value = std::getenv(rank))
        return std::string(value) == "0";
    return true;
  }


  // --help, --version and --parameters only print: they start no MPI, which
  // is most of their time (benchmarks/start_up.sh). Returns whether the
  // option was one of them.
  bool
  answered_without_mpi(const int argc, char **argv)
  {
    const std::string option =
      argc == 2 ? argv[1]
      : argc == 3 && std::string(argv[1]) == "--parameters"
        ? std::string("--parameters ") + argv[2]
        : "";
    std::ostringstream answer;
    if (option == "--help" || option == "-h")
      answer << usage << '\n';
    else if (option == "--version")
      answer << "liftoff " << LIFTOFF_VERSION << " (git " << LIFTOFF_GIT_COMMIT
             << "), deal.II " << DEAL_II_PACKAGE_VERSION << '\n';
    else if (option == "--parameters" || option == "--parameters json")
      {
        dealii::ParameterHandler prm;
        liftoff::Simulator::declare_parameters(prm);
        prm.print_parameters(answer,
                             option == "--parameters"
                               ? dealii::ParameterHandler::PRM
                               : dealii::ParameterHandler::JSON);
      }
    else
      return false;
    if (is_first_process())
      std::cout << answer.str() << std::flush;
    return true;
  }


  struct CommandLine
  {
    liftoff::Simulator::Start start = liftoff::Simulator::Start::fresh;
    bool                      quiet = false;
    bool                      batch = false;
    std::vector<std::string>  scene_names;
    /// Empty if the command line is valid.
    std::string error;
  };


  CommandLine
  parse_command_line(const int argc, char **argv)
  {
    using Start = liftoff::Simulator::Start;
    CommandLine              command;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i)
      {
        const std::string argument = argv[i];
        if (argument == "--resume" || argument == "--overwrite")
          {
            const Start asked =
              argument == "--resume" ? Start::resume : Start::overwrite;
            if (command.start != Start::fresh && command.start != asked)
              command.error = "--resume continues the results in the output "
                              "directory and --overwrite removes them: give "
                              "one of them, not both.";
            command.start = asked;
          }
        else if (argument == "--quiet" || argument == "-q")
          command.quiet = true;
        else if (argument == "--batch")
          command.batch = true;
        else if (argument.size() > 1 && argument[0] == '-')
          command.error = "unknown option " + argument + ".";
        else
          scenes.push_back(argument);
      }
    if (command.error.empty() && scenes.empty())
      command.error = "no scene file given.";
    else if (command.error.empty() && scenes.size() > 1 && !command.batch)
      command.error = "one scene file at a time, not "
                      + std::to_string(scenes.size())
                      + " (--batch runs several).";
    else if (command.error.empty() && command.batch && scenes.size() > 1
             && std::count(scenes.begin(), scenes.end(), "-") > 0)
      command.error = "--batch reads its scenes from files, or (--batch -) "
                      "their names from standard input, not both.";
    command.scene_names = scenes;
    return command;
  }


  // One line on standard error for the exception that ended the run; the
  // exit code.
  int
  report_failure(const std::exception_ptr &failure,
                 const std::string        &scene_name,
                 const bool                is_adaptive,
                 const int                 stopping_signal,
                 const MPI_Comm            comm)
  {
    const bool is_root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    try
      {
        std::rethrow_exception(failure);
      }
    catch (const dealii::ExceptionBase &e)
      {
        // A solver failure is not the user's message but is mostly caused
        // by the scene: say what to look at.
        const std::string hint =
          std::string(e.get_exc_name()).find("Trilinos") != std::string::npos
            ? " (the linear solver failed: the system matrix is singular or "
              "too ill-conditioned for double precision; check Plate, "
              "Foundation/Stiffness, the supports and Time integration/Time "
              "step)"
            : "";
        if (is_root)
          std::cerr << "liftoff: error in " << scene_name << ":\n    "
                    << one_line(liftoff::message_of(e)) << hint << std::endl;
      }
    catch (const std::bad_alloc &)
      {
        // Only rank 0 reports, and a rank that ran out may not be rank 0:
        // every rank that did says so, in one line.
        std::cerr << "liftoff: error in " << scene_name
                  << ": out of memory (std::bad_alloc) on rank "
                  << dealii::Utilities::MPI::this_mpi_process(comm)
                  << "; the scene needs more memory than this machine or its "
                     "limits give "
                  << (is_adaptive
                        ? "as its adaptive mesh grows (see Mesh "
                          "refinement/Maximum number of cells and Maximum "
                          "level)."
                        : "(see Discretization/Cells along x, y, Global "
                          "refinements, Polynomial degree).")
                  << std::endl;
      }
    catch (const std::exception &e)
      {
        if (is_root)
          std::cerr << "liftoff: error in " << scene_name << ":\n    "
                    << one_line(e.what()) << std::endl;
      }
    return stopping_signal != 0 ? 128 + stopping_signal : 1;
  }
  // One scene from its file to its results: its own parameters and
  // Simulator, so that the scenes of a batch share nothing but the
  // process. Returns the exit code a run of it alone would have.
  int
  run_scene(const std::string &scene_name,
            const CommandLine &command,
            const MPI_Comm     comm)
  {
    int stopping_signal = 0;
    // Keep the simulator alive until its exception has been caught: its
    // destructors must not run during stack unwinding under MPI.
    std::exception_ptr failure;
    // Whether the mesh grows during the run: then running out of memory
    // is the refinement's doing, not the initial mesh's (which is checked
    // against the memory before it is built).
    bool is_adaptive = false;
    {
      dealii::ParameterHandler prm;
      liftoff::Simulator       simulator(comm, true, !command.quiet);
      try
        {
          simulator.declare_scene(prm);
          liftoff::OutputDirectory::name_after_scene(prm, scene_name);
          read_scene(scene_name, comm).parse_into(prm, scene_name);
          simulator.parse_parameters(prm);
          prm.enter_subsection("Mesh refinement");
          is_adaptive = prm.get_bool("Adaptive");
          prm.leave_subsection();
          simulator.run(prm, command.start);
        }
      catch (...)
        {
          failure         = std::current_exception();
          stopping_signal = simulator.stopping_signal();
        }
    }
    if (!failure)
      return 0;
    return report_failure(
      failure, scene_name, is_adaptive, stopping_signal, comm);
  }


  // The scenes to run: the command line's, or with `--batch -` the file
  // names that standard input brings, one a line, read on rank 0 as each
  // is wanted, so that a tool can keep one process as a worker and send it
  // a scene whenever it has one (start-up, mostly the dynamic loader, is
  // then paid once per worker).
  class SceneNames
  {
  public:
    SceneNames(const CommandLine &command, const MPI_Comm comm)
        : names(command.scene_names)
        , from_input(command.batch && names.size() == 1 && names[0] == "-")
        , comm(comm)
    {}

    // The next scene's name into `name`; false when there is none.
    bool
    next(std::string &name)
    {
      if (!from_input)
        {
          if (index == names.size())
            return false;
          name = names[index++];
          ++n_taken;
          return true;
        }
      bool has_name = false;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        while (!has_name && std::getline(std::cin, name))
          has_name = !name.empty();
      has_name = dealii::Utilities::MPI::broadcast(comm, has_name, 0);
      name     = dealii::Utilities::MPI::broadcast(comm, name, 0);
      n_taken += has_name;
      return has_name;
    }

    // How many scenes next() has given.
    std::size_t
    taken() const
    {
      return n_taken;
    }

    // How many named scenes follow, for a message; unknown from input.
    std::string
    left() const
    {
      return from_input ? "the scenes still to come on standard input"
                        : std::to_string(names.size() - index) + " scene(s)";
    }

  private:
    const std::vector<std::string> names;
    const bool                     from_input;
    const MPI_Comm                 comm;
    std::size_t                    index   = 0;
    std::size_t                    n_taken = 0;
  };


  double
  cpu_seconds()
  {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval &t) {
      return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec;
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
  }


  // A scene's wall and CPU seconds in a batch (CPU summed over the ranks,
  // as a process's under mpirun would be), printed in one line when it
  // ends: a tool that runs its scenes through one process still knows what
  // each cost, and the process's start-up apart ("started" with the CPU
  // it took).
  class BatchClock
  {
  public:
    explicit BatchClock(const MPI_Comm comm)
        : comm(comm)
    {}

    void
    started() const
    {
      print("liftoff: batch: started, cpu " + seconds(cpu_seconds()));
    }

    void
    start_scene()
    {
      // summary.txt reports the process's peak memory; in a batch that
      // would be an earlier scene's. What the earlier scenes freed goes
      // back to the system first (malloc keeps it otherwise: 390 MB of
      // a larger scene stayed resident), then Linux resets the mark to
      // what is resident on this write; where it cannot, the mark stays
      // the process's.
#ifdef __GLIBC__
      malloc_trim(0);
#endif
      std::ofstream("/proc/self/clear_refs") << "5";
      wall_start = std::chrono::steady_clock::now();
      cpu_start  = cpu_seconds();
    }

    void
    end_scene(const std::string &name, const int code) const
    {
      const std::chrono::duration<double> wall =
        std::chrono::steady_clock::now() - wall_start;
      const double cpu =
        dealii::Utilities::MPI::sum(cpu_seconds() - cpu_start, comm);
      print("liftoff: batch: " + name + ": exit " + std::to_string(code)
            + ", wall " + seconds(wall.count()) + ", cpu " + seconds(cpu));
    }

  private:
    static std::string
    seconds(const double value)
    {
      std::ostringstream text;
      text.precision(6);
      text << std::fixed << value << " s";
      return text.str();
    }

    void
    print(const std::string &line) const
    {
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        std::cout << line << std::endl;
    }

    const MPI_Comm                        comm;
    std::chrono::steady_clock::time_point wall_start;
    double                                cpu_start = 0;
  };


  // Runs the scenes one after the other; the exit code: 0, 1 if a scene
  // failed (named at the end of a batch), or 128 + signal if one was
  // stopped, which starts no further scene.
  int
  run_scenes(const CommandLine &command, const MPI_Comm comm)
  {
    const bool  is_root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    SceneNames  names(command, comm);
    BatchClock  clock(comm);
    std::string name;
    std::vector<std::string> failed;
    if (command.batch)
      clock.started();
    while (names.next(name))
      {
        // A signal while a worker waited for its next scene.
        const int waiting_signal = liftoff::StopSignal::received(comm);
        int       code           = 128 + waiting_signal;
        if (waiting_signal == 0)
          {
            // A scene run alone is left as it always was.
            if (command.batch)
              clock.start_scene();
            code = run_scene(name, command, comm);
          }
        if (command.batch)
          clock.end_scene(name, code);
        if (code > 128)
          {
            if (command.batch && is_root)
              std::cerr << "liftoff: batch interrupted: " << names.left()
                        << " not run." << std::endl;
            return code;
          }
        if (code != 0)
          failed.push_back(name);
      }
    if (command.batch && !failed.empty() && is_root)
      {
        std::cerr << "liftoff: batch: " << failed.size() << " of "
                  << names.taken() << " scenes failed:";
        for (const std::string &f : failed)
          std::cerr << ' ' << f;
        std::cerr << std::endl;
      }
    return failed.empty() ? 0 : 1;
  }
} // namespace


int
main(int argc, char **argv)
{
  if (answered_without_mpi(argc, argv))
    return 0;
  prefer_local_transport_when_alone();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;

  const CommandLine command = parse_command_line(argc, argv);
  if (!command.error.empty())
    {
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        std::cerr << "liftoff: " << command.error << "\n\n"
                  << usage << std::endl;
      return 2;
    }
  // SIGINT / SIGTERM end the run after the current step with complete
  // files and the exit code 128 + signal; a batch starts no further scene.
  liftoff::StopSignal::install();
  return run_scenes(command, comm);
}
