#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <boost/serialization/array_wrapper.hpp>

#include <liftoff/checkpoint.h>
#include <liftoff/output_files.h>

#include <Epetra_CrsMatrix.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace liftoff
{
  namespace
  {
    const std::string header_name = "checkpoint.txt";
    const std::string first_line  = "liftoff checkpoint, format 2";

    std::string
    rank_file(const std::string &folder, const MPI_Comm comm)
    {
      return folder + "/rank_"
             + Utilities::int_to_string(Utilities::MPI::this_mpi_process(comm),
                                        4)
             + ".bin";
    }

    /// Read a line "<key><number>".
    bool
    read_number(std::istream &in, const std::string &key, unsigned int &number)
    {
      std::string line;
      if (!std::getline(in, line) || line.rfind(key, 0) != 0)
        return false;
      std::istringstream value(line.substr(key.size()));
      return static_cast<bool>(value >> number);
    }


    /// Throw on every rank with the message of the first rank that failed.
    void
    throw_if_any_failed(const std::string &error,
                        const MPI_Comm     comm,
                        const std::string &what)
    {
      const auto  errors = Utilities::MPI::gather(comm, error, 0);
      std::string first;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        for (const auto &e : errors)
          if (first.empty())
            first = e;
      first = Utilities::MPI::broadcast(comm, first, 0);
      AssertThrow(first.empty(), ExcMessage(what + ": " + first));
    }
  } // namespace


  void
  save_vector(OutputArchive &archive, const LA::MPI::Vector &vector)
  {
    const std::size_t n = vector.locally_owned_size();
    archive << n << boost::serialization::make_array(vector.begin(), n);
  }


  void
  load_vector(InputArchive &archive, LA::MPI::Vector &vector)
  {
    std::size_t n = 0;
    archive >> n;
    AssertThrow(n == vector.locally_owned_size(),
                ExcMessage("The checkpoint holds " + std::to_string(n)
                           + " entries of a vector where this rank owns "
                           + std::to_string(vector.locally_owned_size())
                           + ": it was written for another mesh."));
    archive >> boost::serialization::make_array(vector.begin(), n);
  }


  std::vector<double>
  matrix_values(const LA::MPI::SparseMatrix &A)
  {
    const Epetra_CrsMatrix &matrix = A.trilinos_matrix();
    std::vector<double>     values;
    values.reserve(matrix.NumMyNonzeros());
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n          = 0;
        double *row_values = nullptr;
        matrix.ExtractMyRowView(row, n, row_values);
        values.insert(values.end(), row_values, row_values + n);
      }
    return values;
  }


  void
  set_matrix_values(const std::vector<double> &values, LA::MPI::SparseMatrix &A)
  {
    // The wrapper hands out only a const Epetra matrix; its rows are
    // overwritten in place, which keeps the structure and needs no
    // communication.
    auto &matrix = const_cast<Epetra_CrsMatrix &>(A.trilinos_matrix());
    AssertThrow(values.size() == std::size_t(matrix.NumMyNonzeros()),
                ExcMessage("The checkpoint holds "
                           + std::to_string(values.size())
                           + " matrix entries where this rank has "
                           + std::to_string(matrix.NumMyNonzeros())
                           + ": it was written for another mesh."));
    auto next = values.begin();
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n          = 0;
        double *row_values = nullptr;
        matrix.ExtractMyRowView(row, n, row_values);
        std::copy(next, next + n, row_values);
        next += n;
      }
  }


  void
  Checkpoint::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry(
      "Interval",
      "0",
      Patterns::Integer(0),
      "Write a checkpoint to <Output/Directory>/checkpoint every this many "
      "steps (replacing the previous checkpoint); 0: not by steps. `liftoff "
      "--resume SCENE` continues from it on the same number of ranks.");
    prm.declare_entry(
      "Wall time interval",
      "600",
      Patterns::Double(0.0),
      "Also write one when this many seconds of wall time have passed since "
      "the last one (or the start); 0: not by time. With either interval "
      "above 0 a checkpoint follows the last step too; with both 0 one is "
      "written only when SIGINT or SIGTERM stops the run. Spacing by time "
      "keeps the cost of checkpoints a small share of any run, short steps "
      "or long.");
    prm.leave_subsection();
  }


  void
  Checkpoint::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    interval           = prm.get_integer("Interval");
    wall_time_interval = prm.get_double("Wall time interval");
    prm.leave_subsection();
  }


  bool
  Checkpoint::is_due(const unsigned int step,
                     const bool         is_last_step,
                     const MPI_Comm     comm) const
  {
    if (interval == 0 && wall_time_interval == 0)
      return false;
    if (is_last_step || (interval > 0 && step % interval == 0))
      return true;
    // Clocks differ between ranks: rank 0's decides for all.
    const bool is_time = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - last_written)
                           .count()
                         >= wall_time_interval;
    return wall_time_interval > 0
           && Utilities::MPI::broadcast(comm, is_time, 0);
  }


  std::string
  Checkpoint::comparable_scene(const ParameterHandler &prm)
  {
    std::ostringstream printed;
    prm.print_parameters(printed, ParameterHandler::ShortPRM);
    std::istringstream       in(printed.str());
    std::vector<std::string> path;
    std::string              line, scene;
    while (std::getline(in, line))
      {
        const std::string text = Utilities::trim(line);
        if (text.rfind("subsection ", 0) == 0)
          path.push_back(Utilities::trim(text.substr(11)));
        else if (text == "end" && !path.empty())
          path.pop_back();
        else if (text.rfind("set ", 0) == 0)
          {
            const auto  equals = text.find('=');
            std::string name;
            for (const auto &subsection : path)
              name += subsection + "/";
            name += Utilities::trim(text.substr(4, equals - 4));
            // A resumed run may go further, and checkpoint at other steps.
            if (name == "Time integration/End time"
                || (!path.empty() && path[0] == "Checkpoint"))
              continue;
            scene +=
              name + " = " + Utilities::trim(text.substr(equals + 1)) + "\n";
          }
      }
    return scene;
  }


  void
  Checkpoint::write(const std::string                          &directory,
                    const MPI_Comm                              comm,
                    const unsigned int                          step,
                    const std::string                          &scene,
                    const std::function<void(OutputArchive &)> &save) const
  {
    last_written               = std::chrono::steady_clock::now();
    const std::string target   = directory + "/checkpoint";
    const std::string fresh    = target + ".new";
    const std::string previous = target + ".previous";
    const bool        is_root  = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string what     = "Writing the checkpoint of step "
                             + std::to_string(step) + " to " + target
                             + " failed (the previous one is unchanged)";

    std::string error;
    if (is_root)
      try
        {
          std::filesystem::remove_all(fresh);
          std::filesystem::create_directories(fresh);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    throw_if_any_failed(error, comm, what);

    try
      {
        write_file_atomically(rank_file(fresh, comm), [&](std::ostream &out) {
          OutputArchive archive(out);
          save(archive);
        });
      }
    catch (const std::exception &e)
      {
        error = message_of(e);
      }
    throw_if_any_failed(error, comm, what);

    // The header is written last: a folder without it is incomplete. Then
    // the new folder takes the place of the old one, which goes only after.
    if (is_root)
      try
        {
          write_file_atomically(fresh + "/" + header_name,
                                [&](std::ostream &out) {
                                  out << first_line << '\n'
                                      << "step = " << step << '\n'
                                      << "ranks = "
                                      << Utilities::MPI::n_mpi_processes(comm)
                                      << '\n'
                                      << "scene:\n"
                                      << scene;
                                });
          std::filesystem::remove_all(previous);
          if (std::filesystem::exists(target))
            std::filesystem::rename(target, previous);
          std::filesystem::rename(fresh, target);
          std::filesystem::remove_all(previous);
        }
      catch (const std::exception &e)
        {
          error = message_of(e);
        }
    throw_if_any_failed(error, comm, what);
  }


  unsigned int
  Checkpoint::open(const std::string &directory,
                   const MPI_Comm     comm,
                   const std::string &scene)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    std::string        error;
    unsigned int       step = 0;
    found.clear();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        // A run that died between the two renames of write() left only
        // the previous checkpoint.
        for (const std::string name : {"checkpoint", "checkpoint.previous"})
          if (found.empty()
              && std::filesystem::exists(directory + "/" + name + "/"
                                         + header_name))
            found = directory + "/" + name;

        std::ifstream in(found + "/" + header_name);
        std::string   line, saved_scene;
        unsigned int  saved_ranks = 0;
        if (found.empty())
          error = "there is no checkpoint in " + directory
                  + "/checkpoint. A run writes one every Checkpoint/Wall "
                    "time interval seconds or Checkpoint/Interval steps, "
                    "after its last step and when SIGINT or SIGTERM stops "
                    "it.";
        else if (!std::getline(in, line) || line != first_line
                 || !read_number(in, "step = ", step)
                 || !read_number(in, "ranks = ", saved_ranks)
                 || !std::getline(in, line) || line != "scene:")
          error = found + "/" + header_name + " is not a liftoff checkpoint "
                  + "header.";
        else
          {
            saved_scene.assign(std::istreambuf_iterator<char>(in), {});
            if (saved_ranks != n_ranks)
              error = "the checkpoint in " + found + " was written by "
                      + std::to_string(saved_ranks) + " rank(s); resume it on "
                      + "as many (mpirun -np " + std::to_string(saved_ranks)
                      + "), not " + std::to_string(n_ranks) + ".";
            else if (saved_scene != scene)
              {
                // Name the first parameter that differs.
                std::istringstream a(saved_scene), b(scene);
                std::string        saved_line, scene_line;
                while (std::getline(a, saved_line)
                       && std::getline(b, scene_line)
                       && saved_line == scene_line)
                  ;
                error =
                  "the scene differs from the one the checkpoint in " + found
                  + " was written for (only Time integration/End time "
                    "and the Checkpoint subsection may change): now <"
                  + scene_line + ">, in the checkpoint <" + saved_line + ">.";
              }
          }
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), ExcMessage("Cannot resume: " + error));
    found = Utilities::MPI::broadcast(comm, found, 0);
    step  = Utilities::MPI::broadcast(comm, step, 0);

    const bool has_file = std::filesystem::exists(rank_file(found, comm));
    AssertThrow(Utilities::MPI::min(has_file ? 1 : 0, comm) == 1,
                ExcMessage("Cannot resume: a rank's file is missing in " + found
                           + "."));
    return step;
  }


  void
  Checkpoint::read(const MPI_Comm                             comm,
                   const std::function<void(InputArchive &)> &load) const
  {
    const std::string name = rank_file(found, comm);
    std::ifstream     in(name, std::ios::binary);
    AssertThrow(in, ExcMessage("Cannot read the checkpoint file " + name));
    try
      {
        InputArchive archive(in);
        load(archive);
      }
    catch (const boost::archive::archive_exception &e)
      {
        AssertThrow(false,
                    ExcMessage("The checkpoint file " + name
                               + " is damaged: " + e.what()));
      }
  }
} // namespace liftoff
