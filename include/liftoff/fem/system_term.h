#pragma once

#include <liftoff/base/archive_types.h>
#include <liftoff/base/linear_algebra.h>

#include <string>
#include <vector>

namespace liftoff
{
  class Discretization;

  /// The factors the system matrix of a solve is made with: the mass
  /// term's (Newmark's 1 / (beta dt^2), 0 in a static solve) and the
  /// velocity's kappa (gamma / (beta dt), 0 in a static solve), by which a
  /// term with dashpots stiffens.
  struct MatrixFactors
  {
    double mass     = 0;
    double velocity = 0;
  };

  /// The displacement a term's force and energy are taken at: owned, and
  /// with ghosts (constraints distributed), and a vector of its layout
  /// that the term may overwrite.
  struct TermState
  {
    const LA::MPI::Vector &u;
    const LA::MPI::Vector &ghosted_u;
    LA::MPI::Vector       &scratch;
  };

  /**
   * A term of the plate's system: the plate itself (stiffness and mass,
   * PlateTerm), the foundation (TensionlessWinklerFoundation, the Bed),
   * and the couplings between slabs (JointSprings along the joints,
   * JointDowels at points). The system matrix, the internal force, the
   * stored and kinetic energies and the checkpoint are the sums of its
   * terms' (SceneParts::system_terms(), the only list of them).
   *
   * A term whose matrix changes with a status of its own (the
   * foundation's contact set) adds the entries of the status it holds;
   * the active-set iteration keeps them up to date (has_status()).
   */
  class SystemTerm
  {
  public:
    virtual ~SystemTerm() = default;

    /// Its data on the current mesh (a new mesh: again).
    virtual void
    setup(const Discretization &discretization) = 0;

    /// Whether its matrix depends on a status that the active-set
    /// iteration drives (then it adds its own entries there, not in the
    /// system's fixed part).
    virtual bool
    has_status() const
    {
      return false;
    }

    /// matrix += its entries for `factors` (and its current status), in
    /// the plate's sparsity pattern.
    virtual void
    add_to_matrix(const MatrixFactors   &factors,
                  LA::MPI::SparseMatrix &matrix) = 0;

    /// force += its internal force at `state`, the part linear in u (its
    /// matrix without the velocity's stiffening, times u).
    virtual void
    add_force(const TermState &state, LA::MPI::Vector &force) const = 0;

    /// The energy it stores at `state`, on the modelled part (collective).
    virtual double
    energy(const TermState &state) const = 0;

    /// The column of history.csv that shows the energy() it stores
    /// ("strain", "foundation", "joint_springs", "dowels").
    virtual std::string
    energy_column() const = 0;

    /// Which sum of the energy balance its energy() joins: the plate's own
    /// strain energy, or the energy the plate's supports and couplings
    /// store (the bed's springs, the joints', the dowels').
    enum class Stores
    {
      strain,
      supports
    };
    virtual Stores
    stores() const
    {
      return Stores::supports;
    }
    /// The kinetic energy of the velocity `state.u` (its mass's share;
    /// none by default; collective).
    virtual double
    kinetic_energy(const TermState &) const
    {
      return 0;
    }

    /// A stiffness by which the term ties unknowns together (a joint's
    /// springs, the dowels): the entry that gives it as the scene names it,
    /// its value, and the diagonal entries one unit of it adds to the
    /// system matrix, every status engaged (StiffnessLimit).
    struct Coupling
    {
      std::string     entry;
      double          value;
      LA::MPI::Vector diagonal_per_unit;
    };
    /// Its couplings on the current mesh (none by default).
    virtual std::vector<Coupling>
    couplings() const
    {
      return {};
    }

    /// Its state for a checkpoint, bit for bit (none by default).
    virtual void
    save(OutputArchive &) const
    {}
    virtual void
    load(InputArchive &)
    {}
  };
} // namespace liftoff
