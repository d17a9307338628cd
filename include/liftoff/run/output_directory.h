#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace liftoff
{
  /**
   * The output folder of a run, which the run owns while it runs, and the
   * one place that knows which of the folder's entries are liftoff's.
   *
   * Ownership: rank 0 holds an exclusive flock(2) on `liftoff.lock` in the
   * folder, a file naming its pid and host. The kernel releases the lock
   * when the process ends however it ends, so the file a killed run leaves
   * behind does not count; another liftoff (a second run, a resume) is
   * refused with the holder's pid and host while it is held. On a file
   * system without flock the run goes on with a warning that the folder is
   * unguarded. The lock file also holds back 16 KiB of disk (allocated
   * beyond its end) until the summary is written, so that a disk that fills
   * during the run still takes the summary saying that the run failed; a
   * disk with less free space is refused at the start.
   *
   * liftoff's entries are the files it writes (used_parameters.prm,
   * summary.txt, history.csv, profiles.csv, solution.pvd,
   * solution_NNNNN.pvtu, solution_NNNNN.RRRR.vtu, solution.xdmf,
   * solution_NNNNN.h5, and within the folders
   * checkpoint, checkpoint.new and checkpoint.previous checkpoint.txt and
   * rank_RRRR.bin) and the temporary `<name>.tmp` of each. Nothing else in
   * the folder is ever counted, removed or overwritten.
   *
   * Every member is collective and throws on all ranks if it fails.
   */
  class OutputDirectory
  {
  public:
    /// `Directory`, the folder's name, in the subsection `Output`.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Makes output-NAME the Directory of the scene file `scene_file`
    /// (.../NAME.prm) unless the scene sets one: two scenes run side by
    /// side never share a folder. A scene from standard input ("-") keeps
    /// `output`. Called after declare_parameters(), before the scene is
    /// read.
    static void
    name_after_scene(dealii::ParameterHandler &prm,
                     const std::string        &scene_file);

    /// Lock the folder `path`, creating it if `create`; a folder that does
    /// not exist and is not created is not locked (there is nothing in it
    /// to protect).
    OutputDirectory(const std::string &path,
                    const MPI_Comm     comm,
                    const bool         create);
    /// Release the lock and remove the lock file (rank 0 only; no
    /// communication, so it is safe while an exception unwinds).
    ~OutputDirectory();

    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &
    operator=(const OutputDirectory &) = delete;

    /// Refuse a folder that holds results of an earlier run, naming them:
    /// a new run must not mix its files with another run's.
    void
    refuse_earlier_results() const;

    /// Remove the results of an earlier run (`liftoff --overwrite`).
    void
    remove_earlier_results() const;

    /// Remove the temporary files a killed run left (`liftoff --resume`).
    void
    remove_temporary_files() const;

    /// What a resumed run removes once it has a step of its own: the
    /// summary of the run it continues, and (once its own PVD file no longer
    /// lists them) the field files of steps after `step`, which that run
    /// wrote and this one has not yet.
    void
    remove_summary() const;
    void
    remove_fields_after(const unsigned int step) const;

    /// Give back the disk space held for the summary since the folder was
    /// locked, just before the summary is written: a disk that another
    /// program (or the run's own files) filled meanwhile still takes a
    /// summary that says the run failed. Rank 0 only; no communication.
    void
    release_space_for_summary() const;

    /// used_parameters.prm: the parameters of the run as it read them,
    /// replaced atomically from rank 0.
    void
    write_used_parameters(const std::string &parameters) const;

  private:
    std::string path;
    MPI_Comm    comm;
    /// The locked file's descriptor on rank 0, or -1.
    int lock_descriptor = -1;

    /// Allocate the summary's space in the lock file (rank 0); refuse a
    /// disk without it.
    void
    keep_space_for_summary();

    /// liftoff's entries of the folder, relative to it (rank 0).
    std::vector<std::string>
    results() const;
  };
} // namespace liftoff
