#pragma once

#include <liftoff/base/archive_types.h>
#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/status_law.h>
#include <liftoff/fem/system_term.h>

#include <functional>
#include <string>
#include <vector>

namespace liftoff
{
  /**
   * Point springs with a status, the one base of the bed's springs (a
   * status per Gauss point: in contact or not) and the dowels (slack, or
   * pressed one way or the other): the terms of the plate's system that
   * the active-set iteration drives. Within one status the term is affine
   * in u: a matrix and a load that does not depend on u (the springs' push
   * on a gap, a loose dowel's offset). The iteration solves with the
   * matrices and loads of the current statuses, asks each term for its
   * status from the solution, and repeats until no status changes.
   *
   * This class keeps the status and the status its matrix entries were
   * built with, so that a matrix holding them is brought up to date by
   * touching only the points that changed (update_matrix()), and the
   * product with the change of that matrix is available without forming
   * it (add_change_product()). What differs between the terms is asked of
   * the derived class: its law (status_law(): next status, band, offset,
   * union), the value a point measures, and how a point's spring enters a
   * matrix or a vector (the bed's by cells of Gauss points, a dowel's by
   * its two cells).
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

    virtual const StatusLaw &
    status_law() const = 0;

    /// The status from the solution `ghosted_u` (with ghosts, constraints
    /// distributed). Returns the number of points (over all ranks) whose
    /// status changed. Collective.
    unsigned long
    update_status(const LA::MPI::Vector &ghosted_u);

    /// Give the points whose value lay inside the round-off band of the
    /// law at the last update_status() the status they have in `earlier`,
    /// so that the status there does not depend on the iteration's path.
    /// Returns the number of points (over all ranks) changed.
    unsigned long
    keep_status_in_band(const Status &earlier);

    /// The status of the locally owned points, and its replacement; the
    /// layout is the term's own, the same between calls on one mesh.
    const Status &
    status() const;
    void
    set_status(const Status &status);

    /// The status of the union of several: `all` holds the union so far.
    void
    unite(const Status &status, Status &all) const;

    /// The status whose entries the matrix of add_to_matrix() and
    /// update_matrix() holds.
    const Status &
    status_in_matrix() const;

    /// matrix += its entries for the current status, with the velocity's
    /// kappa; the matrix now holds that status. Collective.
    void
    add_to_matrix(const MatrixFactors   &factors,
                  LA::MPI::SparseMatrix &matrix) override;

    /// matrix += its entries for `status`, recording nothing: to build
    /// again a matrix that was built from `status`. Collective.
    void
    add_to_matrix(const Status          &status,
                  const double           velocity_factor,
                  LA::MPI::SparseMatrix &matrix) const;

    /// Bring the entries held in `matrix` (by add_to_matrix() with the
    /// same kappa) up to date with the status. Returns the number of points
    /// updated over all ranks (0: `matrix` is unchanged). Collective.
    unsigned long
    update_matrix(const double velocity_factor, LA::MPI::SparseMatrix &matrix);

    /// dst += (A(status_in_matrix()) - A(reference)) src, its entries'
    /// change since the matrix held `reference`. `ghosted_src` satisfies
    /// the constraints; `dst` has no ghosts. Collective.
    void
    add_change_product(const Status          &reference,
                       const double           velocity_factor,
                       const LA::MPI::Vector &ghosted_src,
                       LA::MPI::Vector       &dst) const;

    /// Whether its force has a part that does not depend on u: then it
    /// changes with the status and joins the right-hand side of every
    /// solve (add_status_load()).
    bool
    has_status_load() const;

    /// vector += that part of its force, k offset at the engaged points.
    void
    add_status_load(LA::MPI::Vector &vector) const;

    /// What the status load adds to Clapeyron's identity at an equilibrium
    /// `ghosted_u` of the plate at rest: with it, the work of loads applied
    /// proportionally is 1/2 (f . u + this) (collective).
    virtual double
    status_load_work(const LA::MPI::Vector &ghosted_u) const = 0;

  protected:
    /// The points a pass visits and each one's factor: every point of the
    /// rank, or only those `listed` (ascending). A point whose factor is 0
    /// adds nothing.
    struct PointFactors
    {
      std::function<double(unsigned int)> factor;
      const std::vector<unsigned int>    *listed = nullptr;
    };

    /// Its points on the current mesh, `n_points` on this rank, each with
    /// the status `initial`; a matrix is taken to hold it.
    void
    reset_status(const unsigned int  n_points,
                 const unsigned char initial,
                 const MPI_Comm      communicator);

    /// Point i takes `status` (update_matrix() will look at it).
    void
    change_status(const unsigned int i, const unsigned char status);

    /// The statuses, bit for bit, for a checkpoint; load_status() refuses
    /// a checkpoint of another mesh, naming its `points` ("dowels").
    void
    save_status(OutputArchive &archive) const;
    void
    load_status(InputArchive &archive, const std::string &points);

    /// The value each point measures at `ghosted_u`, the law's argument
    /// (w - e, [w]). Collective.
    virtual void
    point_values(const LA::MPI::Vector &ghosted_u,
                 std::vector<double>   &values) const = 0;

    /// matrix += sum_i factor(i) K_i, K_i the spring of point i with
    /// stiffness k (no compress; every rank calls it).
    virtual void
    add_point_matrices(const PointFactors    &points,
                       const double           k,
                       LA::MPI::SparseMatrix &matrix) const = 0;

    /// dst += sum_i factor(i) K_i src (compressed). Collective.
    virtual void
    add_point_products(const PointFactors    &points,
                       const double           k,
                       const LA::MPI::Vector &ghosted_src,
                       LA::MPI::Vector       &dst) const = 0;

    /// dst += sum_i factor(i) k value(i) b_i, b_i the functional point i
    /// measures (compressed). Collective.
    virtual void
    add_point_loads(const PointFactors                        &points,
                    const double                               k,
                    const std::function<double(unsigned int)> &value,
                    LA::MPI::Vector                           &dst) const = 0;

  private:
    Status current, in_matrix;
    /// The points whose status may differ from in_matrix.
    std::vector<unsigned int> points_to_update;
    /// The points' values at the last update_status() and the half-width
    /// of the law's band then.
    std::vector<double> last_values;
    double              band         = 0;
    MPI_Comm            communicator = MPI_COMM_WORLD;
  };
} // namespace liftoff
