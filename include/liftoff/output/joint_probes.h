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
  class PlateGeometry;
  class TimeHistory;

  /**
   * Load transfer at named points of the joints (`Output/Joint probe
   * points`): at each point, on both slabs, w and the face stress along
   * the joint (sigma_yy on a joint x = const, sigma_xx on y = const: the
   * edge stress, the one that cracks a slab at its joint), and the two
   * ratios, unloaded side over loaded side: the deflection LTE and the
   * stress LTE, as columns of history.csv at every step. In a time
   * integration the ratios are of the changes since the plate's rest at
   * tau = 0 (settled under its weight and permanent loads), as a
   * deflectometer's geophones measure; the w and stress columns are the
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
    parse_parameters(ParameterHandler    &prm,
                     const PlateGeometry &geometry,
                     const MindlinPlate  &plate);
    /// Adds its columns to `history`: w_lower, w_upper, lte, sigma_lower,
    /// sigma_upper, lte_sigma at each point.
    void
    add_columns_to(TimeHistory &history) const override;
    void
    setup(const Discretization &discretization,
          const std::string    &directory) override;
    void
    mesh_changed(const Discretization &discretization) override;
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
    /// w and the stress of both sides at rest, per point (a time
    /// integration's tau = 0; zeros otherwise).
    mutable std::vector<double> rest;

    /// The columns' values at a step (collective).
    std::vector<double>
    values(const StepData &step) const;
  };
} // namespace liftoff
