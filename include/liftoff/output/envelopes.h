#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/located_maximum.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/output/output.h>

#include <string>
#include <utility>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class Discretization;
  class MeshRefinement;
  class RunSummary;

  /**
   * What design reads off a dynamic run: at every output point of the field
   * files, the largest and smallest deflection, the largest bed pressure,
   * the largest M_1, the smallest M_2 and, with `Write stress envelopes`,
   * the largest principal stress of each face (sigma_1_top_max,
   * sigma_1_bottom_max) over all steps, each with the time at which it
   * occurred. Written as envelope.pvtu (and its pieces) at the
   * end of the run and whenever the outputs are flushed (a checkpoint, a
   * failure), and as the extremes over the plate in the summary. A
   * checkpoint keeps them, so a resumed run's envelope is the uninterrupted
   * run's.
   *
   * The values are kept per output point in the order of this rank's cells
   * (a resume has the same mesh and partition); the mesh must not change
   * during the run, so adaptive refinement is refused with them for now.
   */
  class Envelopes : public Output
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;

    /// With the face stresses' envelopes.
    bool
    needs_face_stresses() const override;

    /// Refuses envelopes on a mesh that adapts.
    void
    check(const SceneView &scene) const override;

    /// The summary's extremes and envelope.pvtu in the scene's units.
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;

    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &scene) override;
    void
    execute(const StepData &step) override;
    void
    flush() override;
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

    /// The names of the envelopes: w_max, w_min, foundation_pressure_max,
    /// M_1_max, M_2_min, sigma_1_top_max, sigma_1_bottom_max (the last two
    /// kept with Write stress envelopes only).
    static std::vector<std::string>
    names();

    /// The extreme over the plate of each envelope, in the order of
    /// names(), with its point (of the meshed part) and time (collective).
    std::vector<LocatedMaximum>
    extremes() const;

    /// This rank's values of the envelope `name` (or, for `name`_time, the
    /// times), one per output point in the order of its cells; empty for
    /// an envelope the run does not keep.
    std::vector<double>
    local_field(const std::string &name) const;

    /// extremes() as a section of the summary (collective).
    void
    add_to(RunSummary &summary) const override;

  private:
    /// One envelope: a quantity's largest value (or, for a smallest one,
    /// the largest of its negative) at each output point, and when.
    struct Envelope
    {
      std::string         name;
      std::vector<double> extreme;
      std::vector<double> time;
    };

    bool                  enabled = false;
    std::string           directory;
    const Discretization *discretization = nullptr;
    std::vector<Envelope> envelopes;
    std::vector<Point<2>> points;
    unsigned int          n_steps_seen = 0;
    PhysicalUnits         units;

    void
           write() const;
    double last_time = 0;
  };
} // namespace liftoff
