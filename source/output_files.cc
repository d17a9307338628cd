#include <deal.II/base/exceptions.h>

#include <liftoff/output_files.h>

#include <cstdio>
#include <fstream>

namespace liftoff
{
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".tmp";
    {
      std::ofstream out(temporary);
      AssertThrow(out,
                  dealii::ExcMessage("Cannot write the file " + temporary));
      write(out);
      out.flush();
      AssertThrow(out, dealii::ExcMessage("Writing " + temporary + " failed."));
    }
    AssertThrow(std::rename(temporary.c_str(), path.c_str()) == 0,
                dealii::ExcMessage("Cannot rename " + temporary + " to "
                                   + path));
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
} // namespace liftoff
