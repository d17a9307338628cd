#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/simulator.h>
#include <liftoff/stop_signal.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

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
    "       liftoff --parameters         print every parameter with its "
    "default and documentation";

  // Rank 0 reads the scene (from a file or stdin) and all ranks parse the
  // same text, so every rank fails alike on bad input.
  std::string
  read_scene(const std::string &name, const MPI_Comm comm)
  {
    std::string text;
    bool        ok = true;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        if (name == "-")
          text.assign(std::istreambuf_iterator<char>(std::cin), {});
        else
          {
            std::ifstream in(name);
            ok = static_cast<bool>(in);
            text.assign(std::istreambuf_iterator<char>(in), {});
          }
      }
    ok   = dealii::Utilities::MPI::broadcast(comm, ok, 0);
    text = dealii::Utilities::MPI::broadcast(comm, text, 0);
    AssertThrow(ok, dealii::ExcMessage("Cannot read the scene file " + name));
    return text;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool is_root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

  if (argc == 2 && std::string(argv[1]) == "--parameters")
    {
      dealii::ParameterHandler prm;
      liftoff::Simulator::declare_parameters(prm);
      if (is_root)
        prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
      return 0;
    }
  using Start           = liftoff::Simulator::Start;
  Start      start      = Start::fresh;
  const bool has_option = (argc == 3);
  if (has_option && std::string(argv[1]) == "--resume")
    start = Start::resume;
  else if (has_option && std::string(argv[1]) == "--overwrite")
    start = Start::overwrite;
  if (argc != 2 + (start != Start::fresh)
      || std::string(argv[argc - 1]).rfind("--", 0) == 0)
    {
      if (is_root)
        std::cerr << usage << std::endl;
      return 2;
    }

  const std::string scene_name = argv[argc - 1];

  // SIGINT / SIGTERM end the run after the current step with complete
  // files and the exit code 128 + signal.
  liftoff::StopSignal::install();
  int stopping_signal = 0;

  // Keep the simulator alive until its exception has been caught: its
  // destructors must not run during stack unwinding under MPI.
  std::exception_ptr failure;
  {
    dealii::ParameterHandler prm;
    liftoff::Simulator       simulator(comm);
    try
      {
        liftoff::Simulator::declare_parameters(prm);
        std::istringstream scene(read_scene(scene_name, comm));
        prm.parse_input(scene, scene_name);
        simulator.parse_parameters(prm);
        simulator.run(prm, start);
      }
    catch (...)
      {
        failure         = std::current_exception();
        stopping_signal = simulator.stopping_signal();
      }
  }
  if (!failure)
    return 0;

  try
    {
      std::rethrow_exception(failure);
    }
  catch (const dealii::ExceptionBase &e)
    {
      if (is_root)
        {
          std::cerr << "liftoff: error in " << scene_name << ":\n";
          e.print_info(std::cerr);
          std::cerr << std::endl;
        }
    }
  catch (const std::exception &e)
    {
      if (is_root)
        std::cerr << "liftoff: error in " << scene_name << ":\n"
                  << e.what() << std::endl;
    }
  return stopping_signal != 0 ? 128 + stopping_signal : 1;
}
