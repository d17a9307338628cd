#include <deal.II/base/mpi.h>

#include <liftoff/base/archives.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  TensionlessWinklerFoundation::TensionlessWinklerFoundation()
      : foundation_diagnostics(points, contact_law, in_contact)
  {}


  void
  TensionlessWinklerFoundation::declare_parameters(ParameterHandler &prm)
  {
    ContactLaw::declare_parameters(prm);
  }


  void
  TensionlessWinklerFoundation::parse_parameters(ParameterHandler &prm)
  {
    contact_law.parse_parameters(prm);
  }


  void
  TensionlessWinklerFoundation::setup(const Discretization &disc)
  {
    points.setup(disc, contact_law.has_layer());
    contact_law.setup(points);
    in_contact.assign(points.n_points(),
                      contact_law.model() == ContactLaw::Model::none ? 0 : 1);
    compression.resize(points.n_points());
    term.setup(points, contact_law.layer_modulus(), in_contact);
  }


  const ContactLaw &
  TensionlessWinklerFoundation::law() const
  {
    return contact_law;
  }


  const FoundationDiagnostics &
  TensionlessWinklerFoundation::diagnostics() const
  {
    return foundation_diagnostics;
  }


  void
  TensionlessWinklerFoundation::change_status(const unsigned int  i,
                                              const unsigned char status)
  {
    if (in_contact[i] == status)
      return;
    in_contact[i] = status;
    term.status_changed(i);
  }


  void
  TensionlessWinklerFoundation::activate_all()
  {
    if (contact_law.model() != ContactLaw::Model::none)
      for (unsigned int i = 0; i < in_contact.size(); ++i)
        change_status(i, 1);
  }


  unsigned long
  TensionlessWinklerFoundation::update_status(const LA::MPI::Vector &u,
                                              const SpringPressure  &pressure)
  {
    if (contact_law.model() != ContactLaw::Model::tensionless)
      return 0;
    // Two passes: the threshold needs the largest |w_h - e| of the whole
    // plate.
    const unsigned int  n_q = points.n_q_points();
    std::vector<double> w;
    double              largest = 0;
    for (unsigned int c = 0; c < points.n_cells(); ++c)
      {
        points.values_at_points(u, c, w);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int i = c * n_q + q;
            compression[i] =
              pressure.gap.empty() ? w[q] : w[q] - pressure.gap[i];
            largest = std::max(largest, std::abs(compression[i]));
          }
      }
    const MPI_Comm comm = points.discretization().mpi_communicator;
    band                = contact_law.band(Utilities::MPI::max(largest, comm));

    unsigned long n_changed = 0;
    for (unsigned int i = 0; i < in_contact.size(); ++i)
      {
        const unsigned char now =
          contact_law.next_status(in_contact[i], compression[i], band);
        n_changed += (now != in_contact[i]);
        change_status(i, now);
      }
    return Utilities::MPI::sum(n_changed, comm);
  }


  unsigned long
  TensionlessWinklerFoundation::keep_status_in_band(
    const std::vector<unsigned char> &earlier)
  {
    AssertDimension(earlier.size(), in_contact.size());
    unsigned long n_changed = 0;
    if (contact_law.model() == ContactLaw::Model::tensionless)
      for (unsigned int i = 0; i < in_contact.size(); ++i)
        if (std::abs(compression[i]) <= band && in_contact[i] != earlier[i])
          {
            change_status(i, earlier[i]);
            ++n_changed;
          }
    return Utilities::MPI::sum(n_changed,
                               points.discretization().mpi_communicator);
  }


  const std::vector<unsigned char> &
  TensionlessWinklerFoundation::status() const
  {
    return in_contact;
  }


  void
  TensionlessWinklerFoundation::set_status(
    const std::vector<unsigned char> &status)
  {
    AssertDimension(status.size(), in_contact.size());
    for (unsigned int i = 0; i < status.size(); ++i)
      change_status(i, status[i]);
  }


  void
  TensionlessWinklerFoundation::add_to_matrix(const MatrixFactors   &factors,
                                              LA::MPI::SparseMatrix &matrix)
  {
    term.assemble(in_contact,
                  contact_law.matrix_stiffness(factors.velocity),
                  matrix);
  }


  void
  TensionlessWinklerFoundation::add_to_matrix(
    const std::vector<unsigned char> &status,
    const double                      velocity_factor,
    LA::MPI::SparseMatrix            &matrix) const
  {
    term.add_to_matrix(status,
                       contact_law.matrix_stiffness(velocity_factor),
                       matrix);
  }


  const std::vector<unsigned char> &
  TensionlessWinklerFoundation::status_in_matrix() const
  {
    return term.status_in_matrix();
  }


  unsigned long
  TensionlessWinklerFoundation::update_matrix(const double velocity_factor,
                                              LA::MPI::SparseMatrix &matrix)
  {
    return term.update_matrix(in_contact,
                              contact_law.matrix_stiffness(velocity_factor),
                              matrix);
  }


  void
  TensionlessWinklerFoundation::add_change_product(
    const std::vector<unsigned char> &reference,
    const double                      velocity_factor,
    const LA::MPI::Vector            &ghosted_src,
    LA::MPI::Vector                  &dst) const
  {
    term.add_change_product(reference,
                            contact_law.matrix_stiffness(velocity_factor),
                            ghosted_src,
                            dst);
  }


  void
  TensionlessWinklerFoundation::add_force(const TermState &state,
                                          LA::MPI::Vector &force) const
  {
    if (contact_law.model() == ContactLaw::Model::none)
      force.compress(VectorOperation::add);
    else
      term.add_product(in_contact,
                       contact_law.stiffness(),
                       state.ghosted_u,
                       force);
  }


  double
  TensionlessWinklerFoundation::energy(const TermState &state) const
  {
    return foundation_diagnostics.energy(state.ghosted_u);
  }


  void
  TensionlessWinklerFoundation::add_status_load(const SpringPressure &pressure,
                                                LA::MPI::Vector &vector) const
  {
    Assert(contact_law.has_gap() && pressure.gap.size() == in_contact.size(),
           ExcInternalError());
    const unsigned int n_q = points.n_q_points();
    term.add_integral(
      in_contact,
      pressure.stiffness,
      [&](const unsigned int c, std::vector<double> &e) {
        e.assign(pressure.gap.begin() + c * n_q,
                 pressure.gap.begin() + (c + 1) * n_q);
      },
      vector);
  }


  bool
  TensionlessWinklerFoundation::has_status_load() const
  {
    return contact_law.has_gap();
  }


  double
  TensionlessWinklerFoundation::status_load_work(
    const LA::MPI::Vector &ghosted_u) const
  {
    return foundation_diagnostics.gap_work(ghosted_u);
  }


  void
  TensionlessWinklerFoundation::unite(const Status &status, Status &all) const
  {
    AssertDimension(status.size(), all.size());
    for (unsigned int i = 0; i < all.size(); ++i)
      all[i] |= status[i];
  }


  void
  TensionlessWinklerFoundation::add_dissipative_force(
    const LA::MPI::Vector &u,
    const LA::MPI::Vector &v,
    LA::MPI::Vector       &vector) const
  {
    term.add_integral(
      in_contact,
      contact_law.damping(),
      [&](const unsigned int c, std::vector<double> &v_at_points) {
        points.values_at_points(v, c, v_at_points);
      },
      vector);
    const std::vector<unsigned char> every_point(in_contact.size(), 1);
    const unsigned int               n_q   = points.n_q_points();
    const double                     gamma = contact_law.stiffness();
    term.add_integral(
      every_point,
      1.0,
      [&](const unsigned int c, std::vector<double> &values) {
        points.values_at_points(u, c, values);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int i           = c * n_q + q;
            const double       compression = values[q] - contact_law.gap(i);
            values[q] = (in_contact[i] ? gamma * compression : 0.0)
                        - contact_law.spring_pressure(compression);
          }
      },
      vector);
  }


  void
  TensionlessWinklerFoundation::save(OutputArchive &archive) const
  {
    archive << in_contact;
    term.save(archive);
  }


  void
  TensionlessWinklerFoundation::load(InputArchive &archive)
  {
    const std::size_t n_points = in_contact.size();
    archive >> in_contact;
    term.load(archive);
    AssertThrow(in_contact.size() == n_points
                  && term.status_in_matrix().size() == n_points,
                ExcMessage("The checkpoint's contact status has "
                           + std::to_string(in_contact.size())
                           + " Gauss points where this rank has "
                           + std::to_string(n_points)
                           + ": it was written for another mesh."));
  }
} // namespace liftoff
