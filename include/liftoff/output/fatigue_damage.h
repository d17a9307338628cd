#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <liftoff/base/located_maximum.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/output/fatigue_law.h>
#include <liftoff/output/output.h>
#include <liftoff/output/rainflow.h>
#include <liftoff/output/stress_extremes.h>

#include <array>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class Discretization;

  /**
   * Fatigue damage, the design answer of a dynamic run (Output/Fatigue
   * damage): at every output point of the field files and at each face
   * (top, the face away from the bed; bottom, the bed-side face; and,
   * where the scene has a base and Base modulus of rupture is given, the
   * base's top and bottom), the history of the largest principal stress
   * (ResultantSweep's faces) counted by rainflow as it comes (Rainflow,
   * ASTM E1049) and each counted cycle's damage summed by Miner's rule
   * under the layer's FatigueLaw (the slab's: the MEPDG's or an
   * expression; the base's: an expression), as scripts/liftoff_fatigue.py
   * counts a whole history. Per point and face it keeps the rainflow
   * residue and the counted sum only, so its memory does not grow with the
   * steps.
   *
   * The damage it reports is that of the history ended now: the counted
   * sum plus the residue's half cycles (ASTM's end of a history), which
   * are not counted into the sum, so that a run goes on counting after a
   * checkpoint or a written file. Written at the end (and at each
   * checkpoint) as damage.pvtu (damage_top, damage_bottom, and
   * damage_base_top, damage_base_bottom where the base counts), and the
   * largest with its point, face and slab to the summary. A checkpoint
   * keeps the residues and sums of the faces counted (the scene, which
   * the checkpoint pins, says which); the values are per output point of
   * this rank, so a mesh that adapts is refused, as is a static run (one
   * state, no cycles).
   */
  class FatigueDamage : public Output
  {
  public:
    /// FaceStresses' order.
    enum Face : unsigned int
    {
      top         = 0,
      bottom      = 1,
      base_top    = 2,
      base_bottom = 3
    };

    /// The subsection `Output/Fatigue damage` and its entries.
    static void
    declare_parameters(ParameterHandler &prm);
    /// Refuses the base's law in a scene without a base, and half of it
    /// (a modulus without an expression, or the reverse), naming the entry.
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;
    /// Refuses a mesh that adapts and a static run, naming the entries.
    void
    check(const SceneView &scene) const override;
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;
    bool
    needs_face_stresses() const override;

    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &scene) override;
    void
    execute(const StepData &step) override;
    /// damage.pvtu, the damage of the history so far.
    void
    flush() override;
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;
    /// The largest damage with its point, face and slab (collective).
    void
    add_to(RunSummary &summary) const override;

    /// This rank's damage at `face` (one counted: n_faces()), one value per
    /// output point in the order of its cells: the counted sum and the
    /// residue's half cycles.
    std::vector<double>
    local_field(const Face face) const;
    /// The faces counted: the slab's 2, and the base's where its law is
    /// given (4).
    unsigned int
    n_faces() const;

  private:
    /// A point's history at one face, reduced.
    struct Counter
    {
      Rainflow cycles;
      /// Miner's sum of the cycles counted so far.
      double counted = 0;
    };

    bool enabled = false;
    /// The slab's law, and the base's where it is given.
    FatigueLaw            law, base_law;
    bool                  counts_base = false;
    std::string           directory;
    const Discretization *discretization = nullptr;
    PhysicalUnits         units;
    /// This rank's output points and their slabs, from the first step.
    std::vector<Point<2>>               points;
    std::vector<unsigned int>           slabs;
    std::array<std::vector<Counter>, 4> counters;
    std::vector<Rainflow::Cycle>        closed;
    unsigned int                        n_steps_seen = 0;
    double                              last_time    = 0;
    unsigned int                        n_slabs      = 1;

    /// The law of the layer of `face`.
    const FatigueLaw &
    law_of(const Face face) const;
    /// The damage of `counter`'s history at `face` ended now.
    double
    damage_of(const Face face, const Counter &counter) const;
    /// The largest damage at `face` over the ranks, with its point and
    /// slab (collective).
    StressExtremes::Extreme
    largest(const Face face) const;
  };
} // namespace liftoff
