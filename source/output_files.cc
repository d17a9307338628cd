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
} // namespace liftoff
