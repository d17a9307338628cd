#include <deal.II/base/mpi.h>

#include <liftoff/base/archives.h>
#include <liftoff/contact/status_term.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  void
  StatusTerm::reset_status(const unsigned int  n_points,
                           const unsigned char initial,
                           const MPI_Comm      comm)
  {
    current.assign(n_points, initial);
    in_matrix = current;
    points_to_update.clear();
    last_values.assign(n_points, 0.0);
    band         = 0;
    communicator = comm;
  }


  void
  StatusTerm::change_status(const unsigned int i, const unsigned char status)
  {
    if (current[i] == status)
      return;
    current[i] = status;
    points_to_update.push_back(i);
  }


  unsigned long
  StatusTerm::update_status(const LA::MPI::Vector &ghosted_u)
  {
    const StatusLaw &law = status_law();
    if (!law.switches())
      return 0;
    // Two passes: the band needs the largest value of the whole plate.
    point_values(ghosted_u, last_values);
    double largest = 0;
    for (const double value : last_values)
      largest = std::max(largest, std::abs(value));
    band = law.band(Utilities::MPI::max(largest, communicator));

    unsigned long n_changed = 0;
    for (unsigned int i = 0; i < current.size(); ++i)
      {
        const unsigned char now =
          law.next_status(current[i], last_values[i], band);
        n_changed += (now != current[i]);
        change_status(i, now);
      }
    return Utilities::MPI::sum(n_changed, communicator);
  }


  unsigned long
  StatusTerm::keep_status_in_band(const Status &earlier)
  {
    AssertDimension(earlier.size(), current.size());
    const StatusLaw &law       = status_law();
    unsigned long    n_changed = 0;
    if (law.switches())
      for (unsigned int i = 0; i < current.size(); ++i)
        if (current[i] != earlier[i]
            && law.may_keep(earlier[i], last_values[i], band))
          {
            change_status(i, earlier[i]);
            ++n_changed;
          }
    return Utilities::MPI::sum(n_changed, communicator);
  }


  const StatusTerm::Status &
  StatusTerm::status() const
  {
    return current;
  }


  void
  StatusTerm::set_status(const Status &status)
  {
    AssertDimension(status.size(), current.size());
    for (unsigned int i = 0; i < status.size(); ++i)
      change_status(i, status[i]);
  }


  void
  StatusTerm::unite(const Status &status, Status &all) const
  {
    AssertDimension(status.size(), all.size());
    const StatusLaw &law = status_law();
    for (unsigned int i = 0; i < all.size(); ++i)
      all[i] = law.unite(all[i], status[i]);
  }


  const StatusTerm::Status &
  StatusTerm::status_in_matrix() const
  {
    return in_matrix;
  }


  void
  StatusTerm::add_to_matrix(const MatrixFactors   &factors,
                            LA::MPI::SparseMatrix &matrix)
  {
    add_to_matrix(current, factors.velocity, matrix);
    in_matrix = current;
    points_to_update.clear();
  }


  void
  StatusTerm::add_to_matrix(const Status          &status,
                            const double           velocity_factor,
                            LA::MPI::SparseMatrix &matrix) const
  {
    AssertThrow(status.size() == current.size(),
                ExcMessage("A status of another mesh."));
    add_point_matrices({[&](const unsigned int i) {
                         return StatusLaw::engaged(status[i]) ? 1.0 : 0.0;
                       }},
                       status_law().stiffness(velocity_factor),
                       matrix);
    matrix.compress(VectorOperation::add);
  }


  unsigned long
  StatusTerm::update_matrix(const double           velocity_factor,
                            LA::MPI::SparseMatrix &matrix)
  {
    // Points are listed in the order they changed; in order, each once,
    // so that the bed adds a cell's entries once. A point may have changed
    // and changed back: only a difference from the matrix counts.
    std::sort(points_to_update.begin(), points_to_update.end());
    points_to_update.erase(std::unique(points_to_update.begin(),
                                       points_to_update.end()),
                           points_to_update.end());
    unsigned long n_updated = 0;
    for (const unsigned int i : points_to_update)
      n_updated +=
        StatusLaw::engaged(in_matrix[i]) != StatusLaw::engaged(current[i]);
    add_point_matrices({[&](const unsigned int i) {
                          return 1.0 * StatusLaw::engaged(current[i])
                                 - 1.0 * StatusLaw::engaged(in_matrix[i]);
                        },
                        &points_to_update},
                       status_law().stiffness(velocity_factor),
                       matrix);
    for (const unsigned int i : points_to_update)
      in_matrix[i] = current[i];
    points_to_update.clear();
    n_updated = Utilities::MPI::sum(n_updated, communicator);
    if (n_updated > 0)
      matrix.compress(VectorOperation::add);
    return n_updated;
  }


  void
  StatusTerm::add_change_product(const Status          &reference,
                                 const double           velocity_factor,
                                 const LA::MPI::Vector &ghosted_src,
                                 LA::MPI::Vector       &dst) const
  {
    AssertThrow(reference.size() == in_matrix.size(),
                ExcMessage("A status of another mesh."));
    add_point_products({[&](const unsigned int i) {
                         return 1.0 * StatusLaw::engaged(in_matrix[i])
                                - 1.0 * StatusLaw::engaged(reference[i]);
                       }},
                       status_law().stiffness(velocity_factor),
                       ghosted_src,
                       dst);
  }


  bool
  StatusTerm::has_status_load() const
  {
    return status_law().has_offset();
  }


  void
  StatusTerm::add_status_load(LA::MPI::Vector &vector) const
  {
    const StatusLaw &law = status_law();
    add_point_loads(
      {[&](const unsigned int i) {
        return StatusLaw::engaged(current[i]) ? 1.0 : 0.0;
      }},
      law.offset_stiffness(),
      [&](const unsigned int i) { return law.offset(i, current[i]); },
      vector);
  }


  void
  StatusTerm::save_status(OutputArchive &archive) const
  {
    archive << current << in_matrix << points_to_update;
  }


  void
  StatusTerm::load_status(InputArchive &archive, const std::string &points)
  {
    const std::size_t n = current.size();
    archive >> current >> in_matrix >> points_to_update;
    AssertThrow(current.size() == n && in_matrix.size() == n,
                ExcMessage("The checkpoint's status has "
                           + std::to_string(current.size()) + " " + points
                           + " where this rank has " + std::to_string(n)
                           + ": it was written for another mesh."));
  }
} // namespace liftoff
