#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/joint_springs.h>
#include <liftoff/fem/plate_fields.h>

#include <cmath>
#include <limits>
#include <tuple>

namespace liftoff
{
  namespace
  {
    std::vector<double>
    stiffnesses(const std::string &text, const std::string &entry)
    {
      std::vector<double> values;
      for (const std::string &item : Utilities::split_string_list(text))
        {
          const double value = Utilities::string_to_double(item);
          AssertThrow(std::isfinite(value) && value >= 0,
                      ExcMessage("Slabs/" + entry + " = " + text + ": " + item
                                 + " is no stiffness; each value must be a "
                                   "finite number >= 0."));
          values.push_back(value);
        }
      AssertThrow(!values.empty(),
                  ExcMessage("Slabs/" + entry
                             + " is empty: give one value for every joint, "
                               "or one per joint."));
      return values;
    }
  } // namespace


  void
  JointSprings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Slabs");
    prm.declare_entry(
      "Shear stiffness",
      "0",
      Patterns::List(Patterns::Double(), 1, 64),
      "AGG, the aggregate interlock of the joints that are not tied: the "
      "shear force per unit length of joint per unit jump of w across it "
      "(N/m^2 in an SI scene; AGG L^3 / D dimensionless). One value for "
      "every joint, or one per joint of the whole plate in the order x1, x2, "
      "..., y1, y2, ... (a mesh file's in its order; also on a half or "
      "quarter model, which takes its joints' values), or one per modelled "
      "joint; 0: the joint passes no shear (free)."
        + quantity("pressure"));
    prm.declare_entry(
      "Rotational stiffness",
      "0",
      Patterns::List(Patterns::Double(), 1, 64),
      "The moment per unit length of joint per unit jump of the rotation "
      "about the joint's line (N m / m per radian, that is N, in an SI "
      "scene; R L / D dimensionless), as Shear stiffness: one value or one "
      "per joint; 0: no moment passes."
        + quantity("force"));
    prm.leave_subsection();
  }


  void
  JointSprings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Slabs");
    shear_stiffness =
      stiffnesses(prm.get("Shear stiffness"), "Shear stiffness");
    rotational_stiffness =
      stiffnesses(prm.get("Rotational stiffness"), "Rotational stiffness");
    prm.leave_subsection();
  }


  void
  JointSprings::check_against(const SlabLayout &slabs) const
  {
    const std::size_t n = slabs.n_joints_of_plate();
    std::string       modelled;
    for (const Joint &joint : slabs.joints())
      modelled += (modelled.empty() ? "" : ", ") + joint.name;
    for (const auto &[values, entry] :
         {std::make_pair(&shear_stiffness, "Shear stiffness"),
          std::make_pair(&rotational_stiffness, "Rotational stiffness")})
      AssertThrow(values->size() == 1 || values->size() == n
                    || values->size() == slabs.joints().size(),
                  ExcMessage("Slabs/" + std::string(entry) + " has "
                             + std::to_string(values->size())
                             + " values; the plate has " + std::to_string(n)
                             + " joints (x1, x2, ..., y1, ...), the "
                               "modelled part "
                             + std::to_string(slabs.joints().size()) + " ("
                             + modelled
                             + "): give one value, one per joint of the "
                               "plate, or one per modelled joint."));
  }


  double
  JointSprings::stiffness_of(const std::vector<double> &values,
                             const unsigned int         joint) const
  {
    // A list per joint of the whole plate (as Thicknesses counts slabs),
    // or, as the modelled part has them, per modelled joint.
    const SlabLayout &slabs = discretization->geometry().slabs();
    if (values.size() == 1)
      return values[0];
    return values.size() == slabs.n_joints_of_plate()
             ? values[slabs.joints()[joint].number]
             : values[joint];
  }


  void
  JointSprings::setup(const Discretization &disc)
  {
    discretization = &disc;
    segments.clear();
    w_dofs =
      DoFTools::extract_dofs(disc.dof_handler,
                             PlateFields::w_mask(disc.dof_handler.get_fe()));
    const SlabLayout &slabs = disc.geometry().slabs();
    has_springs             = false;
    for (unsigned int j = 0; j < slabs.joints().size(); ++j)
      has_springs = has_springs
                    || (!slabs.joints()[j].tied
                        && (stiffness_of(shear_stiffness, j) > 0
                            || stiffness_of(rotational_stiffness, j) > 0));
    slabs.for_each_joint_face(
      disc.dof_handler,
      [&](const DoFHandler<2>::active_cell_iterator &cell,
          const unsigned int                         face,
          const unsigned int                         joint) {
        segments.push_back(make_segment(cell, face, joint));
      });
    // Free joints keep their segments for transfer() only.
    if (has_springs)
      assemble();
  }


  JointSprings::Segment
  JointSprings::make_segment(const DoFHandler<2>::active_cell_iterator &cell,
                             const unsigned int                         face,
                             const unsigned int joint) const
  {
    const FiniteElement<2> &fe      = discretization->dof_handler.get_fe();
    const Mapping<2>       &mapping = discretization->mapping();
    const unsigned int      n       = fe.n_dofs_per_cell();
    const Joint       &j = discretization->geometry().slabs().joints()[joint];
    const unsigned int rotation = PlateFields::rotation(j.normal_axis);

    FEFaceValues<2> here(mapping,
                         fe,
                         QGauss<1>(fe.degree + 1),
                         update_values | update_quadrature_points
                           | update_JxW_values);
    here.reinit(cell, face);
    // On a symmetry plane the other side is this cell's mirror image: the
    // same w, the opposite psi . n; the modelled part carries half the
    // joint's energy.
    const auto opposite = discretization->geometry().slabs().across(cell, face);
    const int  mirror   = j.on_plane ? -1 : 1;
    const double          share = j.on_plane ? 0.5 : 1.0;
    std::vector<Point<2>> unit_points;
    for (const Point<2> &p : here.get_quadrature_points())
      unit_points.push_back(mapping.transform_real_to_unit_cell(opposite, p));
    FEValues<2> there(mapping, fe, Quadrature<2>(unit_points), update_values);
    there.reinit(opposite);
    // The mirror's values are this side's, so that [w] is exactly 0.
    const FEValuesBase<2> &other =
      j.on_plane ? static_cast<const FEValuesBase<2> &>(here) : there;
    Segment segment;
    segment.joint = joint;
    segment.sign  = cell->face(face)->boundary_id() == j.lower_side ? 1 : -1;
    segment.dofs.resize(2 * n);
    std::vector<types::global_dof_index> opposite_dofs(n);
    cell->get_dof_indices(segment.dofs);
    segment.dofs.resize(n);
    opposite->get_dof_indices(opposite_dofs);
    segment.dofs.insert(segment.dofs.end(),
                        opposite_dofs.begin(),
                        opposite_dofs.end());
    for (const unsigned int q : here.quadrature_point_indices())
      {
        const double        root = std::sqrt(share * here.JxW(q));
        std::vector<double> w(2 * n), psi(2 * n);
        const unsigned int  of_w = PlateFields::w;
        for (unsigned int i = 0; i < n; ++i)
          {
            w[i]     = root * here.shape_value_component(i, q, of_w);
            w[n + i] = -root * other.shape_value_component(i, q, of_w);
            psi[i]   = root * here.shape_value_component(i, q, rotation);
            psi[n + i] =
              -mirror * root * other.shape_value_component(i, q, rotation);
          }
        segment.w_jump.push_back(w);
        segment.rotation_jump.push_back(psi);
      }
    segment.points = here.get_quadrature_points();
    return segment;
  }


  void
  JointSprings::assemble()
  {
    const Discretization  &disc = *discretization;
    DynamicSparsityPattern pattern(disc.locally_relevant_dofs.size(),
                                   disc.locally_relevant_dofs.size(),
                                   disc.locally_relevant_dofs);
    for (const Segment &segment : segments)
      disc.constraints.add_entries_local_to_global(segment.dofs,
                                                   pattern,
                                                   false);
    SparsityTools::distribute_sparsity_pattern(pattern,
                                               disc.locally_owned_dofs,
                                               disc.mpi_communicator,
                                               disc.locally_relevant_dofs);
    springs.reinit(disc.locally_owned_dofs,
                   disc.locally_owned_dofs,
                   pattern,
                   disc.mpi_communicator);
    for (const Segment &segment : segments)
      {
        const std::size_t m   = segment.dofs.size();
        const double      agg = stiffness_of(shear_stiffness, segment.joint);
        const double      r = stiffness_of(rotational_stiffness, segment.joint);
        FullMatrix<double> local(m, m);
        for (unsigned int q = 0; q < segment.w_jump.size(); ++q)
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int k = 0; k < m; ++k)
              local(i, k) +=
                agg * segment.w_jump[q][i] * segment.w_jump[q][k]
                + r * segment.rotation_jump[q][i] * segment.rotation_jump[q][k];
        disc.constraints.distribute_local_to_global(local,
                                                    segment.dofs,
                                                    springs);
      }
    springs.compress(VectorOperation::add);
  }


  std::vector<SystemTerm::Coupling>
  JointSprings::couplings() const
  {
    const Discretization &disc   = *discretization;
    const auto           &joints = disc.geometry().slabs().joints();
    std::vector<Coupling> result;
    for (unsigned int j = 0; j < joints.size(); ++j)
      for (const auto &[values, entry, of_rotation] :
           {std::make_tuple(&shear_stiffness, "Shear stiffness", false),
            std::make_tuple(&rotational_stiffness,
                            "Rotational stiffness",
                            true)})
        {
          const double value = stiffness_of(*values, j);
          if (joints[j].tied || value == 0)
            continue;
          Coupling coupling{"Slabs/" + std::string(entry) + " (joint "
                              + joints[j].name + ")",
                            value,
                            {}};
          disc.reinit_vector(coupling.diagonal_per_unit);
          for (const Segment &segment : segments)
            if (segment.joint == j)
              {
                Vector<double> diagonal(segment.dofs.size());
                for (const auto &jump :
                     of_rotation ? segment.rotation_jump : segment.w_jump)
                  for (unsigned int i = 0; i < jump.size(); ++i)
                    diagonal[i] += jump[i] * jump[i];
                disc.constraints.distribute_local_to_global(
                  diagonal, segment.dofs, coupling.diagonal_per_unit);
              }
          coupling.diagonal_per_unit.compress(VectorOperation::add);
          result.push_back(std::move(coupling));
        }
    return result;
  }


  void
  JointSprings::add_to_matrix(const MatrixFactors &,
                              LA::MPI::SparseMatrix &matrix)
  {
    if (has_springs)
      matrix.add(1.0, springs);
  }


  void
  JointSprings::add_force(const TermState &state, LA::MPI::Vector &force) const
  {
    if (!has_springs)
      return;
    springs.vmult(state.scratch, state.u);
    force += state.scratch;
  }


  double
  JointSprings::energy(const TermState &state) const
  {
    if (!has_springs)
      return 0;
    springs.vmult(state.scratch, state.u);
    // The constrained rows hold a diagonal of their own, not the joint's.
    discretization->constraints.set_zero(state.scratch);
    return 0.5 * (state.scratch * state.u);
  }


  std::array<double, 3>
  JointSprings::sides(const Segment             &segment,
                      const std::vector<double> &jump,
                      const LA::MPI::Vector     &ghosted_u)
  {
    // Each side's w times sqrt(JxW), and sqrt(JxW) itself as the sum of its
    // w shape values (a partition of unity).
    const std::size_t n    = segment.dofs.size() / 2;
    double            here = 0, there = 0, root = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        here += jump[i] * ghosted_u(segment.dofs[i]);
        there -= jump[n + i] * ghosted_u(segment.dofs[n + i]);
        root += jump[i];
      }
    return {{here, there, root}};
  }


  double
  JointSprings::load_transfer(const double a,
                              const double b,
                              const double reference)
  {
    const double larger = std::max(std::abs(a), std::abs(b));
    if (larger < far_load_fraction * reference || reference == 0)
      return std::numeric_limits<double>::quiet_NaN();
    // + 0.0: a side at rest gives 0, not -0.
    return (std::abs(a) < std::abs(b) ? a / b : b / a) + 0.0;
  }


  double
  JointSprings::largest_load_deflection(
    const LA::MPI::Vector &ghosted_u,
    const LA::MPI::Vector &ghosted_rest) const
  {
    std::vector<double> largest(2, 0.0);
    for (const auto i : w_dofs)
      {
        largest[0] =
          std::max(largest[0], std::abs(ghosted_u(i) - ghosted_rest(i)));
        largest[1] = std::max(largest[1], std::abs(ghosted_rest(i)));
      }
    Utilities::MPI::max(largest, discretization->mpi_communicator, largest);
    // A plate at rest drifts by round-off (1e-10 of its settled w over a
    // run without another load): no load's part.
    return largest[0] > 1e-6 * largest[1] ? largest[0] : 0.0;
  }


  std::vector<JointSprings::JointPoint>
  JointSprings::points_along(const LA::MPI::Vector &ghosted_u,
                             const LA::MPI::Vector &ghosted_rest) const
  {
    const double reference = largest_load_deflection(ghosted_u, ghosted_rest);
    std::vector<JointPoint> points;
    for (const Segment &segment : segments)
      {
        const double agg = stiffness_of(shear_stiffness, segment.joint);
        for (unsigned int q = 0; q < segment.points.size(); ++q)
          {
            const auto [here, there, root] =
              sides(segment, segment.w_jump[q], ghosted_u);
            const auto [here_0, there_0, root_0] =
              sides(segment, segment.w_jump[q], ghosted_rest);
            const double lower = (segment.sign > 0 ? here : there) / root;
            const double upper = (segment.sign > 0 ? there : here) / root;
            points.push_back({segment.joint,
                              segment.points[q],
                              lower,
                              upper,
                              load_transfer((here - here_0) / root,
                                            (there - there_0) / root,
                                            reference),
                              agg * (lower - upper) + 0.0});
          }
      }
    return points;
  }


  std::vector<JointSprings::Transfer>
  JointSprings::transfer(const LA::MPI::Vector &ghosted_u,
                         const LA::MPI::Vector &ghosted_rest) const
  {
    const unsigned int n_joints =
      discretization->geometry().slabs().joints().size();
    std::vector<double> force(n_joints, 0.0);
    // Per joint: the largest change of w of a side since rest, and the
    // other side's change there.
    std::vector<std::array<double, 2>> loaded(n_joints, {{0.0, 0.0}});
    for (const Segment &segment : segments)
      {
        const double agg = stiffness_of(shear_stiffness, segment.joint);
        for (const std::vector<double> &jump : segment.w_jump)
          {
            const auto [here, there, root] = sides(segment, jump, ghosted_u);
            const auto [here_0, there_0, root_0] =
              sides(segment, jump, ghosted_rest);
            force[segment.joint] += segment.sign * agg * (here - there) * root;
            const double a = (here - here_0) / root,
                         b = (there - there_0) / root;
            if (std::max(std::abs(a), std::abs(b))
                > std::abs(loaded[segment.joint][0]))
              loaded[segment.joint] = std::abs(a) > std::abs(b)
                                        ? std::array<double, 2>{{a, b}}
                                        : std::array<double, 2>{{b, a}};
          }
      }
    const MPI_Comm comm = discretization->mpi_communicator;
    Utilities::MPI::sum(force, comm, force);
    // A joint that crosses a symmetry plane goes on in the mirror image,
    // which passes the same force.
    const PlateGeometry &geometry = discretization->geometry();
    for (unsigned int j = 0; j < n_joints; ++j)
      for (const unsigned int axis : geometry.symmetry_axes())
        if (axis != geometry.slabs().joints()[j].normal_axis)
          force[j] *= 2;
    const double reference = largest_load_deflection(ghosted_u, ghosted_rest);
    const auto   all       = Utilities::MPI::all_gather(comm, loaded);
    std::vector<Transfer> result(n_joints);
    for (unsigned int j = 0; j < n_joints; ++j)
      {
        result[j].shear_force = force[j] + 0.0;
        std::array<double, 2> largest{{0.0, 0.0}};
        for (const auto &rank : all)
          if (std::abs(rank[j][0]) > std::abs(largest[0]))
            largest = rank[j];
        // A tied joint is one slab: it transfers all.
        result[j].efficiency =
          geometry.slabs().joints()[j].tied
            ? 1.0
            : load_transfer(largest[0], largest[1], reference);
      }
    return result;
  }
} // namespace liftoff
