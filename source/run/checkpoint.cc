#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/serialization/array_wrapper.hpp>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/run/checkpoint.h>

#include <Epetra_CrsMatrix.h>
#include <liftoff/base/output_files.h>

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>

namespace liftoff
{
  namespace
  {
    const std::string header_name = "checkpoint.txt";
    const std::string format_line = "liftoff checkpoint, format ";
    /// Raised whenever what a checkpoint holds or how it is laid out
    /// changes, so that an older checkpoint is refused by name rather than
    /// misread.
    const std::string checksum_label = "crc32 of the lines above = ";

    std::string
    rank_name(const unsigned int rank)
    {
      return "rank_" + Utilities::int_to_string(rank, 4) + ".bin";
    }

    std::string
    rank_file(const std::string &folder, const MPI_Comm comm)
    {
      return folder + "/" + rank_name(Utilities::MPI::this_mpi_process(comm));
    }

    /// The CRC-32 of `n` bytes continuing that of the bytes before them
    /// (`crc`): zlib's, which deal.II links, a few times faster than a
    /// byte-wise table (boost::crc_32_type gives the same values).
    std::uint32_t
    crc_of(const char *data, const std::size_t n, const std::uint32_t crc = 0)
    {
      return crc32(crc, reinterpret_cast<const Bytef *>(data), n);
    }

    /// Size and CRC-32 of a file, as checkpoint.txt records them.
    using FileSum = std::pair<std::uint64_t, std::uint32_t>;

    FileSum
    sum_of_file(const std::string &name)
    {
      std::ifstream in(name, std::ios::binary);
      AssertThrow(in,
                  ExcMessage("the checkpoint file " + name + " is missing."));
      std::uint32_t     crc   = 0;
      std::uint64_t     bytes = 0;
      std::vector<char> buffer(1 << 20);
      while (in)
        {
          in.read(buffer.data(), buffer.size());
          crc = crc_of(buffer.data(), in.gcount(), crc);
          bytes += in.gcount();
        }
      AssertThrow(in.eof(), ExcMessage("Cannot read " + name));
      return {bytes, crc};
    }

    std::string
    describe(const FileSum &sum)
    {
      std::ostringstream text;
      text << sum.first << " bytes, crc32 " << std::hex << std::setw(8)
           << std::setfill('0') << sum.second;
      return text.str();
    }

    /// The last line of checkpoint.txt, after the lines `body`.
    std::string
    checksum_line(const std::string &body)
    {
      std::ostringstream line;
      line << checksum_label << std::hex << std::setw(8) << std::setfill('0')
           << crc_of(body.data(), body.size()) << '\n';
      return line.str();
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
    // A run that died between the two renames of Checkpoint::write() left
    // only the previous checkpoint.
    std::string
    newest_checkpoint(const std::string &directory)
    {
      for (const std::string name : {"checkpoint", "checkpoint.previous"})
        if (std::filesystem::exists(directory + "/" + name + "/" + header_name))
          return directory + "/" + name;
      AssertThrow(false,
                  ExcMessage("there is no checkpoint in " + directory
                             + "/checkpoint. A run writes one every Checkpoint/"
                               "Wall time interval seconds or Checkpoint/"
                               "Interval steps, after its last step and when "
                               "SIGINT or SIGTERM stops it."));
      return "";
    }

    // The lines of a header file before its checksum line, once the format
    // and the checksum are found right.
    std::string
    checked_header_text(const std::string &header)
    {
      std::ifstream     in(header, std::ios::binary);
      const std::string text(std::istreambuf_iterator<char>(in), {});
      const std::string first_line = text.substr(0, text.find('\n'));
      const std::string format     = std::to_string(Checkpoint::format);
      // An older liftoff's checkpoint is named as such, before the checksum
      // (whose line format 1 did not have).
      const std::string written_format =
        first_line.rfind(format_line, 0) == 0
          ? first_line.substr(format_line.size())
          : "";
      AssertThrow(written_format.empty() || written_format == format
                    || written_format.find_first_not_of("0123456789")
                         != std::string::npos,
                  ExcMessage(
                    header + " is of checkpoint format " + written_format
                    + ", written by another liftoff that this one "
                      "(format "
                    + format + ") does not read; run the scene " + "again."));
      // The last line is the checksum of everything before it.
      const auto last =
        text.size() > 1 ? text.rfind('\n', text.size() - 2) : std::string::npos;
      const std::string body = text.substr(0, last + 1);
      AssertThrow(last != std::string::npos && text.back() == '\n'
                    && text.substr(last + 1) == checksum_line(body),
                  ExcMessage(header + " is damaged (its contents do not match "
                             + "its checksum) or not a liftoff checkpoint."));
      AssertThrow(first_line == format_line + format,
                  ExcMessage(header + " says <" + first_line + ">; this "
                             + "liftoff reads format " + format + " only."));
      return body;
    }

    struct Header
    {
      unsigned int         step = 0;
      std::vector<FileSum> sums;
      /// Files shared by all ranks (the mesh of an adaptive run), by name.
      std::vector<std::pair<std::string, FileSum>> shared_files;
      std::string                                  scene;
    };

    const std::string shared_file_label = "file ";

    Header
    read_header(const std::string &header)
    {
      const std::string  body = checked_header_text(header);
      std::istringstream lines(body.substr(body.find('\n') + 1));
      Header             result;
      unsigned int       saved_ranks = 0;
      std::string        line;
      bool               is_header = read_number(lines, "step = ", result.step)
                       && read_number(lines, "ranks = ", saved_ranks);
      for (unsigned int r = 0; is_header && r < saved_ranks; ++r)
        {
          FileSum     sum;
          std::string name, equals, bytes, label;
          is_header = std::getline(lines, line).good();
          std::istringstream entry(line);
          entry >> name >> equals >> sum.first >> bytes >> label >> std::hex
            >> sum.second;
          is_header = is_header && entry && name == rank_name(r);
          result.sums.push_back(sum);
        }
      while (is_header && std::getline(lines, line)
             && line.rfind(shared_file_label, 0) == 0)
        {
          FileSum            sum;
          std::string        name, equals, bytes, label;
          std::istringstream entry(line.substr(shared_file_label.size()));
          entry >> name >> equals >> sum.first >> bytes >> label >> std::hex
            >> sum.second;
          is_header =
            entry && equals == "=" && name.find('/') == std::string::npos;
          result.shared_files.emplace_back(name, sum);
        }
      is_header = is_header && line == "scene:";
      AssertThrow(is_header,
                  ExcMessage(header + " is not a liftoff checkpoint header."));
      result.scene.assign(std::istreambuf_iterator<char>(lines), {});
      return result;
    }

    // Refuse a scene other than the checkpoint's, naming the first
    // parameter that differs.
    void
    require_same_scene(const std::string &saved_scene,
                       const std::string &scene,
                       const std::string &found)
    {
      if (saved_scene == scene)
        return;
      std::istringstream a(saved_scene), b(scene);
      std::string        saved_line, scene_line;
      while (std::getline(a, saved_line) && std::getline(b, scene_line)
             && saved_line == scene_line)
        ;
      AssertThrow(false,
                  ExcMessage("the scene differs from the one the checkpoint "
                             "in "
                             + found
                             + " was written for (only Time integration/End "
                               "time and the Checkpoint subsection may "
                               "change): now <"
                             + scene_line + ">, in the checkpoint <"
                             + saved_line + ">."));
    }


    // The header of the checkpoint in `folder`: format, step, every file
    // with its checksum, and the scene.
    std::string
    header_text(const std::string              &folder,
                const unsigned int              step,
                const std::vector<FileSum>     &sums,
                const std::vector<std::string> &shared_names,
                const std::string              &scene)
    {
      std::ostringstream header;
      header << format_line << Checkpoint::format << '\n'
             << "step = " << step << '\n'
             << "ranks = " << sums.size() << '\n';
      for (unsigned int r = 0; r < sums.size(); ++r)
        header << rank_name(r) << " = " << describe(sums[r]) << '\n';
      for (const auto &name : shared_names)
        header << shared_file_label << name << " = "
               << describe(sum_of_file(folder + "/" + name)) << '\n';
      header << "scene:\n" << scene;
      return header.str();
    }
  } // namespace


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
      "or long."
        + quantity("number"));
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
    // ParameterHandler's own tree, read back from its JSON form: leaves are
    // entries, every other node a subsection.
    std::stringstream json;
    prm.print_parameters(json, ParameterHandler::ShortJSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);

    std::string scene;
    const std::function<void(const boost::property_tree::ptree &,
                             const std::string &)>
      collect =
        [&](const boost::property_tree::ptree &node, const std::string &path) {
          for (const auto &[key, child] : node)
            {
              const std::string name = path + key;
              // What a resume may change: how far to run, where and how
              // often to checkpoint, how much iteration to allow before
              // giving up, and the energy check; none of these changes a
              // step the run has made. The folder is the one the resumed
              // scene names, wherever it has been moved.
              if (name == "Time integration/End time" || name == "Checkpoint"
                  || name == "Output/Directory"
                  || name == "Active set/Maximum iterations"
                  || name == "Energy check")
                continue;
              // ShortJSON writes an entry as "name": "value", the full
              // form as an object with a "value".
              if (child.empty())
                scene += name + " = " + child.data() + "\n";
              else if (const auto value =
                         child.get_optional<std::string>("value"))
                scene += name + " = " + *value + "\n";
              else
                collect(child, name + "/");
            }
        };
    collect(tree, "");
    return scene;
  }


  void
  Checkpoint::write(const std::string                          &directory,
                    const MPI_Comm                              comm,
                    const unsigned int                          step,
                    const std::string                          &scene,
                    const std::function<void(OutputArchive &)> &save,
                    const SharedFiles &save_shared) const
  {
    last_written               = std::chrono::steady_clock::now();
    const std::string target   = directory + "/checkpoint";
    const std::string fresh    = target + ".new";
    const std::string previous = target + ".previous";
    const bool        is_root  = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string what     = "Writing the checkpoint of step "
                             + std::to_string(step) + " to " + target
                             + " failed (the previous one is unchanged)";

    collective_attempt(comm, what, [&]() {
      if (is_root)
        {
          std::filesystem::remove_all(fresh);
          std::filesystem::create_directories(fresh);
        }
    });

    // Files the ranks write together (Triangulation::save): collective.
    std::vector<std::string> shared_names;
    if (save_shared)
      collective_attempt(comm, what, [&]() {
        shared_names = save_shared(fresh);
      });

    // Each file's checksum is taken from what is on the disk.
    FileSum sum;
    collective_attempt(comm, what, [&]() {
      write_file_atomically(rank_file(fresh, comm), [&](std::ostream &out) {
        OutputArchive archive(out);
        save(archive);
      });
      sum = sum_of_file(rank_file(fresh, comm));
    });
    const std::vector<FileSum> sums = Utilities::MPI::gather(comm, sum, 0);

    // The header is written last: a folder without it is incomplete. Then
    // the new folder takes the place of the old one, which goes only after.
    collective_attempt(comm, what, [&]() {
      if (!is_root)
        return;
      write_file_atomically(fresh + "/" + header_name, [&](std::ostream &out) {
        const std::string header =
          header_text(fresh, step, sums, shared_names, scene);
        out << header << checksum_line(header);
      });
      std::filesystem::remove_all(previous);
      if (std::filesystem::exists(target))
        std::filesystem::rename(target, previous);
      std::filesystem::rename(fresh, target);
      std::filesystem::remove_all(previous);
    });
  }


  unsigned int
  Checkpoint::open(const std::string &directory,
                   const MPI_Comm     comm,
                   const std::string &scene)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    Header             header;
    found.clear();
    collective_attempt(comm, "Cannot resume", [&]() {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      found  = newest_checkpoint(directory);
      header = read_header(found + "/" + header_name);
      AssertThrow(header.sums.size() == n_ranks,
                  ExcMessage("the checkpoint in " + found + " was written by "
                             + std::to_string(header.sums.size())
                             + " rank(s); resume it on as many (mpirun -np "
                             + std::to_string(header.sums.size()) + "), not "
                             + std::to_string(n_ranks) + "."));
      require_same_scene(header.scene, scene, found);
      for (const auto &[name, saved] : header.shared_files)
        {
          const FileSum now = sum_of_file(found + "/" + name);
          AssertThrow(now == saved,
                      ExcMessage("the checkpoint file " + found + "/" + name
                                 + " is damaged: " + describe(now) + " where "
                                 + header_name + " records " + describe(saved)
                                 + "."));
        }
    });
    found       = Utilities::MPI::broadcast(comm, found, 0);
    header.step = Utilities::MPI::broadcast(comm, header.step, 0);
    header.sums = Utilities::MPI::broadcast(comm, header.sums, 0);

    // Every rank checks its own file before any rank reads one: a damaged
    // file must stop all ranks here, not one of them halfway through
    // restoring the state, which communicates.
    collective_attempt(comm, "Cannot resume", [&]() {
      const std::string name = rank_file(found, comm);
      const FileSum saved = header.sums[Utilities::MPI::this_mpi_process(comm)];
      const FileSum now   = sum_of_file(name);
      AssertThrow(now == saved,
                  ExcMessage("the checkpoint file " + name + " is damaged: "
                             + describe(now) + " where " + header_name
                             + " records " + describe(saved) + "."));
    });
    return header.step;
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


  namespace
  {
    // The name of an adaptive run's mesh in its checkpoint folder.
    const std::string mesh_name = "mesh";
  } // namespace


  Checkpoint::SharedFiles
  Checkpoint::mesh_writer(
    const parallel::distributed::Triangulation<2> &triangulation)
  {
    return [&triangulation](const std::string &folder) {
      triangulation.save(folder + "/" + mesh_name);
      // deal.II writes "mesh", "mesh.info" and, with cell data, more.
      std::vector<std::string> names;
      for (const auto &entry : std::filesystem::directory_iterator(folder))
        if (entry.path().filename().string().rfind(mesh_name, 0) == 0)
          names.push_back(entry.path().filename().string());
      std::sort(names.begin(), names.end());
      return names;
    };
  }


  std::string
  Checkpoint::mesh_file() const
  {
    return found + "/" + mesh_name;
  }
} // namespace liftoff
