#pragma once

#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/contact_law.h>
#include <liftoff/fem/system_term.h>

#include <vector>

namespace liftoff
{
  /**
   * A term of the plate's system whose matrix depends on a status of its
   * own, one small number per point where its law switches, which the
   * active-set iteration drives: the foundation's contact set (in contact
   * or not), the dowels' engagement (slack, or pressed one way or the
   * other). Within one status the term is affine in u: a matrix and a
   * load that does not depend on u (the springs' push on a gap, a loose
   * dowel's offset). The iteration solves with the matrices and loads of
   * the current statuses, asks each term for its status from the
   * solution, and repeats until no status changes.
   *
   * A term keeps the status its matrix entries were built with, so that a
   * matrix holding it is brought up to date by touching only the points
   * that changed (update_matrix()), and the product with the change of
   * that matrix is available without forming it (add_change_product()).
   */
  class StatusTerm : public SystemTerm
  {
  public:
    using Status = std::vector<unsigned char>;

    /// A term's status describes its matrices: it is never copied.
    StatusTerm()                   = default;
    StatusTerm(const StatusTerm &) = delete;
    StatusTerm &
    operator=(const StatusTerm &) = delete;

    bool
    has_status() const override
    {
      return true;
    }

    /// The status from the solution `ghosted_u` (with ghosts, constraints
    /// distributed); `pressure` is the bed's for the plate's velocity,
    /// which a term without dashpots ignores. Returns the number of points
    /// (over all ranks) whose status changed.
    virtual unsigned long
    update_status(const LA::MPI::Vector &ghosted_u,
                  const SpringPressure  &pressure) = 0;

    /// Give the points whose state lay inside the round-off band of the
    /// law at the last update_status() the status they have in `earlier`,
    /// so that the status there does not depend on the iteration's path.
    /// Returns the number of points (over all ranks) changed.
    virtual unsigned long
    keep_status_in_band(const Status &earlier) = 0;

    /// The status of the locally owned points, and its replacement; the
    /// layout is the term's own, the same between calls on one mesh.
    virtual const Status &
    status() const = 0;
    virtual void
    set_status(const Status &status) = 0;

    /// The status of the union of several: what the iteration solves with
    /// when the statuses go round a cycle. `all` holds the union so far.
    virtual void
    unite(const Status &status, Status &all) const = 0;

    /// The status whose entries the matrix of add_to_matrix() and
    /// update_matrix() holds.
    virtual const Status &
    status_in_matrix() const = 0;

    /// matrix += its entries for `status`, with the velocity's kappa
    /// (velocity_factor), recording nothing: to build again a matrix that
    /// was built from `status`.
    virtual void
    add_to_matrix(const Status          &status,
                  const double           velocity_factor,
                  LA::MPI::SparseMatrix &matrix) const = 0;
    using SystemTerm::add_to_matrix;

    /// Bring the entries held in `matrix` (by SystemTerm::add_to_matrix()
    /// with the same kappa) up to date with the status. Returns the number
    /// of points updated over all ranks (0: `matrix` is unchanged).
    virtual unsigned long
    update_matrix(const double           velocity_factor,
                  LA::MPI::SparseMatrix &matrix) = 0;

    /// dst += (A(status_in_matrix()) - A(reference)) src, its entries' change
    /// since the matrix held `reference`. `ghosted_src` satisfies the
    /// constraints; `dst` has no ghosts. Collective.
    virtual void
    add_change_product(const Status          &reference,
                       const double           velocity_factor,
                       const LA::MPI::Vector &ghosted_src,
                       LA::MPI::Vector       &dst) const = 0;

    /// Whether its force has a part that does not depend on u: then it
    /// changes with the status and joins the right-hand side of every
    /// solve (add_status_load()).
    virtual bool
    has_status_load() const = 0;

    /// vector += that part of its force, for the bed's `pressure`.
    virtual void
    add_status_load(const SpringPressure &pressure,
                    LA::MPI::Vector      &vector) const = 0;

    /// What the status load adds to Clapeyron's identity at an equilibrium
    /// `ghosted_u` of the plate at rest: with it, the work of loads applied
    /// proportionally is 1/2 (f . u + this) (collective).
    virtual double
    status_load_work(const LA::MPI::Vector &ghosted_u) const = 0;
  };
} // namespace liftoff
