#include <deal.II/base/mpi.h>

#include <liftoff/base/archives.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/plate_fields.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  TensionlessWinklerFoundation::TensionlessWinklerFoundation()
      : foundation_diagnostics(points, contact_law, status())
  {}


  void
  TensionlessWinklerFoundation::declare_parameters(ParameterHandler &prm)
  {
    ContactLaw::declare_parameters(prm);
  }


  void
  TensionlessWinklerFoundation::parse_parameters(ParameterHandler &prm,
                                                 const double mass_per_area)
  {
    contact_law.parse_parameters(prm, mass_per_area);
  }


  void
  TensionlessWinklerFoundation::setup(const Discretization &disc)
  {
    points.setup(disc,
                 contact_law.has_layer(),
                 measured_fields(disc.dof_handler.get_fe()));
    contact_law.setup(points);
    contact_rule.use_pressure(contact_law.pressure());
    reset_status(points.n_points(),
                 contact_law.model() == ContactLaw::Model::none ? 0 : 1,
                 disc.mpi_communicator);
    term.setup(points, contact_law.layer_modulus());
  }


  std::vector<FoundationPoints::Part>
  TensionlessWinklerFoundation::measured_fields(
    const FiniteElement<2> &fe) const
  {
    return {{PlateFields::bed_component(fe), 1.0}};
  }


  ContactLaw &
  TensionlessWinklerFoundation::own_law()
  {
    return contact_law;
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
  TensionlessWinklerFoundation::activate_all()
  {
    if (contact_law.model() != ContactLaw::Model::none)
      for (unsigned int i = 0; i < status().size(); ++i)
        change_status(i, 1);
  }


  const StatusLaw &
  TensionlessWinklerFoundation::status_law() const
  {
    return contact_rule;
  }


  void
  TensionlessWinklerFoundation::use_pressure(SpringPressure pressure)
  {
    contact_rule.use_pressure(std::move(pressure));
  }


  void
  TensionlessWinklerFoundation::point_values(const LA::MPI::Vector &u,
                                             std::vector<double> &values) const
  {
    const std::vector<double> &gap = contact_rule.pressure().gap;
    const unsigned int         n_q = points.n_q_points();
    std::vector<double>        w;
    values.resize(points.n_points());
    for (unsigned int c = 0; c < points.n_cells(); ++c)
      {
        points.values_at_points(u, c, w);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int i = c * n_q + q;
            values[i]            = gap.empty() ? w[q] : w[q] - gap[i];
          }
      }
  }


  void
  TensionlessWinklerFoundation::add_point_matrices(
    const PointFactors    &factors,
    const double           k,
    LA::MPI::SparseMatrix &matrix) const
  {
    term.add_to_matrix(factors.factor, factors.listed, k, matrix);
  }


  void
  TensionlessWinklerFoundation::add_point_products(
    const PointFactors    &factors,
    const double           k,
    const LA::MPI::Vector &ghosted_src,
    LA::MPI::Vector       &dst) const
  {
    Assert(factors.listed == nullptr, ExcNotImplemented());
    term.add_product(factors.factor, k, ghosted_src, dst);
  }


  void
  TensionlessWinklerFoundation::add_point_loads(
    const PointFactors                        &factors,
    const double                               k,
    const std::function<double(unsigned int)> &value,
    LA::MPI::Vector                           &dst) const
  {
    Assert(factors.listed == nullptr, ExcNotImplemented());
    const unsigned int n_q = points.n_q_points();
    term.add_integral(
      factors.factor,
      k,
      [&](const unsigned int c, std::vector<double> &values) {
        values.resize(n_q);
        for (unsigned int q = 0; q < n_q; ++q)
          values[q] = value(c * n_q + q);
      },
      dst);
  }


  void
  TensionlessWinklerFoundation::add_force(const TermState &state,
                                          LA::MPI::Vector &force) const
  {
    if (contact_law.model() == ContactLaw::Model::none)
      force.compress(VectorOperation::add);
    else
      term.add_reaction(status(),
                        contact_law.stiffness(),
                        state.ghosted_u,
                        force);
  }


  double
  TensionlessWinklerFoundation::energy(const TermState &state) const
  {
    return foundation_diagnostics.energy(state.ghosted_u);
  }


  double
  TensionlessWinklerFoundation::status_load_work(
    const LA::MPI::Vector &ghosted_u) const
  {
    return foundation_diagnostics.gap_work(ghosted_u);
  }


  void
  TensionlessWinklerFoundation::add_dissipative_force(
    const LA::MPI::Vector &u,
    const LA::MPI::Vector &v,
    LA::MPI::Vector       &vector) const
  {
    const Status &in_contact = status();
    term.add_integral([&](const unsigned int i) { return 1.0 * in_contact[i]; },
                      contact_law.damping(),
                      [&](const unsigned int   c,
                          std::vector<double> &v_at_points) {
                        points.values_at_points(v, c, v_at_points);
                      },
                      vector);
    const unsigned int n_q   = points.n_q_points();
    const double       gamma = contact_law.stiffness();
    term.add_integral([](const unsigned int) { return 1.0; },
                      1.0,
                      [&](const unsigned int c, std::vector<double> &values) {
                        points.values_at_points(u, c, values);
                        for (unsigned int q = 0; q < n_q; ++q)
                          {
                            const unsigned int i = c * n_q + q;
                            const double       compression =
                              values[q] - contact_law.gap(i);
                            values[q] =
                              (in_contact[i] ? gamma * compression : 0.0)
                              - contact_law.spring_pressure(compression);
                          }
                      },
                      vector);
  }


  void
  TensionlessWinklerFoundation::save(OutputArchive &archive) const
  {
    save_status(archive);
  }


  void
  TensionlessWinklerFoundation::load(InputArchive &archive)
  {
    load_status(archive, "Gauss points");
  }
} // namespace liftoff
