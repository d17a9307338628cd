#include <liftoff/base/archives.h>
#include <liftoff/output/progress_line.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/time/plate_state.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace liftoff
{
  namespace
  {
    std::string
    duration(const double seconds)
    {
      std::ostringstream text;
      if (seconds < 60)
        text << std::fixed << std::setprecision(1) << seconds << " s";
      else if (seconds < 3600)
        text << int(seconds / 60) << " min " << int(seconds) % 60 << " s";
      else
        text << int(seconds / 3600) << " h " << int(seconds / 60) % 60
             << " min";
      return text.str();
    }

    // mpirun hands its ranks a pseudo-terminal even when its own output
    // goes to a file, so a rank cannot tell; lines then suit both.
    bool
    is_under_mpirun(const MPI_Comm comm)
    {
      return Utilities::MPI::n_mpi_processes(comm) > 1
             || std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr
             || std::getenv("PMI_SIZE") != nullptr;
    }
  } // namespace


  ProgressLine::ProgressLine(const MPI_Comm comm, std::ostream &out)
      : out(out)
      , is_root(Utilities::MPI::this_mpi_process(comm) == 0)
      , is_terminal(is_root && &out == &std::cout && isatty(STDOUT_FILENO)
                    && !is_under_mpirun(comm))
  {}


  void
  ProgressLine::setup(const SceneView &, const std::string &)
  {
    start       = Clock::now();
    last_shown  = start;
    has_started = false;
  }


  void
  ProgressLine::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  void
  ProgressLine::mesh_changed(const SceneView &)
  {}


  void
  ProgressLine::execute(const StepData &step)
  {
    // The row of tau = 0 (or of the checkpoint) is where timing starts.
    if (!has_started)
      {
        has_started = true;
        first_step  = step.state.clock.step();
        return;
      }
    const Clock::time_point now = Clock::now();
    if (!is_root
        || (!step.state.clock.is_at_end()
            && std::chrono::duration<double>(now - last_shown).count() < 1.0))
      return;
    last_shown           = now;
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const unsigned int done = step.state.clock.step() - first_step;
    const unsigned int left =
      step.state.clock.n_steps() - step.state.clock.step();

    std::ostringstream line;
    line << "step " << step.state.clock.step() << "/"
         << step.state.clock.n_steps()
         << (units.is_physical() ? "  t " : "  tau ") << std::setprecision(6)
         << units.scale(PhysicalUnits::Quantity::time) * step.state.clock.tau()
         << (units.is_physical() ? " s" : "") << "  iterations "
         << step.iteration.iterations << "  contact " << std::fixed
         << std::setprecision(3) << step.contact_fraction << "  elapsed "
         << duration(elapsed);
    if (left > 0)
      line << "  left ~" << duration(elapsed / done * left);
    if (is_terminal)
      {
        // Pad over the end of a longer previous line.
        out << '\r' << std::left << std::setw(100) << line.str() << std::flush;
        is_open = true;
      }
    else
      out << line.str() << std::endl;
  }


  void
  ProgressLine::flush()
  {
    if (is_open)
      out << std::endl;
    is_open = false;
  }


  void
  ProgressLine::save(OutputArchive &) const
  {}


  void
  ProgressLine::load(InputArchive &)
  {}
} // namespace liftoff
