#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <functional>
#include <limits>

#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/contact/tensionless_winkler_foundation.h>

#include <cmath>

namespace liftoff
{
  namespace
  {
    using Model                        = TensionlessWinklerFoundation::Model;
    const Selection<Model> model_names = {{"tensionless", Model::tensionless},
                                          {"bilateral", Model::bilateral},
                                          {"none", Model::none}};
  } // namespace


  void
  TensionlessWinklerFoundation::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Foundation");
    prm.declare_entry("Model",
                      "tensionless",
                      model_names.pattern(),
                      "tensionless: springs act only where w > 0; bilateral: "
                      "linear springs of both signs (for checks); none: no "
                      "foundation.");
    prm.declare_entry("Stiffness",
                      "1",
                      Patterns::Double(0.0, 1e12),
                      "Gamma = K_f L^4 / D, the dimensionless Winkler "
                      "modulus (at most 1e12: beyond it the plate's "
                      "stiffness is lost in the bed's in double precision; "
                      "at 1e16 a static run gave w 3e4 times too large "
                      "with a balanced energy, doc/reliability.md).");
    prm.declare_entry(
      "Contact tolerance",
      "1e-9",
      Patterns::Double(0.0, 1e-3),
      "Round-off band of the contact rule, relative to max |w_h| over all "
      "Gauss points of the plate: a point comes into contact when w_h rises "
      "above tolerance * max |w_h| and leaves it when w_h falls below "
      "-tolerance * max |w_h|; inside the band it keeps its status. There "
      "the sign of w_h would depend on the linear solver and the number of "
      "ranks. 0 gives the bare rule w_h > 0. At most 1e-3: a point in the "
      "band may keep or lack a spring force of up to tolerance * Gamma * "
      "max |w_h|, so the band perturbs the foundation pressure by up to "
      "tolerance times its peak; 1e-3 still covers the worst round-off the "
      "Plate bounds admit (6e-4 at Delta = 1e-5), while a tolerance of 1 "
      "freezes every status and makes the foundation bilateral.");
    prm.declare_entry(
      "Initial gap",
      "0",
      Patterns::Anything(),
      "g(x, y), muParser in x, y of the full plate: the distance between the "
      "unloaded plate and the bed, in the unit of w, F0 L^2 / D (w is "
      "positive into the bed). The springs act where w > g with the pressure "
      "Gamma (w - g): "
      "g > 0 is a gap (a curled slab, a void), g < 0 a pre-compression (a "
      "settled support). Must be finite on the plate, and symmetric on a "
      "half or quarter model. The contact tolerance applies to w - g.");
    prm.declare_entry(
      "Damping",
      "0",
      Patterns::Double(0.0, 1e8),
      "c = C_f L^2 / sqrt(rho H D), dashpots per unit area beside the "
      "springs (a viscous subgrade; 0: none; at most 1e8, where the "
      "contact set of a point load no longer settles). They act only in "
      "contact, "
      "and the pressure Gamma (w - g) + c w_dot is never tensile: where "
      "spring and dashpot together would pull, the point is out of contact "
      "(doc/model.md). The dissipated energy becomes a history column.");
    prm.declare_entry(
      "Shear modulus",
      "0",
      Patterns::Double(0.0, 1e12),
      "G_p = G_f L^2 / D, the dimensionless shear modulus of a Pasternak "
      "shear layer on the springs (0: none, a Winkler bed; at most 1e12: at "
      "1e14 the energy balance is off by 1.4e-3, at 1e20 by its whole "
      "size). The layer "
      "stores 1/2 G_p |grad w|^2 per unit area over the contact region "
      "(the whole plate when bilateral) and adds -G_p Lap w to the "
      "foundation pressure there. Tensionless: the layer acts only where "
      "the plate is in contact, the layer outside is not modelled "
      "(doc/model.md); the contact rule w > g is unchanged.");
    prm.leave_subsection();
  }


  void
  TensionlessWinklerFoundation::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Foundation");
    model             = model_names.parse(prm.get("Model"), "Foundation/Model");
    stiffness         = prm.get_double("Stiffness");
    contact_tolerance = prm.get_double("Contact tolerance");
    gap_expression    = prm.get("Initial gap");
    damping           = prm.get_double("Damping");
    shear_modulus     = prm.get_double("Shear modulus");
    prm.leave_subsection();
    // A broken expression is refused now, before any mesh is built.
    parse_expression<2>(
      "Foundation/Initial gap", gap_expression, 1, "x,y", false);
    AssertThrow(model == Model::none || stiffness > 0,
                ExcMessage("Foundation/Stiffness (Gamma) must be > 0, or set "
                           "Foundation/Model = none."));
  }


  void
  TensionlessWinklerFoundation::setup(const Discretization &disc)
  {
    discretization     = &disc;
    const auto     &fe = *disc.fe;
    const QGauss<2> rule(fe.degree + 1);
    n_q_points = rule.size();

    w_dofs.clear();
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == 0)
        w_dofs.push_back(i);

    // Lagrange shape values at the Gauss points do not depend on the cell.
    shape_values.reinit(n_q_points, w_dofs.size());
    for (unsigned int q = 0; q < n_q_points; ++q)
      for (unsigned int k = 0; k < w_dofs.size(); ++k)
        shape_values(q, k) = fe.shape_value(w_dofs[k], rule.point(q));

    // Gradients only for a shear layer: they depend on the cell.
    FEValues<2>                          fe_values(disc.mapping,
                          fe,
                          rule,
                          update_JxW_values | update_quadrature_points
                            | (has_layer() ? update_gradients
                                                                    : update_default));
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    cell_w_dof_indices.clear();
    local_positions.clear();
    cell_w_dof_is_constrained.clear();
    cell_has_hanging_node.clear();
    cell_index.clear();
    jxw.clear();
    gauss_points.clear();
    shape_gradients.clear();
    for (const auto &cell : disc.locally_owned_cells())
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
        bool is_hanging = false;
        for (const unsigned int i : w_dofs)
          {
            cell_w_dof_indices.push_back(dofs[i]);
            // Constraints w_i = 0 (edges) drop a row and column of the
            // cell term; a hanging node (w_i a combination of other
            // nodes) sends them to those nodes (add_cell_term()).
            const auto *entries =
              disc.constraints.get_constraint_entries(dofs[i]);
            is_hanging = is_hanging || (entries && !entries->empty());
            cell_w_dof_is_constrained.push_back(
              disc.constraints.is_constrained(dofs[i]));
          }
        cell_has_hanging_node.push_back(is_hanging);
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            jxw.push_back(fe_values.JxW(q));
            gauss_points.push_back(fe_values.quadrature_point(q));
            if (has_layer())
              for (const unsigned int i : w_dofs)
                shape_gradients.push_back(fe_values.shape_grad(i, q));
          }
        cell_index.push_back(cell->active_cell_index());
      }
    in_contact.assign(jxw.size(), model == Model::none ? 0 : 1);
    w_at_points.resize(jxw.size());
    in_matrix = in_contact;
    points_to_update.clear();
    evaluate_gap();
  }


  void
  TensionlessWinklerFoundation::evaluate_gap()
  {
    gap.clear();
    effective_gap.clear();
    is_gapped           = false;
    is_precompressed    = false;
    is_affine           = false;
    effective_stiffness = stiffness;
    matrix_stiffness    = stiffness;
    if (model == Model::none)
      return;
    const std::string name = "Foundation/Initial gap";
    const auto g = parse_expression<2>(name, gap_expression, 1, "x,y", false);
    // A half or quarter model is right only if the bed is symmetric too:
    // compare g at each point with its images in the symmetry planes.
    const std::vector<unsigned int> axes = discretization->symmetry_axes();
    std::vector<double>             values(jxw.size());
    bool is_finite = true, is_symmetric = true, is_zero = true;
    bool is_pressed = false;
    for (unsigned int i = 0; i < jxw.size(); ++i)
      {
        values[i] = g->value(gauss_points[i]);
        // Beyond 1e100 the bed's force Gamma g and its energy overflow
        // before anything else does.
        is_finite  = is_finite && std::abs(values[i]) <= 1e100;
        is_zero    = is_zero && values[i] == 0.0;
        is_pressed = is_pressed || values[i] < 0.0;
        for (const unsigned int axis : axes)
          {
            Point<2> image = gauss_points[i];
            image[axis]    = -image[axis];
            is_symmetric   = is_symmetric
                           && std::abs(g->value(image) - values[i])
                                <= 1e-12 * (1.0 + std::abs(values[i]));
          }
      }
    const MPI_Comm comm = discretization->mpi_communicator;
    AssertThrow(Utilities::MPI::min(int(is_finite), comm) == 1,
                ExcMessage(name + " = <" + abbreviated(gap_expression)
                           + "> is not a finite number of at most 1e100 in "
                             "magnitude at some Gauss point of the plate; it "
                             "must be one everywhere."));
    AssertThrow(Utilities::MPI::min(int(is_symmetric), comm) == 1,
                ExcMessage(name + " = <" + abbreviated(gap_expression)
                           + "> is not symmetric about the symmetry planes "
                             "of Discretization/Symmetry; model the full "
                             "plate or give a symmetric gap."));
    // Decided on all ranks alike: a rank without cells takes part in the
    // collective calls of the gap too.
    is_gapped        = (Utilities::MPI::min(int(is_zero), comm) == 0);
    is_precompressed = (Utilities::MPI::max(int(is_pressed), comm) == 1);
    if (is_gapped)
      {
        gap = std::move(values);
        gap_function =
          parse_expression<2>(name, gap_expression, 1, "x,y", false);
      }
    // Dashpots make the reaction affine with a moving gap (set each step).
    is_affine = is_gapped || damping > 0;
    if (is_affine)
      effective_gap = (is_gapped ? gap : std::vector<double>(jxw.size(), 0.0));
  }


  bool
  TensionlessWinklerFoundation::has_gap() const
  {
    return is_affine;
  }


  bool
  TensionlessWinklerFoundation::has_initial_gap() const
  {
    return is_gapped;
  }


  double
  TensionlessWinklerFoundation::rigid_body_frequency() const
  {
    return model == Model::none ? 0.0 : std::sqrt(stiffness);
  }


  bool
  TensionlessWinklerFoundation::is_pressing_plate() const
  {
    return is_precompressed;
  }


  double
  TensionlessWinklerFoundation::gap_at(const Point<2> &p) const
  {
    return is_gapped ? gap_function->value(p) : 0.0;
  }


  bool
  TensionlessWinklerFoundation::has_layer() const
  {
    return model != Model::none && shear_modulus > 0;
  }


  bool
  TensionlessWinklerFoundation::has_damping() const
  {
    return model != Model::none && damping > 0;
  }


  void
  TensionlessWinklerFoundation::set_matrix_velocity_factor(const double kappa)
  {
    matrix_stiffness =
      (has_damping() ? stiffness + damping * kappa : stiffness);
  }


  void
  TensionlessWinklerFoundation::set_dashpot_velocity(
    const double           kappa,
    const LA::MPI::Vector &offset)
  {
    Assert(has_damping(), ExcInternalError());
    // Gamma (w - g) + c (kappa w - o) = (Gamma + c kappa) (w - e).
    effective_stiffness = stiffness + damping * kappa;
    std::vector<double> o;
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        deflection_at_gauss_points(offset, c, o);
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const unsigned int i = c * n_q_points + q;
            effective_gap[i] =
              ((is_gapped ? stiffness * gap[i] : 0.0) + damping * o[q])
              / effective_stiffness;
          }
      }
  }


  void
  TensionlessWinklerFoundation::add_dashpot_force(const LA::MPI::Vector &v,
                                                  LA::MPI::Vector &vector) const
  {
    add_contact_integral(
      damping,
      [&](const unsigned int c, std::vector<double> &v_at_points) {
        deflection_at_gauss_points(v, c, v_at_points);
      },
      vector);
  }


  TensionlessWinklerFoundation::PressureRange
  TensionlessWinklerFoundation::pressure_range(const LA::MPI::Vector &u,
                                               const LA::MPI::Vector &v) const
  {
    PressureRange       range;
    std::vector<double> w, v_at_points;
    double              smallest = std::numeric_limits<double>::max();
    double              largest  = -std::numeric_limits<double>::max();
    double              size     = 0;
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        deflection_at_gauss_points(u, c, w);
        deflection_at_gauss_points(v, c, v_at_points);
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const unsigned int i = c * n_q_points + q;
            const double       pressure =
              stiffness * (w[q] - (is_gapped ? gap[i] : 0.0))
              + damping * v_at_points[q];
            size = std::max(size, std::abs(pressure));
            if (in_contact[i])
              smallest = std::min(smallest, pressure);
            else
              largest = std::max(largest, pressure);
          }
      }
    const MPI_Comm comm          = discretization->mpi_communicator;
    range.smallest_in_contact    = Utilities::MPI::min(smallest, comm);
    range.largest_out_of_contact = Utilities::MPI::max(largest, comm);
    range.largest_magnitude      = Utilities::MPI::max(size, comm);
    return range;
  }


  void
  TensionlessWinklerFoundation::set_status(const unsigned int  i,
                                           const unsigned char status)
  {
    if (in_contact[i] == status)
      return;
    in_contact[i] = status;
    points_to_update.push_back(i);
  }


  const std::vector<unsigned char> &
  TensionlessWinklerFoundation::contact_status() const
  {
    return in_contact;
  }


  void
  TensionlessWinklerFoundation::set_contact_status(
    const std::vector<unsigned char> &status)
  {
    AssertDimension(status.size(), in_contact.size());
    for (unsigned int i = 0; i < status.size(); ++i)
      set_status(i, status[i]);
  }


  void
  TensionlessWinklerFoundation::activate_all()
  {
    if (model != Model::none)
      for (unsigned int i = 0; i < in_contact.size(); ++i)
        set_status(i, 1);
  }


  const int *
  TensionlessWinklerFoundation::positions_in(const LA::MPI::Vector &u,
                                             const bool owned_only) const
  {
    const Epetra_BlockMap &map = u.trilinos_vector().Map();
    for (const auto &known : local_positions)
      if (known.map->DataPtr() == map.DataPtr()
          && known.owned_only == owned_only)
        return known.positions.data();
    // The program's ghosted vectors come in a few layouts (solution,
    // velocity, scratch), and the solver's products one owned layout; a
    // few more would mean layouts made per call.
    if (local_positions.size() == 5)
      local_positions.erase(local_positions.begin());
    LocalPositions known;
    known.map        = std::make_unique<Epetra_BlockMap>(map);
    known.owned_only = owned_only;
    known.positions.reserve(cell_w_dof_indices.size());
    for (const auto index : cell_w_dof_indices)
      {
        const int position = map.LID(static_cast<int>(index));
        AssertThrow(position >= 0 || owned_only,
                    ExcMessage("The foundation reads w_h from a vector "
                               "without the ghost entries of its cells."));
        known.positions.push_back(position);
      }
    local_positions.push_back(std::move(known));
    return local_positions.back().positions.data();
  }


  void
  TensionlessWinklerFoundation::deflection_at_gauss_points(
    const LA::MPI::Vector &u,
    const unsigned int     c,
    std::vector<double>   &w) const
  {
    const unsigned int n_w       = w_dofs.size();
    const int         *positions = positions_in(u) + c * n_w;
    const double      *values    = u.trilinos_vector()[0];
    w.assign(n_q_points, 0.0);
    for (unsigned int k = 0; k < n_w; ++k)
      {
        const double u_k = values[positions[k]];
        for (unsigned int q = 0; q < n_q_points; ++q)
          w[q] += shape_values(q, k) * u_k;
      }
  }


  void
  TensionlessWinklerFoundation::compression_at_gauss_points(
    const LA::MPI::Vector &u,
    const unsigned int     c,
    std::vector<double>   &compression) const
  {
    deflection_at_gauss_points(u, c, compression);
    if (is_affine)
      for (unsigned int q = 0; q < n_q_points; ++q)
        compression[q] -= effective_gap[c * n_q_points + q];
  }


  unsigned long
  TensionlessWinklerFoundation::update_contact_status(const LA::MPI::Vector &u)
  {
    if (model != Model::tensionless)
      return 0;
    // Two passes: the threshold needs the largest |w_h - g| of the whole
    // plate.
    std::vector<double> w;
    double              largest = 0;
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        compression_at_gauss_points(u, c, w);
        std::copy(w.begin(), w.end(), w_at_points.begin() + c * n_q_points);
        for (const double value : w)
          largest = std::max(largest, std::abs(value));
      }
    const MPI_Comm comm = discretization->mpi_communicator;
    const double   threshold =
      contact_tolerance * Utilities::MPI::max(largest, comm);
    band = threshold;

    unsigned long n_changed = 0;
    for (unsigned int i = 0; i < in_contact.size(); ++i)
      {
        // Hysteresis: within the round-off band a point keeps its status. A
        // one-sided threshold would let a point in a stiff foundation's tail
        // cycle: held below it by its spring, pushed above it without.
        const double        w = w_at_points[i];
        const unsigned char now =
          (in_contact[i] ? w > -threshold : w > threshold);
        n_changed += (now != in_contact[i]);
        set_status(i, now);
      }
    return Utilities::MPI::sum(n_changed, comm);
  }


  unsigned long
  TensionlessWinklerFoundation::keep_status_in_band(
    const std::vector<unsigned char> &earlier)
  {
    AssertDimension(earlier.size(), in_contact.size());
    unsigned long n_changed = 0;
    if (model == Model::tensionless)
      for (unsigned int i = 0; i < in_contact.size(); ++i)
        if (std::abs(w_at_points[i]) <= band && in_contact[i] != earlier[i])
          {
            set_status(i, earlier[i]);
            ++n_changed;
          }
    return Utilities::MPI::sum(n_changed, discretization->mpi_communicator);
  }


  void
  TensionlessWinklerFoundation::add_cell_term(
    const unsigned int         c,
    const std::vector<double> &weight,
    const std::vector<double> &layer_weight,
    LA::MPI::SparseMatrix     &matrix) const
  {
    const unsigned int n_w = w_dofs.size();
    FullMatrix<double> cell_matrix(n_w, n_w);
    for (unsigned int q = 0; q < n_q_points; ++q)
      if (weight[q] != 0.0)
        for (unsigned int i = 0; i < n_w; ++i)
          for (unsigned int j = 0; j < n_w; ++j)
            cell_matrix(i, j) +=
              weight[q] * shape_values(q, i) * shape_values(q, j);
    // The shear layer at the same points: the same status, one path.
    if (has_layer())
      for (unsigned int q = 0; q < n_q_points; ++q)
        if (layer_weight[q] != 0.0)
          {
            const Tensor<1, 2> *grad =
              &shape_gradients[(c * n_q_points + q) * n_w];
            for (unsigned int i = 0; i < n_w; ++i)
              for (unsigned int j = 0; j < n_w; ++j)
                cell_matrix(i, j) += layer_weight[q] * (grad[i] * grad[j]);
          }

    if (cell_has_hanging_node[c])
      {
        add_condensed(c, cell_matrix, matrix);
        return;
      }
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    for (unsigned int i = 0; i < n_w; ++i)
      {
        if (cell_w_dof_is_constrained[c * n_w + i])
          continue;
        columns.clear();
        values.clear();
        for (unsigned int j = 0; j < n_w; ++j)
          if (!cell_w_dof_is_constrained[c * n_w + j])
            {
              columns.push_back(cell_w_dof_indices[c * n_w + j]);
              values.push_back(cell_matrix(i, j));
            }
        matrix.add(cell_w_dof_indices[c * n_w + i], columns, values, false);
      }
  }


  void
  TensionlessWinklerFoundation::add_condensed(
    const unsigned int        c,
    const FullMatrix<double> &cell_matrix,
    LA::MPI::SparseMatrix    &matrix) const
  {
    // Row and column i of the cell go to the nodes w_i depends on, with
    // its weights: itself, the masters of a hanging node, or none (w_i =
    // 0). All constraints here are homogeneous.
    const unsigned int n_w         = w_dofs.size();
    const auto        &constraints = discretization->constraints;
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>
      targets(n_w);
    for (unsigned int i = 0; i < n_w; ++i)
      {
        const auto dof = cell_w_dof_indices[c * n_w + i];
        if (!constraints.is_constrained(dof))
          targets[i] = {{dof, 1.0}};
        else if (const auto *entries = constraints.get_constraint_entries(dof))
          targets[i].assign(entries->begin(), entries->end());
      }
    for (unsigned int i = 0; i < n_w; ++i)
      for (const auto &[row, row_weight] : targets[i])
        for (unsigned int j = 0; j < n_w; ++j)
          for (const auto &[column, column_weight] : targets[j])
            matrix.add(row,
                       column,
                       row_weight * column_weight * cell_matrix(i, j));
  }


  void
  TensionlessWinklerFoundation::add_to_matrix(LA::MPI::SparseMatrix &matrix)
  {
    add_to_matrix(in_contact, matrix);
    in_matrix = in_contact;
    points_to_update.clear();
  }


  void
  TensionlessWinklerFoundation::add_to_matrix(
    const std::vector<unsigned char> &status,
    LA::MPI::SparseMatrix            &matrix) const
  {
    AssertThrow(status.size() == in_contact.size(),
                ExcMessage("A contact status of another mesh."));
    std::vector<double> weight(n_q_points), layer_weight(n_q_points);
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        bool any = false;
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const unsigned int i = c * n_q_points + q;
            weight[q]            = status[i] * matrix_stiffness * jxw[i];
            layer_weight[q]      = status[i] * shear_modulus * jxw[i];
            any                  = any || status[i];
          }
        if (any)
          add_cell_term(c, weight, layer_weight, matrix);
      }
    matrix.compress(VectorOperation::add);
  }


  void
  TensionlessWinklerFoundation::add_change_product(
    const std::vector<unsigned char> &reference,
    const LA::MPI::Vector            &ghosted_src,
    LA::MPI::Vector                  &dst) const
  {
    AssertThrow(reference.size() == in_matrix.size(),
                ExcMessage("A contact status of another mesh."));
    const unsigned int        n_w         = w_dofs.size();
    const int                *positions   = positions_in(dst, true);
    double                   *dst_values  = dst.trilinos_vector()[0];
    const auto               &constraints = discretization->constraints;
    std::vector<double>       w, weight(n_q_points), layer_weight(n_q_points);
    std::vector<Tensor<1, 2>> gradient;
    Vector<double>            cell_vector(n_w);
    std::vector<types::global_dof_index> dofs(n_w), others;
    std::vector<double>                  other_values;
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        const auto first = c * n_q_points;
        if (std::equal(in_matrix.begin() + first,
                       in_matrix.begin() + first + n_q_points,
                       reference.begin() + first))
          continue;
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const double change = static_cast<double>(in_matrix[first + q])
                                  - static_cast<double>(reference[first + q]);
            weight[q]       = change * matrix_stiffness * jxw[first + q];
            layer_weight[q] = change * shear_modulus * jxw[first + q];
          }
        // The cell's term as update_matrix() adds it (add_cell_term()),
        // applied through w at the points instead of assembled: 2 n_q n_w
        // operations instead of n_q n_w^2.
        deflection_at_gauss_points(ghosted_src, c, w);
        for (unsigned int k = 0; k < n_w; ++k)
          {
            double sum = 0;
            for (unsigned int q = 0; q < n_q_points; ++q)
              sum += weight[q] * w[q] * shape_values(q, k);
            cell_vector(k) = sum;
          }
        if (has_layer())
          {
            deflection_gradient_at_gauss_points(ghosted_src, c, gradient);
            for (unsigned int q = 0; q < n_q_points; ++q)
              for (unsigned int k = 0; k < n_w; ++k)
                cell_vector(k) +=
                  layer_weight[q]
                  * (gradient[q] * shape_gradients[(first + q) * n_w + k]);
          }
        if (cell_has_hanging_node[c])
          {
            std::copy(cell_w_dof_indices.begin() + c * n_w,
                      cell_w_dof_indices.begin() + (c + 1) * n_w,
                      dofs.begin());
            constraints.distribute_local_to_global(cell_vector, dofs, dst);
            continue;
          }
        others.clear();
        other_values.clear();
        for (unsigned int k = 0; k < n_w; ++k)
          if (!cell_w_dof_is_constrained[c * n_w + k])
            {
              const int position = positions[c * n_w + k];
              if (position >= 0)
                dst_values[position] += cell_vector(k);
              else
                {
                  others.push_back(cell_w_dof_indices[c * n_w + k]);
                  other_values.push_back(cell_vector(k));
                }
            }
        if (!others.empty())
          dst.add(others, other_values);
      }
    dst.compress(VectorOperation::add);
  }


  const std::vector<unsigned char> &
  TensionlessWinklerFoundation::status_in_matrix() const
  {
    return in_matrix;
  }


  unsigned long
  TensionlessWinklerFoundation::update_matrix(LA::MPI::SparseMatrix &matrix)
  {
    // Points are listed in the order they changed; group them by cell so a
    // cell's entries are added once. A point may have changed and changed
    // back: only a difference from the matrix counts.
    std::sort(points_to_update.begin(), points_to_update.end());
    points_to_update.erase(std::unique(points_to_update.begin(),
                                       points_to_update.end()),
                           points_to_update.end());
    unsigned long       n_updated = 0;
    std::vector<double> weight(n_q_points), layer_weight(n_q_points);
    for (auto p = points_to_update.begin(); p != points_to_update.end();)
      {
        const unsigned int c = *p / n_q_points;
        std::fill(weight.begin(), weight.end(), 0.0);
        std::fill(layer_weight.begin(), layer_weight.end(), 0.0);
        bool any = false;
        for (; p != points_to_update.end() && *p / n_q_points == c; ++p)
          if (in_contact[*p] != in_matrix[*p])
            {
              const double sign             = (in_contact[*p] ? 1.0 : -1.0);
              weight[*p % n_q_points]       = sign * matrix_stiffness * jxw[*p];
              layer_weight[*p % n_q_points] = sign * shear_modulus * jxw[*p];
              in_matrix[*p]                 = in_contact[*p];
              any                           = true;
              ++n_updated;
            }
        if (any)
          add_cell_term(c, weight, layer_weight, matrix);
      }
    points_to_update.clear();
    n_updated =
      Utilities::MPI::sum(n_updated, discretization->mpi_communicator);
    if (n_updated > 0)
      matrix.compress(VectorOperation::add);
    return n_updated;
  }


  void
  TensionlessWinklerFoundation::add_cell_vectors(
    const std::function<void(const unsigned int, Vector<double> &)> &f,
    LA::MPI::Vector &vector) const
  {
    const unsigned int                   n_w = w_dofs.size();
    Vector<double>                       cell_vector(n_w);
    std::vector<types::global_dof_index> dofs(n_w);
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        cell_vector = 0;
        f(c, cell_vector);
        std::copy(cell_w_dof_indices.begin() + c * n_w,
                  cell_w_dof_indices.begin() + (c + 1) * n_w,
                  dofs.begin());
        discretization->constraints.distribute_local_to_global(cell_vector,
                                                               dofs,
                                                               vector);
      }
    vector.compress(VectorOperation::add);
  }


  void
  TensionlessWinklerFoundation::add_contact_integral(
    const double coefficient,
    const std::function<void(const unsigned int, std::vector<double> &)> &f,
    LA::MPI::Vector &vector) const
  {
    const unsigned int  n_w = w_dofs.size();
    std::vector<double> values;
    add_cell_vectors(
      [&](const unsigned int c, Vector<double> &cell_vector) {
        f(c, values);
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const unsigned int i = c * n_q_points + q;
            for (unsigned int k = 0; k < n_w; ++k)
              cell_vector(k) += in_contact[i] * coefficient * jxw[i] * values[q]
                                * shape_values(q, k);
          }
      },
      vector);
  }


  void
  TensionlessWinklerFoundation::deflection_gradient_at_gauss_points(
    const LA::MPI::Vector     &u,
    const unsigned int         c,
    std::vector<Tensor<1, 2>> &gradient) const
  {
    const unsigned int n_w       = w_dofs.size();
    const int         *positions = positions_in(u) + c * n_w;
    const double      *values    = u.trilinos_vector()[0];
    gradient.assign(n_q_points, Tensor<1, 2>());
    for (unsigned int k = 0; k < n_w; ++k)
      {
        const double u_k = values[positions[k]];
        for (unsigned int q = 0; q < n_q_points; ++q)
          gradient[q] += u_k * shape_gradients[(c * n_q_points + q) * n_w + k];
      }
  }


  void
  TensionlessWinklerFoundation::add_reaction(const LA::MPI::Vector &u,
                                             LA::MPI::Vector &vector) const
  {
    if (model == Model::none)
      {
        vector.compress(VectorOperation::add);
        return;
      }
    add_contact_integral(
      stiffness,
      [&](const unsigned int c, std::vector<double> &w) {
        deflection_at_gauss_points(u, c, w);
      },
      vector);
    if (!has_layer())
      return;
    // The layer: G_p int_S grad w . grad phi_i.
    const unsigned int        n_w = w_dofs.size();
    std::vector<Tensor<1, 2>> gradient;
    add_cell_vectors(
      [&](const unsigned int c, Vector<double> &cell_vector) {
        deflection_gradient_at_gauss_points(u, c, gradient);
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const unsigned int i = c * n_q_points + q;
            if (in_contact[i])
              for (unsigned int k = 0; k < n_w; ++k)
                cell_vector(k) +=
                  shear_modulus * jxw[i]
                  * (gradient[q] * shape_gradients[i * n_w + k]);
          }
      },
      vector);
  }


  void
  TensionlessWinklerFoundation::add_gap_load(LA::MPI::Vector &vector) const
  {
    Assert(has_gap(), ExcInternalError());
    add_contact_integral(
      effective_stiffness,
      [&](const unsigned int c, std::vector<double> &e) {
        e.assign(effective_gap.begin() + c * n_q_points,
                 effective_gap.begin() + (c + 1) * n_q_points);
      },
      vector);
  }


  double
  TensionlessWinklerFoundation::gap_work(const LA::MPI::Vector &u) const
  {
    if (!is_gapped)
      return 0;
    double              local = 0;
    std::vector<double> w;
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        deflection_at_gauss_points(u, c, w);
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const unsigned int i = c * n_q_points + q;
            local +=
              in_contact[i] * stiffness * gap[i] * (gap[i] - w[q]) * jxw[i];
          }
      }
    return Utilities::MPI::sum(local, discretization->mpi_communicator);
  }


  double
  TensionlessWinklerFoundation::energy(const LA::MPI::Vector &u) const
  {
    double              local = 0;
    std::vector<double> w;
    if (model != Model::none)
      for (unsigned int c = 0; c < cell_index.size(); ++c)
        {
          // The springs' own compression w - g: the dashpots store nothing.
          deflection_at_gauss_points(u, c, w);
          if (is_gapped)
            for (unsigned int q = 0; q < n_q_points; ++q)
              w[q] -= gap[c * n_q_points + q];
          for (unsigned int q = 0; q < n_q_points; ++q)
            {
              const double compression =
                (model == Model::bilateral ? w[q] : std::max(w[q], 0.0));
              local += 0.5 * stiffness * compression * compression
                       * jxw[c * n_q_points + q];
            }
        }
    if (has_layer())
      local += layer_energy(u);
    return Utilities::MPI::sum(local, discretization->mpi_communicator);
  }


  double
  TensionlessWinklerFoundation::layer_energy(const LA::MPI::Vector &u) const
  {
    // 1/2 G_p int_S |grad w|^2, S the current status (all points when
    // bilateral): the layer acts where the springs do.
    double                    local = 0;
    std::vector<Tensor<1, 2>> gradient;
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        deflection_gradient_at_gauss_points(u, c, gradient);
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const unsigned int i = c * n_q_points + q;
            local += 0.5 * shear_modulus * in_contact[i] * gradient[q]
                     * gradient[q] * jxw[i];
          }
      }
    return local;
  }


  TensionlessWinklerFoundation::Resultant
  TensionlessWinklerFoundation::resultant(const LA::MPI::Vector &u,
                                          const LA::MPI::Vector &v) const
  {
    // Force, its moments about the axes x = 0 and y = 0, area in contact.
    std::vector<double> sums(4, 0.0), w, v_at_points;
    if (model != Model::none)
      for (unsigned int c = 0; c < cell_index.size(); ++c)
        {
          deflection_at_gauss_points(u, c, w);
          if (has_damping())
            deflection_at_gauss_points(v, c, v_at_points);
          for (unsigned int q = 0; q < n_q_points; ++q)
            {
              const unsigned int i = c * n_q_points + q;
              if (!in_contact[i])
                continue;
              const double pressure =
                stiffness * (w[q] - (is_gapped ? gap[i] : 0.0))
                + (has_damping() ? damping * v_at_points[q] : 0.0);
              const double force = pressure * jxw[i];
              sums[0] += force;
              sums[1] += force * gauss_points[i][0];
              sums[2] += force * gauss_points[i][1];
              sums[3] += jxw[i];
            }
        }
    Utilities::MPI::sum(sums, discretization->mpi_communicator, sums);
    // The mirror images of a symmetric part carry the same force; their
    // moments about a symmetry plane cancel that part's.
    const double copies = discretization->n_symmetry_copies();
    Resultant    r;
    r.force        = copies * sums[0];
    r.contact_area = copies * sums[3];
    if (sums[0] != 0.0)
      for (unsigned int d = 0; d < 2; ++d)
        r.centre[d] = sums[1 + d] / sums[0];
    for (const unsigned int axis : discretization->symmetry_axes())
      r.centre[axis] = 0;
    return r;
  }


  double
  TensionlessWinklerFoundation::contact_area_fraction() const
  {
    double in_contact_area = 0, area = 0;
    for (unsigned int i = 0; i < jxw.size(); ++i)
      {
        area += jxw[i];
        in_contact_area += in_contact[i] * jxw[i];
      }
    const MPI_Comm comm = discretization->mpi_communicator;
    return Utilities::MPI::sum(in_contact_area, comm)
           / Utilities::MPI::sum(area, comm);
  }


  double
  TensionlessWinklerFoundation::rigid_body_restraint() const
  {
    // Modes r = (1, x, y); a symmetry plane x = 0 (y = 0) fixes the
    // rotation that w = x (w = y) needs, so that mode is held already.
    std::array<bool, 3> is_free = {{true, true, true}};
    for (const unsigned int axis : discretization->symmetry_axes())
      is_free[1 + axis] = false;
    // Moments of the contact set and of the whole part, entry by entry.
    std::vector<double> moments(18, 0.0);
    for (unsigned int i = 0; i < jxw.size(); ++i)
      {
        const Point<2>             &p = gauss_points[i];
        const std::array<double, 3> r = {{1.0, p[0], p[1]}};
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            {
              moments[3 * a + b] += in_contact[i] * jxw[i] * r[a] * r[b];
              moments[9 + 3 * a + b] += jxw[i] * r[a] * r[b];
            }
      }
    Utilities::MPI::sum(moments, discretization->mpi_communicator, moments);
    // The whole part's moment matrix is diagonal (it is symmetric about
    // the axes of the modes kept): scale by it, so that full contact gives
    // the identity; held modes enter as 1.
    SymmetricTensor<2, 3> scaled;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = a; b < 3; ++b)
        scaled[a][b] =
          (is_free[a] && is_free[b]
             ? moments[3 * a + b]
                 / std::sqrt(moments[9 + 4 * a] * moments[9 + 4 * b])
             : (a == b ? 1.0 : 0.0));
    return eigenvalues(scaled)[2];
  }


  Vector<float>
  TensionlessWinklerFoundation::contact_fraction_per_cell() const
  {
    Vector<float> fraction(discretization->triangulation.n_active_cells());
    for (unsigned int c = 0; c < cell_index.size(); ++c)
      {
        double sum = 0, area = 0;
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            area += jxw[c * n_q_points + q];
            sum += in_contact[c * n_q_points + q] * jxw[c * n_q_points + q];
          }
        fraction[cell_index[c]] = sum / area;
      }
    return fraction;
  }


  void
  TensionlessWinklerFoundation::save(OutputArchive &archive) const
  {
    archive << in_contact << in_matrix << points_to_update;
  }


  void
  TensionlessWinklerFoundation::load(InputArchive &archive)
  {
    const std::size_t n_points = in_contact.size();
    archive >> in_contact >> in_matrix >> points_to_update;
    AssertThrow(in_contact.size() == n_points && in_matrix.size() == n_points,
                ExcMessage("The checkpoint's contact status has "
                           + std::to_string(in_contact.size())
                           + " Gauss points where this rank has "
                           + std::to_string(n_points)
                           + ": it was written for another mesh."));
  }
} // namespace liftoff
