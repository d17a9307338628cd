#pragma once

#include <deal.II/base/mpi.h>

#include <liftoff/base/located_maximum.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/output/output.h>

#include <array>
#include <string>
#include <vector>

namespace liftoff
{
  class TimeHistory;

  /**
   * Stresses as design quantities: the largest principal stress at each
   * face of the plate, the face away from the bed (top, where top-down
   * cracks start) and the bed-side face (bottom, bottom-up cracks), and
   * with a base (BaseLayer) the base's top and bottom faces, each
   * slab's with its own thickness and with a temperature profile's stress
   * of that face (StressResultants' sigma_1_top and sigma_1_bottom, read at
   * the output points from the step's ResultantSweep). With `Write stress
   * extremes`, the largest of the run on each face, with its point (of the
   * meshed part), slab and time, in the summary and summary.json (MPa in
   * an SI scene, F0/L^2 in a dimensionless one); with `Write stress
   * history`, the step's largest of each face in history.csv.
   *
   * Each rank keeps its own largest per face and slab (points of its
   * cells); the reduction over the ranks breaks ties by the point
   * (LocatedMaximum), so 1 and 2 ranks report the same; a checkpoint keeps
   * them. They need no per-point storage, so the mesh may adapt.
   */
  class StressExtremes : public Output
  {
  public:
    /// The largest principal stress of a face over the plate (solver's
    /// units), with its point, time and slab (0, 1, ...).
    struct Extreme
    {
      LocatedMaximum where;
      unsigned int   slab = 0;
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;
    bool
    needs_face_stresses() const override;
    /// The step's largest per face (Write stress history).
    void
    add_columns_to(TimeHistory &history) const override;
    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &) override
    {}
    void
    execute(const StepData &step) override;
    void
    flush() override
    {}
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;
    /// The run's largest per face (Write stress extremes); collective.
    void
    add_to(RunSummary &summary) const override;

    /// The largest of `face` (FaceStresses' order) over the steps so far
    /// (collective).
    Extreme
    largest(const unsigned int face) const;

    /// The largest of one face's maxima over slabs and ranks (collective):
    /// slab by slab over the ranks, then over the slabs by LocatedMaximum's
    /// rule; of equal values at one point and time, the first slab.
    static Extreme
    reduce(const std::vector<LocatedMaximum> &of_slab, const MPI_Comm comm);

  private:
    /// Per face (FaceStresses' order), per slab: the largest this rank has
    /// met.
    using Maxima = std::vector<std::vector<LocatedMaximum>>;

    bool writes_summary = false;
    bool writes_history = false;
    /// The slab's two faces, and the base's where there is one.
    unsigned int  n_faces    = 2;
    bool          is_dynamic = false;
    MPI_Comm      comm       = MPI_COMM_SELF;
    PhysicalUnits units;
    Maxima        run_maxima;

    /// The step's values at this rank's output points into `maxima`.
    static void
    consider_step(const StepData &step, Maxima &maxima);
  };
} // namespace liftoff
