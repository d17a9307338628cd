#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>


#include <liftoff/base/archive_types.h>
#include <liftoff/base/linear_algebra.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The files of a checkpoint and when to write one. A checkpoint is a
   * folder `checkpoint` in the output directory: one binary archive per rank
   * (`rank_RRRR.bin`, filled by the caller with that rank's state) and a
   * text header `checkpoint.txt`, written last, with the format number, the
   * step, the number of ranks, each archive's size and CRC-32, the scene,
   * and a last line with the CRC-32 of all the lines before it. It is
   * written as `checkpoint.new` and renamed into place once complete; the
   * previous checkpoint is kept as `checkpoint.previous` until then, so a
   * run that dies while writing leaves one complete checkpoint behind.
   *
   * The archives hold each rank's own degrees of freedom and matrix rows, so
   * a run resumes on the same number of ranks (the mesh, rebuilt from the
   * scene or, for an adaptive run, loaded from the checkpoint's shared
   * files, is then partitioned and numbered the same way); anything else is
   * refused, as is a scene that differs from the checkpoint's in anything
   * but the end time and this subsection, a checkpoint of another format,
   * and any file whose size or checksum differs from the header's.
   */
  class Checkpoint
  {
  public:
    /// The layout of the archives this code writes and reads
    /// (Simulator::serialize()), raised with every change of it, so that a
    /// checkpoint of another layout is refused by its number rather than
    /// misread. A new history column needs none: TimeHistory keeps its
    /// column names and refuses a checkpoint of other columns by name.
    static constexpr unsigned int format = 21;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Whether a checkpoint is written after step `step` without a signal.
    /// Collective (the wall time is rank 0's).
    bool
    is_due(const unsigned int step,
           const bool         is_last_step,
           const MPI_Comm     comm) const;

    /// The scene as "Subsection/Entry = value" lines, without the entries a
    /// resumed run may change.
    static std::string
    comparable_scene(const ParameterHandler &prm);

    /// Files all ranks write together into the checkpoint folder given
    /// (the mesh of an adaptive run); returns their names, which the
    /// header lists with their checksums.
    using SharedFiles =
      std::function<std::vector<std::string>(const std::string &folder)>;

    /// The shared files of an adaptive run's mesh, whose cells the scene
    /// cannot rebuild: `triangulation` saved for
    /// Discretization::load_mesh() from mesh_file().
    static SharedFiles
    mesh_writer(const parallel::distributed::Triangulation<2> &triangulation);

    /// Write a checkpoint of step `step`; `save` fills this rank's archive,
    /// `save_shared` (if given) writes the shared files. Collective; throws
    /// on every rank if any rank fails, and then the previous checkpoint is
    /// untouched.
    void
    write(const std::string                          &directory,
          const MPI_Comm                              comm,
          const unsigned int                          step,
          const std::string                          &scene,
          const std::function<void(OutputArchive &)> &save,
          const SharedFiles                          &save_shared = {}) const;

    /// Find the newest complete checkpoint in `directory`, check its
    /// header against the scene and the number of ranks and every rank's
    /// archive against the header's checksum; returns its step. Writes
    /// nothing, so a refused resume leaves the output as it was. Collective:
    /// throws on every rank if any check fails on any rank.
    unsigned int
    open(const std::string &directory,
         const MPI_Comm     comm,
         const std::string &scene);

    /// The mesh that mesh_writer() saved in the checkpoint open() found.
    std::string
    mesh_file() const;

    /// Read this rank's archive of the checkpoint found by open(), whose
    /// checksum open() has checked on every rank.
    void
    read(const MPI_Comm                             comm,
         const std::function<void(InputArchive &)> &load) const;

  private:
    unsigned int interval           = 0;
    double       wall_time_interval = 600;
    /// When the last checkpoint was written (or the run started).
    mutable std::chrono::steady_clock::time_point last_written =
      std::chrono::steady_clock::now();
    /// The folder open() found.
    std::string found;
  };
} // namespace liftoff
