#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/output_files.h>
#include <liftoff/run/output_directory.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <regex>

namespace liftoff
{
  using namespace dealii;

  namespace
  {
    namespace fs = std::filesystem;

    const std::string lock_name = "liftoff.lock";

    /// What the lock file holds back for the summary files (each a few
    /// hundred bytes, written under a temporary name first): two blocks of
    /// up to 8 KiB.
    constexpr off_t summary_space = 16 * 1024;

    // The names that Simulator, RunSummary, TimeHistory, ProfileOutput,
    // FieldOutput (with the dowels' files) and Checkpoint write, with their
    // temporary names (write_file_atomically).
    const std::regex file_names(
      R"((used_parameters\.prm|summary\.txt|summary\.json|history\.csv|)"
      R"(profiles\.csv|(solution|dowels)\.pvd|solution_[0-9]+\.pvtu|)"
      R"(solution_[0-9]+\.[0-9]+\.vtu|dowels_[0-9]+\.vtu|solution\.xdmf|)"
      R"(solution_[0-9]+\.h5))"
      R"((\.tmp)?)");
    const std::regex checkpoint_folders(R"(checkpoint(\.new|\.previous)?)");
    const std::regex
      checkpoint_files(R"((checkpoint\.txt|rank_[0-9]+\.bin)(\.tmp)?)");
    /// A field file and its step.
    const std::regex
      field_file(R"((?:solution|dowels)_([0-9]+)\.(pvtu|[0-9]+\.vtu|vtu|h5))");

    bool
    matches(const fs::directory_entry &entry, const std::regex &names)
    {
      return std::regex_match(entry.path().filename().string(), names);
    }

    /// liftoff's files in `folder`, then those in its checkpoint folders,
    /// then these folders (which go only when they are empty of anything
    /// else).
    std::vector<fs::path>
    liftoff_entries(const std::string &folder)
    {
      std::vector<fs::path> files, inner_files, folders;
      if (!fs::is_directory(folder))
        return files;
      for (const auto &entry : fs::directory_iterator(folder))
        if (entry.is_regular_file() && matches(entry, file_names))
          files.push_back(entry.path());
        else if (entry.is_directory() && matches(entry, checkpoint_folders))
          {
            folders.push_back(entry.path());
            for (const auto &inner : fs::directory_iterator(entry.path()))
              if (inner.is_regular_file() && matches(inner, checkpoint_files))
                inner_files.push_back(inner.path());
          }
      for (auto *list : {&files, &inner_files, &folders})
        std::sort(list->begin(), list->end());
      files.insert(files.end(), inner_files.begin(), inner_files.end());
      files.insert(files.end(), folders.begin(), folders.end());
      return files;
    }


    std::string
    host_name()
    {
      char name[256] = {};
      return gethostname(name, sizeof(name) - 1) == 0 ? name : "unknown";
    }

    /// Name this process in the lock file, for the message of a refused
    /// run; the lock holds without it (a full disk). Whatever the file held
    /// goes, and with it the space kept for the summary.
    void
    write_holder(const int descriptor)
    {
      const std::string holder =
        "pid " + std::to_string(getpid()) + " on host " + host_name() + "\n";
      const bool is_written =
        ftruncate(descriptor, 0) == 0
        && pwrite(descriptor, holder.data(), holder.size(), 0)
             == static_cast<ssize_t>(holder.size());
      (void)is_written;
    }


    /// Lock `folder`/liftoff.lock and write pid and host into it; returns
    /// the descriptor that holds the lock.
    int
    lock(const std::string &folder)
    {
      const std::string name = folder + "/" + lock_name;
      for (unsigned int attempt = 0; attempt < 100; ++attempt)
        {
          const int descriptor =
            open(name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
          AssertThrow(descriptor >= 0,
                      ExcMessage("cannot create the lock file " + name + ": "
                                 + std::strerror(errno)));
          if (flock(descriptor, LOCK_EX | LOCK_NB) != 0)
            {
              const int error = errno;
              if (error != EWOULDBLOCK)
                {
                  // A file system without flock (Lustre mounted with
                  // noflock): run, but say that the folder is unguarded.
                  std::cerr << "liftoff: warning: cannot lock " << name << " ("
                            << std::strerror(error)
                            << "); another run into this folder would not "
                               "be refused."
                            << std::endl;
                  return descriptor;
                }
              std::string holder(256, '\0');
              const auto n = pread(descriptor, holder.data(), holder.size(), 0);
              holder.resize(n > 0 ? n : 0);
              close(descriptor);
              holder = Utilities::trim(holder);
              AssertThrow(false,
                          ExcMessage("another liftoff run ("
                                     + (holder.empty() ? "starting" : holder)
                                     + ") is writing to it; wait for it to "
                                       "end or choose another directory."));
            }
          // A holder that ended may have removed the file between open()
          // and flock(): then the lock is on a file nobody else sees.
          struct stat opened, named;
          if (fstat(descriptor, &opened) == 0 && stat(name.c_str(), &named) == 0
              && opened.st_ino == named.st_ino && opened.st_dev == named.st_dev)
            {
              write_holder(descriptor);
              return descriptor;
            }
          close(descriptor);
        }
      AssertThrow(false, ExcMessage("cannot lock " + name));
      return -1;
    }
  } // namespace


  void
  OutputDirectory::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry(
      "Directory",
      "output",
      dealii::Patterns::Anything(),
      "Folder for all results, created if needed (empty: write "
      "no files); output-NAME for a scene file NAME.prm, output "
      "for a scene from standard input. A run owns it while it runs and "
      "refuses it "
      "if it holds an earlier run's results, unless started "
      "with `liftoff --overwrite` (which removes them) or "
      "`--resume`. Only the files liftoff writes are ever "
      "touched. `#` starts a comment in a parameter file, "
      "so a name cannot hold it: `run#3` is read as `run`."
        + quantity("text"));
  }


  void
  OutputDirectory::name_after_scene(dealii::ParameterHandler &prm,
                                    const std::string        &scene_file)
  {
    if (scene_file == "-")
      return;
    std::string name = std::filesystem::path(scene_file).filename().string();
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".prm") == 0)
      name.resize(name.size() - 4);
    // `#` would start a comment in used_parameters.prm.
    if (name.empty() || name.find('#') != std::string::npos)
      return;
    prm.enter_subsection("Output");
    prm.set("Directory", "output-" + name);
    prm.leave_subsection();
  }


  OutputDirectory::OutputDirectory(const std::string &folder,
                                   const MPI_Comm     communicator,
                                   const bool         create)
      : path(folder)
      , comm(communicator)
  {
    collective_attempt(comm,
                       "Output/Directory = " + path + " cannot be written",
                       [&]() {
                         if (Utilities::MPI::this_mpi_process(comm) != 0)
                           return;
                         if (create)
                           fs::create_directories(path);
                         if (fs::is_directory(path))
                           lock_descriptor = lock(path);
                         keep_space_for_summary();
                       });
  }


  void
  OutputDirectory::keep_space_for_summary()
  {
    if (lock_descriptor < 0)
      return;
    // Blocks allocated beyond the end of the lock file: it still reads as
    // the holder's line. File systems without fallocate(2) (NFS) keep
    // nothing back.
    if (fallocate(lock_descriptor, FALLOC_FL_KEEP_SIZE, 0, summary_space) == 0
        || errno != ENOSPC)
      return;
    unlink((path + "/" + lock_name).c_str());
    close(lock_descriptor);
    lock_descriptor = -1;
    AssertThrow(false,
                ExcMessage("its disk has less than "
                           + std::to_string(summary_space / 1024)
                           + " KiB free, which a run keeps for summary.txt "
                             "and summary.json until it ends."));
  }


  void
  OutputDirectory::release_space_for_summary() const
  {
    if (lock_descriptor >= 0)
      write_holder(lock_descriptor);
  }


  OutputDirectory::~OutputDirectory()
  {
    if (lock_descriptor < 0)
      return;
    // Removed while still locked: a run that opened it meanwhile finds,
    // once it has the lock, that the name is gone, and tries again.
    unlink((path + "/" + lock_name).c_str());
    close(lock_descriptor);
  }


  std::vector<std::string>
  OutputDirectory::results() const
  {
    std::vector<std::string> names;
    for (const auto &entry : liftoff_entries(path))
      names.push_back(fs::relative(entry, path).string());
    return names;
  }


  void
  OutputDirectory::refuse_earlier_results() const
  {
    collective_attempt(comm, "", [&]() {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      const auto names = results();
      if (names.empty())
        return;
      std::string listed;
      for (unsigned int i = 0; i < std::min<std::size_t>(3, names.size()); ++i)
        listed += (i > 0 ? ", " : "") + names[i];
      if (names.size() > 3)
        listed += " and " + std::to_string(names.size() - 3) + " more";
      AssertThrow(false,
                  ExcMessage(
                    "Output/Directory = " + path
                    + " holds the results of an earlier run (" + listed
                    + "). A run does not mix its files with another's: "
                      "`liftoff --overwrite SCENE` replaces them, `liftoff "
                      "--resume SCENE` continues that run from its "
                      "checkpoint; or choose another directory."));
    });
  }


  void
  OutputDirectory::remove_earlier_results() const
  {
    collective_attempt(comm,
                       "Removing the earlier results in Output/Directory = "
                         + path + " failed",
                       [&]() {
                         if (Utilities::MPI::this_mpi_process(comm) != 0)
                           return;
                         for (const auto &entry : liftoff_entries(path))
                           {
                             // A checkpoint folder stays if it holds
                             // something else.
                             std::error_code not_empty;
                             if (fs::is_directory(entry))
                               fs::remove(entry, not_empty);
                             else
                               fs::remove(entry);
                           }
                       });
  }


  void
  OutputDirectory::remove_temporary_files() const
  {
    collective_attempt(comm, "Output/Directory = " + path, [&]() {
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        for (const auto &entry : liftoff_entries(path))
          if (entry.extension() == ".tmp")
            fs::remove(entry);
    });
  }


  void
  OutputDirectory::write_used_parameters(const std::string &parameters) const
  {
    collective_attempt(
      comm, "Output/Directory = " + path + " cannot be written", [&]() {
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          write_file_atomically(path + "/used_parameters.prm",
                                [&](std::ostream &out) { out << parameters; });
      });
  }


  void
  OutputDirectory::remove_summary() const
  {
    collective_attempt(comm, "Output/Directory = " + path, [&]() {
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        for (const char *name : {"/summary.txt", "/summary.json"})
          fs::remove(path + name);
    });
  }


  void
  OutputDirectory::remove_fields_after(const unsigned int step) const
  {
    collective_attempt(comm, "Output/Directory = " + path, [&]() {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      for (const auto &entry : liftoff_entries(path))
        {
          const std::string name = entry.filename().string();
          std::smatch       field;
          if (std::regex_match(name, field, field_file)
              && std::stoull(field[1]) > step)
            fs::remove(entry);
        }
    });
  }
} // namespace liftoff
