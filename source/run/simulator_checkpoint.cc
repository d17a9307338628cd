#include <liftoff/base/archives.h>
#include <liftoff/base/number_text.h>
#include <liftoff/run/simulator.h>

// The Simulator's checkpoints (as ASPECT keeps its checkpoint_restart.cc
// apart): opening one to resume, reading the state back, writing one when
// due, and the one list of what a checkpoint holds.
namespace liftoff
{
  unsigned int
  Simulator::open_checkpoint()
  {
    // Everything is checked before a file is touched: a refused resume
    // leaves the output of the earlier run as it was.
    const unsigned int step =
      checkpoint.open(output_directory, mpi_communicator, scene);
    const Clock &clock = stepper->state().clock;
    AssertThrow(step <= clock.n_steps(),
                ExcMessage("Cannot resume: the checkpoint is of step "
                           + std::to_string(step)
                           + ", beyond Time integration/End time = <"
                           + format_number(clock.end_time()) + "> ("
                           + std::to_string(clock.n_steps()) + " steps)."));
    // A killed run may leave temporary files (and checkpoint.new).
    output_folder->remove_temporary_files();
    return step;
  }


  void
  Simulator::resume_from_checkpoint()
  {
    SectionTimer::Scope t(timer, "checkpoint");
    if (parts.mesh_refinement.is_enabled())
      {
        // The run's mesh is the checkpoint's; everything on it is rebuilt
        // before the state is read into it.
        parts.discretization.load_mesh(checkpoint.mesh_file());
        stepper->setup();
        find_points_on_new_mesh();
      }
    checkpoint.read(mpi_communicator, [&](InputArchive &archive) {
      serialize(archive, Checkpoint::format);
    });
    const unsigned int step = stepper->state().clock.step();
    AssertThrow(step == resume_step && history().size() == resume_step + 1,
                ExcMessage("The checkpoint of step "
                           + std::to_string(resume_step) + " holds step "
                           + std::to_string(step) + " and "
                           + std::to_string(history().size()) + " rows."));
    pcout << "resumed after step " << resume_step << std::endl;
  }


  void
  Simulator::write_checkpoint_if_due(const bool is_stopping)
  {
    const Clock &clock = stepper->state().clock;
    if (!writes_files()
        || !(is_stopping
             || checkpoint.is_due(clock.step(),
                                  clock.is_at_end(),
                                  mpi_communicator)))
      return;
    SectionTimer::Scope t(timer, "checkpoint");
    // An adaptive run's mesh cannot be rebuilt from the scene.
    const Checkpoint::SharedFiles save_mesh =
      parts.mesh_refinement.is_enabled()
        ? Checkpoint::mesh_writer(parts.discretization.triangulation)
        : Checkpoint::SharedFiles();
    checkpoint.write(
      output_directory,
      mpi_communicator,
      clock.step(),
      scene,
      [&](OutputArchive &archive) { serialize(archive, Checkpoint::format); },
      save_mesh);
  }


  template <class Archive>
  void
  Simulator::serialize(Archive &archive, const unsigned int version)
  {
    // The time loop's whole state, bit for bit: the next step's right-hand
    // side needs the state, its active-set iteration starts from the
    // contact status and the matrix and factor as they are; the outputs
    // keep what they have written.
    stepper->serialize_state(archive);
    archive &adaptation_pending;
    stepper->serialize_contact(archive);
    transfer(archive, outputs);
    (void)version;
  }
} // namespace liftoff
