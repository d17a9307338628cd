#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>

#include <liftoff/output/output.h>

#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class MindlinPlate;
  class Discretization;
  class PlateGeometry;
  class TimeHistory;

  /**
   * Load transfer at named points of the joints (`Output/Joint probe
   * points`): at each point, on both slabs, w and the face stress along
   * the joint (sigma_yy on a joint x = const, sigma_xx on y = const: the
   * edge stress, the one that cracks a slab at its joint), and the two
   * ratios, unloaded side over loaded side: the deflection LTE and the
   * stress LTE, as columns of history.csv at every step. The ratios are
   * of the changes since the plate at rest (PlateState::ghosted_rest:
   * tau = 0 of a time integration, settled under its weight and permanent
   * loads; the weight and the curl alone in a static analysis), as a
   * deflectometer's geophones measure, and empty where the load is far
   * (JointSprings::load_transfer()); the w and stress columns are the
   * totals. Each side is
   * evaluated in its own cell, so a point on a joint has two values and
   * their ratio, where a probe of w there would read whichever cell is
   * found first.
   */
  class JointProbes : public Output
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    /// Refuses a point that lies on no joint that is not tied.
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;
    /// Adds its columns to `history`: w_lower, w_upper, lte, sigma_lower,
    /// sigma_upper, lte_sigma at each point.
    void
    add_columns_to(TimeHistory &history) const override;
    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &scene) override;
    void
    execute(const StepData &) override
    {}
    void
    flush() override
    {}
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

  private:
    /// A point of the full plate, where it is in the modelled part, and
    /// its joint.
    struct Probe
    {
      Point<2>     point;
      Point<2>     modelled;
      unsigned int joint;
    };
    std::vector<Probe> probes;
    /// The probes this rank evaluates, with the cells of their lower and
    /// upper slab.
    struct Located
    {
      unsigned int                        probe;
      DoFHandler<2>::active_cell_iterator lower, upper;
    };
    std::vector<Located>  located;
    const Discretization *discretization = nullptr;
    const MindlinPlate   *plate          = nullptr;
    /// w and the stress of both sides at rest, per point, taken at step 0.
    mutable std::vector<double> rest;

    /// w and the stress of both sides at each point for the displacement
    /// `ghosted_u`, in the columns' order with the ratios left 0
    /// (collective).
    std::vector<double>
    sides_at(const LA::MPI::Vector &ghosted_u, const StepData &step) const;
    /// The columns' values at a step (collective).
    std::vector<double>
    values(const StepData &step) const;
  };
} // namespace liftoff
