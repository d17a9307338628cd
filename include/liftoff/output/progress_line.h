#pragma once

#include <deal.II/base/mpi.h>

#include <liftoff/base/physical_units.h>
#include <liftoff/output/output.h>

#include <chrono>
#include <ostream>

namespace liftoff
{
  using namespace dealii;

  /**
   * The line a user watches during a run: step, tau, active-set iterations,
   * contact fraction, wall time so far and an estimate of the time left,
   * at most once a second. On a terminal it is rewritten in place; into a
   * file or pipe it is one line per update, so a log keeps the course of a
   * run. Rank 0 writes it from StepData alone: execute() makes no
   * collective call, so it may return early on the other ranks.
   */
  class ProgressLine : public Output
  {
  public:
    ProgressLine(const MPI_Comm comm, std::ostream &out);

    /// Show the time in the scene's units (t in s for an SI scene).
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;

    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &scene) override;
    void
    execute(const StepData &step) override;
    /// Ends the line on a terminal, so that what follows starts on its own.
    void
    flush() override;
    /// A progress line has nothing to resume.
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

  private:
    using Clock = std::chrono::steady_clock;

    PhysicalUnits     units;
    std::ostream     &out;
    const bool        is_root;
    const bool        is_terminal;
    Clock::time_point start, last_shown;
    /// The first step this run computes (a resumed run starts later).
    unsigned int first_step  = 0;
    bool         has_started = false;
    /// Whether a line is open on the terminal.
    bool is_open = false;
  };
} // namespace liftoff
