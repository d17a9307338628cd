#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/contact/joint_dowels.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/plate_fields.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace
  {
    // Trilinos' first add after an insert assembles the object, a
    // collective call, on the rank that adds: a rank that holds no dowel
    // must take that step too, or the ranks wait for each other for ever
    // (seen: two ranks, loose dowels, self-weight).
    void
    add_on_every_rank(LA::MPI::Vector &vector)
    {
      vector.add(0, nullptr, nullptr);
    }


    void
    add_on_every_rank(LA::MPI::SparseMatrix &matrix)
    {
      matrix.add(0, 0, 0.0);
    }
  } // namespace


  void
  JointDowels::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Slabs");
    prm.enter_subsection("Dowels");
    DowelLayout::declare_parameters(prm);
    prm.declare_entry(
      "Stiffness",
      "0",
      Patterns::Double(0.0),
      "C, the force a dowel passes per unit jump of w across the joint (N/m "
      "in an SI scene); 0: from the bar by Friberg's analysis (Diameter, "
      "Steel modulus, Steel Poisson ratio, Modulus of dowel support, Joint "
      "opening; doc/model.md)."
        + quantity("force per length"));
    DowelBar::declare_parameters(prm);
    prm.declare_entry(
      "Looseness",
      "0",
      Patterns::Double(0.0),
      "g, the play of a dowel in its hole: no force while |w_lower - "
      "w_upper| <= g, the force C (|[w]| - g) beyond (a second tensionless "
      "law, in the same active-set iteration as the foundation)."
        + quantity("deflection"));
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  JointDowels::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Slabs");
    prm.enter_subsection("Dowels");
    layout.parse_parameters(prm);
    given_stiffness = prm.get_double("Stiffness");
    dowel_bar.parse_parameters(prm);
    looseness = prm.get_double("Looseness");
    prm.leave_subsection();
    prm.leave_subsection();
    law = DowelLaw(stiffness(), looseness);
    if (layout.is_empty())
      return;
    AssertThrow(given_stiffness > 0
                  || (dowel_bar.diameter > 0 && dowel_bar.modulus > 0
                      && dowel_bar.support_modulus > 0),
                ExcMessage("Slabs/Dowels: give the dowels' Stiffness > 0, or "
                           "the bar's Diameter, Steel modulus and Modulus of "
                           "dowel support (all > 0) to compute it."));
    AssertThrow(std::isfinite(stiffness()) && stiffness() > 0,
                ExcMessage("Slabs/Dowels: the bar gives the stiffness "
                           + format_number(stiffness())
                           + "; check Diameter, Steel modulus, Modulus of "
                             "dowel support and Joint opening."));
  }


  double
  JointDowels::stiffness() const
  {
    return given_stiffness > 0 ? given_stiffness : dowel_bar.stiffness();
  }


  const DowelBar *
  JointDowels::bar() const
  {
    return given_stiffness > 0 ? nullptr : &dowel_bar;
  }


  const std::vector<DowelSite> &
  JointDowels::sites() const
  {
    return dowel_sites;
  }


  void
  JointDowels::place_on(const PlateGeometry &geometry)
  {
    dowel_sites = layout.place_on(geometry);
  }


  JointDowels::Local
  JointDowels::make_local(const DoFHandler<2>::active_cell_iterator &cell,
                          const unsigned int                         face,
                          const unsigned int                         d) const
  {
    const FiniteElement<2> &fe      = discretization->dof_handler.get_fe();
    const Mapping<2>       &mapping = discretization->mapping();
    const unsigned int      n       = fe.n_dofs_per_cell();
    const Joint            &joint =
      discretization->geometry().slabs().joints()[dowel_sites[d].joint];
    // [w] = w_lower - w_upper: this cell's side first.
    const double sign =
      cell->face(face)->boundary_id() == joint.lower_side ? 1 : -1;
    const auto opposite = discretization->geometry().slabs().across(cell, face);
    Local      dowel{d, {}, {}};
    for (const auto &[side, factor] :
         {std::make_pair(DoFHandler<2>::cell_iterator(cell), sign),
          std::make_pair(opposite, -sign)})
      {
        std::vector<types::global_dof_index> dofs(n);
        side->get_dof_indices(dofs);
        dowel.dofs.insert(dowel.dofs.end(), dofs.begin(), dofs.end());
        FEValues<2> values(mapping,
                           fe,
                           Quadrature<2>(mapping.transform_real_to_unit_cell(
                             side, dowel_sites[d].location)),
                           update_values);
        values.reinit(side);
        for (unsigned int i = 0; i < n; ++i)
          dowel.jump.push_back(
            factor * values.shape_value_component(i, 0, PlateFields::w));
      }
    return dowel;
  }


  void
  JointDowels::setup(const Discretization &disc)
  {
    discretization = &disc;
    local.clear();
    const SlabLayout &slabs = disc.geometry().slabs();
    slabs.for_each_joint_face(
      disc.dof_handler,
      [&](const DoFHandler<2>::active_cell_iterator &cell,
          const unsigned int                         face,
          const unsigned int                         joint) {
        const unsigned int along = 1 - slabs.joints()[joint].normal_axis;
        const double       a     = cell->face(face)->vertex(0)[along];
        const double       b     = cell->face(face)->vertex(1)[along];
        const double       tol   = 1e-10 * std::abs(b - a);
        for (unsigned int d = 0; d < dowel_sites.size(); ++d)
          {
            const double x = dowel_sites[d].location[along];
            // Half-open pieces: a dowel at a vertex belongs to one.
            if (dowel_sites[d].joint == joint && x >= std::min(a, b) - tol
                && x < std::max(a, b) - tol)
              local.push_back(make_local(cell, face, d));
          }
      });
    AssertThrow(Utilities::MPI::sum(local.size(), disc.mpi_communicator)
                  == dowel_sites.size(),
                ExcInternalError());
    reset_status(local.size(), law.initial_status(), disc.mpi_communicator);
  }


  std::vector<SystemTerm::Coupling>
  JointDowels::couplings() const
  {
    if (dowel_sites.empty())
      return {};
    Coupling coupling{bar() == nullptr
                        ? std::string("Slabs/Dowels/Stiffness")
                        : std::string("The dowels' stiffness from "
                                      "Slabs/Dowels/Diameter, Steel modulus "
                                      "and Modulus of dowel support"),
                      stiffness(),
                      {}};
    discretization->reinit_vector(coupling.diagonal_per_unit);
    for (const Local &dowel : local)
      {
        Vector<double> diagonal(dowel.jump.size());
        for (unsigned int i = 0; i < dowel.jump.size(); ++i)
          diagonal[i] =
            dowel_sites[dowel.index].share * dowel.jump[i] * dowel.jump[i];
        discretization->constraints.distribute_local_to_global(
          diagonal, dowel.dofs, coupling.diagonal_per_unit);
      }
    coupling.diagonal_per_unit.compress(VectorOperation::add);
    return {std::move(coupling)};
  }


  double
  JointDowels::jump_of(const unsigned int     i,
                       const LA::MPI::Vector &ghosted_u) const
  {
    double jump = 0;
    for (unsigned int k = 0; k < local[i].dofs.size(); ++k)
      jump += local[i].jump[k] * ghosted_u(local[i].dofs[k]);
    return jump;
  }


  void
  JointDowels::add_dowel(const unsigned int     i,
                         const double           factor,
                         LA::MPI::SparseMatrix &matrix) const
  {
    const std::vector<double> &b = local[i].jump;
    FullMatrix<double>         cell_matrix(b.size(), b.size());
    for (unsigned int r = 0; r < b.size(); ++r)
      for (unsigned int c = 0; c < b.size(); ++c)
        cell_matrix(r, c) =
          factor * dowel_sites[local[i].index].share * b[r] * b[c];
    discretization->constraints.distribute_local_to_global(cell_matrix,
                                                           local[i].dofs,
                                                           matrix);
  }


  void
  JointDowels::add_vector(const unsigned int i,
                          const double       factor,
                          LA::MPI::Vector   &vector) const
  {
    Vector<double> cell_vector(local[i].jump.begin(), local[i].jump.end());
    cell_vector *= factor * dowel_sites[local[i].index].share;
    discretization->constraints.distribute_local_to_global(cell_vector,
                                                           local[i].dofs,
                                                           vector);
  }


  const StatusLaw &
  JointDowels::status_law() const
  {
    return law;
  }


  void
  JointDowels::point_values(const LA::MPI::Vector &ghosted_u,
                            std::vector<double>   &values) const
  {
    values.resize(local.size());
    for (unsigned int i = 0; i < local.size(); ++i)
      values[i] = jump_of(i, ghosted_u);
  }


  void
  JointDowels::add_point_matrices(const PointFactors    &points,
                                  const double           k,
                                  LA::MPI::SparseMatrix &matrix) const
  {
    add_on_every_rank(matrix);
    const auto add = [&](const unsigned int i) {
      const double f = points.factor(i);
      if (f != 0.0)
        add_dowel(i, f * k, matrix);
    };
    if (points.listed == nullptr)
      for (unsigned int i = 0; i < local.size(); ++i)
        add(i);
    else
      for (const unsigned int i : *points.listed)
        add(i);
  }


  void
  JointDowels::add_point_products(const PointFactors    &points,
                                  const double           k,
                                  const LA::MPI::Vector &ghosted_src,
                                  LA::MPI::Vector       &dst) const
  {
    Assert(points.listed == nullptr, ExcNotImplemented());
    add_on_every_rank(dst);
    for (unsigned int i = 0; i < local.size(); ++i)
      {
        const double f = points.factor(i);
        if (f != 0.0)
          add_vector(i, f * k * jump_of(i, ghosted_src), dst);
      }
    dst.compress(VectorOperation::add);
  }


  void
  JointDowels::add_point_loads(const PointFactors &points,
                               const double        k,
                               const std::function<double(unsigned int)> &value,
                               LA::MPI::Vector &dst) const
  {
    Assert(points.listed == nullptr, ExcNotImplemented());
    add_on_every_rank(dst);
    for (unsigned int i = 0; i < local.size(); ++i)
      {
        const double v = points.factor(i) * value(i);
        if (v != 0.0)
          add_vector(i, k * v, dst);
      }
    dst.compress(VectorOperation::add);
  }


  void
  JointDowels::add_force(const TermState &state, LA::MPI::Vector &force) const
  {
    add_on_every_rank(force);
    for (unsigned int i = 0; i < local.size(); ++i)
      if (status()[i] != DowelLaw::slack)
        add_vector(i, stiffness() * jump_of(i, state.ghosted_u), force);
    force.compress(VectorOperation::add);
  }


  double
  JointDowels::energy(const TermState &state) const
  {
    double energy = 0;
    for (unsigned int i = 0; i < local.size(); ++i)
      if (status()[i] != DowelLaw::slack)
        energy += 0.5 * stiffness() * dowel_sites[local[i].index].share
                  * std::pow(jump_of(i, state.ghosted_u)
                               - looseness * DowelLaw::offset_sign(status()[i]),
                             2);
    return Utilities::MPI::sum(energy, discretization->mpi_communicator);
  }


  double
  JointDowels::status_load_work(const LA::MPI::Vector &ghosted_u) const
  {
    // A dowel's F [w] = C ([w] - g s) [w] is 2 E + C g s ([w] - g s): its
    // stored energy is half its work less this.
    double work = 0;
    for (unsigned int i = 0; i < local.size(); ++i)
      {
        const double offset = looseness * DowelLaw::offset_sign(status()[i]);
        work += stiffness() * dowel_sites[local[i].index].share * offset
                * (offset - jump_of(i, ghosted_u));
      }
    return Utilities::MPI::sum(work, discretization->mpi_communicator);
  }


  std::vector<double>
  JointDowels::forces(const LA::MPI::Vector &ghosted_u) const
  {
    std::vector<double> force(dowel_sites.size(), 0.0);
    for (unsigned int i = 0; i < local.size(); ++i)
      if (status()[i] != DowelLaw::slack)
        force[local[i].index] =
          stiffness()
          * (jump_of(i, ghosted_u)
             - looseness * DowelLaw::offset_sign(status()[i]));
    Utilities::MPI::sum(force, discretization->mpi_communicator, force);
    return force;
  }


  void
  JointDowels::save(OutputArchive &archive) const
  {
    save_status(archive);
  }


  void
  JointDowels::load(InputArchive &archive)
  {
    load_status(archive, "dowels");
  }
} // namespace liftoff
