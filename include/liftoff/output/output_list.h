#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/archive_types.h>
#include <liftoff/output/output.h>
#include <liftoff/output/time_history.h>

#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The outputs of a run, in the order they are written after each step:
   * the list of output_list.cc is the only place that names them. Calls
   * each output the same way (its parameters, checks, steps, checkpoint)
   * and gives every one the time history to add its columns to, so a new
   * output touches its own files and one line of that list.
   */
  class OutputList
  {
  public:
    /// With show_progress, the progress line on rank 0's terminal too.
    OutputList(const MPI_Comm comm, const bool show_progress);

    /// The entries of every output, inside the `Output` subsection.
    static void
    declare_parameters(ParameterHandler &prm);
    /// Every output reads its entries inside `Output` (which this enters),
    /// writes in the scene's units and adds its columns to the history.
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene);
    /// Whether any output reads the face stresses of the sweep.
    bool
    needs_face_stresses() const;
    /// The outputs' checks against the scene, in the list's order.
    void
    check(const SceneView &scene) const;

    void
    setup(const SceneView &scene, const std::string &directory);
    void
    mesh_changed(const SceneView &scene);
    void
    execute(const StepData &step);
    /// Every output's flush(); with `keep_first_error`, a failure of one
    /// (a full disk) does not stop the others and is dropped, for a run
    /// that is ending with an error of its own.
    void
    flush(const bool keep_first_error = false);

    void
    add_to(RunSummary &summary) const;
    /// The outputs' warnings, one text (empty: none).
    std::string
    warnings() const;

    void
    save(OutputArchive &archive) const;
    void
    load(InputArchive &archive);

    /// The time history every output adds its columns to.
    TimeHistory &
    history();
    const TimeHistory &
    history() const;
    /// The output of class T in the list (tests read their results).
    template <class T>
    const T &
    get() const;

  private:
    std::vector<std::unique_ptr<Output>> outputs;
  };


  template <class T>
  const T &
  OutputList::get() const
  {
    for (const auto &output : outputs)
      if (const T *found = dynamic_cast<const T *>(output.get()))
        return *found;
    AssertThrow(false, ExcMessage("The run has no output of this kind."));
    return dynamic_cast<const T &>(*outputs.front());
  }
} // namespace liftoff
