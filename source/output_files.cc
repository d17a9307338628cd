#include <deal.II/base/exceptions.h>

#include <liftoff/output_files.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

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


  void
  remove_temporary_files(const std::string &directory)
  {
    std::vector<std::filesystem::path> leftovers;
    for (const auto &entry :
         std::filesystem::recursive_directory_iterator(directory))
      if (entry.is_regular_file() && entry.path().extension() == ".tmp")
        leftovers.push_back(entry.path());
    for (const auto &path : leftovers)
      std::filesystem::remove(path);
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
  GrowingTextFile::open(const std::string &file_path,
                        const double       interval_seconds)
  {
    path     = file_path;
    interval = interval_seconds;
    contents.str("");
    since_written.restart();
  }


  std::ostream &
  GrowingTextFile::stream()
  {
    return contents;
  }


  void
  GrowingTextFile::write_if_due()
  {
    if (since_written.wall_time() >= interval)
      flush();
  }


  void
  GrowingTextFile::flush()
  {
    if (path.empty())
      return;
    write_file_atomically(path,
                          [&](std::ostream &out) { out << contents.str(); });
    since_written.restart();
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
