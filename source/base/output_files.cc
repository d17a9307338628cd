#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <liftoff/base/output_files.h>

#include <cstdio>
#include <fstream>

namespace liftoff
{
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".tmp";
    bool              written   = false;
    {
      std::ofstream out(temporary);
      AssertThrow(out,
                  dealii::ExcMessage("Cannot write the file " + temporary));
      try
        {
          write(out);
          out.close();
          written = static_cast<bool>(out);
        }
      catch (...)
        {
          // The writer gave up on a failing stream (deal.II's DataOut
          // does); handled as a failed write below.
        }
    }
    if (!written)
      {
        // A full disk or a file size limit: leave no partial file behind.
        std::remove(temporary.c_str());
        AssertThrow(false,
                    dealii::ExcMessage("Writing " + path
                                       + " failed (disk full or file too "
                                         "large?); the previous version, if "
                                         "any, is unchanged."));
      }
    AssertThrow(std::rename(temporary.c_str(), path.c_str()) == 0,
                dealii::ExcMessage("Cannot rename " + temporary + " to "
                                   + path));
  }


  std::string
  message_of(const std::exception &e)
  {
    if (const auto *deal_ii = dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        std::ostringstream text;
        deal_ii->print_info(text);
        // print_info indents and ends the text; keep the words.
        std::string message = text.str();
        message.erase(0, message.find_first_not_of(" \n"));
        message.erase(message.find_last_not_of(" \n") + 1);
        return message;
      }
    return e.what();
  }


  void
  collective_attempt(const MPI_Comm               comm,
                     const std::string           &what,
                     const std::function<void()> &attempt)
  {
    std::string error;
    try
      {
        attempt();
      }
    catch (const std::exception &e)
      {
        error = message_of(e);
      }
    catch (...)
      {
        error = "an unknown error";
      }
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int first   = dealii::Utilities::MPI::min(
      error.empty() ? n_ranks : dealii::Utilities::MPI::this_mpi_process(comm),
      comm);
    if (first == n_ranks)
      return;
    error = dealii::Utilities::MPI::broadcast(comm, error, first);
    AssertThrow(false,
                dealii::ExcMessage(what.empty() ? error : what + ": " + error));
  }


  void
  GrowingTextFile::open(const std::string &file_path,
                        const double       interval_seconds,
                        const MPI_Comm     communicator)
  {
    path     = file_path;
    interval = interval_seconds;
    comm     = communicator;
    is_writer =
      !path.empty() && dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    is_held = false;
    contents.str("");
    since_written.restart();
  }


  std::ostream &
  GrowingTextFile::stream()
  {
    return is_writer ? contents : discarded;
  }


  void
  GrowingTextFile::write_if_due()
  {
    // Rank 0's clock decides; the others take part in case the write fails.
    write(!is_held && since_written.wall_time() >= interval);
  }


  void
  GrowingTextFile::flush()
  {
    is_held = false;
    write(true);
  }


  void
  GrowingTextFile::write(const bool is_due)
  {
    if (path.empty())
      return;
    collective_attempt(comm, "", [&]() {
      if (is_writer && is_due)
        write_file_atomically(path, [&](std::ostream &out) {
          out << contents.str();
        });
    });
    if (is_due)
      since_written.restart();
  }


  void
  GrowingTextFile::hold()
  {
    is_held = true;
  }


  std::string
  GrowingTextFile::text() const
  {
    return contents.str();
  }


  void
  GrowingTextFile::replace(const std::string &text)
  {
    contents.str("");
    contents << text;
  }
} // namespace liftoff
