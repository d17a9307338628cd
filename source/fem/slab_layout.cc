#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/fem/plate_geometry.h>
#include <liftoff/fem/slab_layout.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace liftoff
{
  namespace
  {
    /// The joints' boundary ids follow the edges', planes' and a mesh
    /// file's few tags.
    constexpr types::boundary_id first_joint_id = 64;
  } // namespace


  void
  SlabLayout::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Slabs");
    prm.declare_entry("Slabs along x",
                      "1",
                      Patterns::Integer(1, 32),
                      "The rectangle as this many slabs of equal length "
                      "along x, with the transverse joints x1, x2, ... "
                      "between them (from the left). Each joint must lie on "
                      "a line of the coarse cells (Discretization/Cells "
                      "along x a multiple of the slabs on the meshed part).");
    prm.declare_entry("Slabs along y",
                      "1",
                      Patterns::Integer(1, 32),
                      "Slabs of equal width along y, with the longitudinal "
                      "joints y1, y2, ... between them (from the bottom).");
    prm.declare_entry("Slab lengths",
                      "",
                      Patterns::Anything(),
                      "The slabs' lengths along x from the left, instead of "
                      "equal slabs (Slabs along x then 1 or their number): "
                      "they must add up to the plate's length; the joints "
                      "x1, x2, ... lie between them, each on a line of the "
                      "coarse cells (e.g. 4.5, 5.5 with 0.5 m cells)."
                        + quantity("length"));
    prm.declare_entry("Slab widths",
                      "",
                      Patterns::Anything(),
                      "The slabs' widths along y from the bottom (a shoulder "
                      "and lanes: 1.2, 3.6, 3.6), as Slab lengths: they add "
                      "up to the plate's width, the joints y1, y2, ... "
                      "between them."
                        + quantity("length"));
    prm.declare_entry("Tied joints",
                      "",
                      Patterns::List(Patterns::Anything()),
                      "Joints (x1, y2, ...) that are monolithic: w and psi "
                      "continuous across them, as if there were no joint."
                        + quantity("text"));
    prm.leave_subsection();
  }


  void
  SlabLayout::parse_parameters(
    ParameterHandler                                              &prm,
    const PlateGeometry                                           &geometry,
    const std::shared_ptr<const MeshFile>                         &mesh_file,
    const std::vector<std::pair<types::boundary_id, std::string>> &joint_tags)
  {
    prm.enter_subsection("Slabs");
    slab_grid = {{static_cast<unsigned int>(prm.get_integer("Slabs along x")),
                  static_cast<unsigned int>(prm.get_integer("Slabs along y"))}};
    const std::vector<std::string> tied =
      Utilities::split_string_list(prm.get("Tied joints"));
    read_given_sizes(prm);
    prm.leave_subsection();

    joint_list.clear();
    mesh = mesh_file;
    if (mesh != nullptr)
      {
        std::set<types::boundary_id> joint_ids;
        for (const auto &tag : joint_tags)
          joint_ids.insert(tag.first);
        mesh->require_conforming(joint_ids);
      }
    slab_numbers.clear();
    joint_tag_ids.clear();
    if (slab_grid[0] * slab_grid[1] > 1 || !given_sizes[0].empty()
        || !given_sizes[1].empty())
      {
        AssertThrow(geometry.shape() == PlateShape::rectangle,
                    ExcMessage("Slabs/Slabs along x and y: slabs are made on "
                               "the rectangle, or come from a mesh file's "
                               "physical surfaces; not on "
                               + geometry.shape_setting() + "."));
        place_joints(geometry);
      }
    else if (mesh != nullptr)
      place_mesh_joints(joint_tags);
    AssertThrow(tied.empty() || !joint_list.empty(),
                ExcMessage("Slabs/Tied joints = " + tied[0]
                           + ": the plate has no joints (Slabs along x and y "
                             "are 1, and no curve of a mesh file is a "
                             "joint)."));
    for (const std::string &name : tied)
      {
        const auto joint =
          std::find_if(joint_list.begin(), joint_list.end(), [&](auto &j) {
            return j.name == name;
          });
        AssertThrow(joint != joint_list.end(),
                    ExcMessage("Slabs/Tied joints: " + name
                               + " is no joint of the modelled plate."));
        joint->tied = true;
      }
  }


  void
  SlabLayout::read_given_sizes(ParameterHandler &prm)
  {
    const char *entries[2] = {"Slab lengths", "Slab widths"};
    const char *axes[2]    = {"x", "y"};
    for (unsigned int axis = 0; axis < 2; ++axis)
      {
        const std::string text = prm.get(entries[axis]);
        const std::string name =
          std::string("Slabs/") + entries[axis] + " = <" + text + ">";
        given_texts[axis] = name;
        given_sizes[axis].clear();
        if (text.find_first_not_of(" \t") == std::string::npos)
          continue;
        const std::string message =
          name + " must be sizes > 0 separated by ','.";
        try
          {
            given_sizes[axis] = Utilities::string_to_double(
              Utilities::split_string_list(text, ','));
          }
        catch (...)
          {
            AssertThrow(false, ExcMessage(message));
          }
        for (const double size : given_sizes[axis])
          AssertThrow(std::isfinite(size) && size > 0, ExcMessage(message));
        const unsigned int n = given_sizes[axis].size();
        AssertThrow(slab_grid[axis] == 1 || slab_grid[axis] == n,
                    ExcMessage(name + " gives " + std::to_string(n)
                               + " slabs, Slabs/Slabs along " + axes[axis]
                               + " = " + std::to_string(slab_grid[axis])
                               + ": leave that at 1 or make it the same."));
        AssertThrow(n <= 32,
                    ExcMessage(name + ": at most 32 slabs along " + axes[axis]
                               + "."));
        slab_grid[axis] = n;
      }
  }


  void
  SlabLayout::place_edges(const unsigned int axis,
                          const double       low,
                          const double       high,
                          const bool         mirrored)
  {
    const unsigned int   n     = slab_grid[axis];
    std::vector<double> &slabs = edges[axis];
    slabs.assign(1, low);
    const std::vector<double> &given = given_sizes[axis];
    if (given.empty())
      {
        const double size = (high - low) / n;
        for (unsigned int j = 1; j < n; ++j)
          slabs.push_back(low + j * size);
        slabs.push_back(high);
        return;
      }
    double sum = 0;
    for (const double size : given)
      slabs.push_back(low + (sum += size));
    const double tolerance = 1e-10 * (high - low);
    AssertThrow(std::abs(sum - (high - low)) <= tolerance,
                ExcMessage(given_texts[axis] + " add up to "
                           + format_number(sum) + ", but the plate's "
                           + (axis == 0 ? "length" : "width") + " is "
                           + format_number(high - low)
                           + " (lengths in units of L in the dimensionless "
                             "scene): the slabs must cover the plate."));
    slabs.back() = high;
    for (unsigned int j = 0; mirrored && j <= n; ++j)
      AssertThrow(std::abs(slabs[j] + slabs[n - j]) <= tolerance,
                  ExcMessage(given_texts[axis]
                             + " are not mirrored about the symmetry plane "
                               "of Discretization/Symmetry: model the full "
                               "plate or mirror the slabs."));
  }


  void
  SlabLayout::place_mesh_joints(
    const std::vector<std::pair<types::boundary_id, std::string>> &joint_tags)
  {
    Triangulation<2> coarse;
    mesh->copy_to(coarse);
    for (const auto &cell : coarse.active_cell_iterators())
      slab_numbers.emplace(cell->material_id(), 0);
    unsigned int number = 0;
    for (auto &slab : slab_numbers)
      slab.second = number++;
    // The sides' ids above every id of the file.
    const std::vector<types::boundary_id> ids = coarse.get_boundary_ids();
    types::boundary_id                    id  = std::max<types::boundary_id>(
      first_joint_id, 1 + *std::max_element(ids.begin(), ids.end()));
    const double size = mesh->bounding_box().side_length(0);
    for (const auto &[tag, name] : joint_tags)
      {
        const std::string what = "Boundary conditions/Mesh tags: the joint "
                                 + name + " of the mesh file";
        const unsigned int along = mesh->direction_of(tag);
        AssertThrow(along < 2,
                    ExcMessage(what
                               + " does not run along x or y; liftoff's "
                                 "joints are straight lines along x or y."));
        Joint joint{name, 1 - along, 0.0, id, id + 1u, false, 1e300, -1e300};
        bool  first = true;
        for (const auto &face : coarse.active_face_iterators())
          if (face->at_boundary() && face->boundary_id() == tag)
            {
              const double at = face->center()[joint.normal_axis];
              AssertThrow(first
                            || std::abs(at - joint.position) <= 1e-10 * size,
                          ExcMessage(what + " lies on the lines "
                                     + format_number(joint.position) + " and "
                                     + format_number(at)
                                     + ": give each straight joint a "
                                       "physical curve of its own."));
              joint.position = at;
              first          = false;
              for (const unsigned int v : {0u, 1u})
                {
                  joint.start = std::min(joint.start, face->vertex(v)[along]);
                  joint.end   = std::max(joint.end, face->vertex(v)[along]);
                }
            }
        joint.number = joint_list.size();
        joint_list.push_back(joint);
        joint_tag_ids.insert(tag);
        id += 2;
      }
  }


  void
  SlabLayout::place_joints(const PlateGeometry &geometry)
  {
    const auto [low, high] = geometry.plate_box().get_boundary_points();
    const auto [modelled_low, modelled_high] =
      geometry.modelled_box().get_boundary_points();
    const char *axis_names[2] = {"x", "y"};
    for (unsigned int axis = 0; axis < 2; ++axis)
      {
        const bool mirrored = geometry.symmetry_axes().size() > axis;
        place_edges(axis, low[axis], high[axis], mirrored);
        const double cell = (modelled_high[axis] - modelled_low[axis])
                            / geometry.coarse_cells_along(axis);
        for (unsigned int j = 1; j < slab_grid[axis]; ++j)
          {
            const double      position = edges[axis][j];
            const std::string name     = axis_names[axis] + std::to_string(j);
            const std::string what =
              (given_sizes[axis].empty()
                 ? "Slabs/Slabs along " + std::string(axis_names[axis]) + " = "
                     + std::to_string(slab_grid[axis])
                 : given_texts[axis])
              + " puts the joint " + name + " at " + axis_names[axis] + " = "
              + format_number(position);
            const double tolerance = 1e-10 * (high[axis] - low[axis]);
            const types::boundary_id id =
              first_joint_id + 2 * joint_list.size();
            const bool on_plane = std::abs(position) <= tolerance && mirrored;
            if (position < modelled_low[axis] - tolerance
                || (position < modelled_low[axis] + tolerance && !on_plane))
              continue;
            const double cells = (position - modelled_low[axis]) / cell;
            AssertThrow(std::abs(cells - std::round(cells)) < 1e-8,
                        ExcMessage(what
                                   + ", inside a coarse cell: make "
                                     "Discretization/Cells along "
                                   + axis_names[axis]
                                   + " such that every joint lies on a line "
                                     "between cells (for equal slabs a "
                                     "multiple of the slabs on the meshed "
                                     "part)."));
            joint_list.push_back({name,
                                  axis,
                                  position,
                                  id,
                                  id + 1u,
                                  false,
                                  low[1 - axis],
                                  high[1 - axis],
                                  on_plane,
                                  axis * (slab_grid[0] - 1) + j - 1});
          }
      }
  }


  unsigned int
  SlabLayout::n_slabs() const
  {
    return mesh != nullptr && slab_grid[0] * slab_grid[1] == 1
             ? std::max<unsigned int>(1, slab_numbers.size())
             : slab_grid[0] * slab_grid[1];
  }


  unsigned int
  SlabLayout::n_joints_of_plate() const
  {
    return mesh != nullptr && slab_grid[0] * slab_grid[1] == 1
             ? joint_list.size()
             : slab_grid[0] + slab_grid[1] - 2;
  }


  bool
  SlabLayout::is_jointed() const
  {
    return n_slabs() > 1 || !joint_list.empty();
  }


  const std::vector<Joint> &
  SlabLayout::joints() const
  {
    return joint_list;
  }


  const Joint *
  SlabLayout::joint_of(const types::boundary_id id) const
  {
    for (const Joint &joint : joint_list)
      if (id == joint.lower_side || id == joint.upper_side)
        return &joint;
    return nullptr;
  }


  DoFHandler<2>::cell_iterator
  SlabLayout::across(const DoFHandler<2>::active_cell_iterator &cell,
                     const unsigned int                         face) const
  {
    const Joint *joint = joint_of(cell->face(face)->boundary_id());
    Assert(joint != nullptr, ExcInternalError());
    return joint->on_plane ? DoFHandler<2>::cell_iterator(cell)
                           : cell->periodic_neighbor(face);
  }


  unsigned int
  SlabLayout::slab_of(const Point<2> &p) const
  {
    if (!slab_numbers.empty())
      {
        const auto slab = slab_numbers.find(mesh->material_id_at(p));
        return slab != slab_numbers.end() ? slab->second : 0;
      }
    // The slab whose lower end is the last one at or below p (the first
    // or last slab beyond the plate's ends).
    std::array<unsigned int, 2> index = {{0, 0}};
    for (unsigned int axis = 0; axis < 2 && !edges[axis].empty(); ++axis)
      index[axis] = std::upper_bound(edges[axis].begin() + 1,
                                     edges[axis].end() - 1,
                                     p[axis])
                    - (edges[axis].begin() + 1);
    return index[0] + slab_grid[0] * index[1];
  }


  void
  SlabLayout::require_symmetric(const std::vector<SlabSection>  &sections,
                                const std::vector<unsigned int> &symmetry_axes,
                                const std::string &symmetry_name) const
  {
    if (sections.empty())
      return;
    for (unsigned int s = 0; s < sections.size(); ++s)
      for (const unsigned int axis : symmetry_axes)
        {
          std::array<unsigned int, 2> index = {
            {s % slab_grid[0], s / slab_grid[0]}};
          index[axis]          = slab_grid[axis] - 1 - index[axis];
          const unsigned int m = index[0] + slab_grid[0] * index[1];
          const bool same      = sections[m].thickness == sections[s].thickness
                            && sections[m].modulus == sections[s].modulus;
          AssertThrow(same,
                      ExcMessage("Slabs/Thicknesses and Modulus ratios: slab "
                                 + std::to_string(s + 1) + " and slab "
                                 + std::to_string(m + 1)
                                 + ", its mirror image, differ, so "
                                   "Discretization/Symmetry = "
                                 + symmetry_name
                                 + " would model another plate: model the "
                                   "full plate."));
        }
  }


  void
  SlabLayout::cut(const Triangulation<2>                  &whole,
                  parallel::distributed::Triangulation<2> &cut) const
  {
    // A vertex once per slab that uses it.
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> copy_of;
    std::vector<Point<2>>                                         vertices;
    std::vector<CellData<2>>                                      cells;
    for (const auto &cell : whole.active_cell_iterators())
      {
        const unsigned int slab = slab_numbers.empty()
                                    ? slab_of(cell->center())
                                    : slab_numbers.at(cell->material_id());
        CellData<2>        data;
        data.material_id = slab;
        // A mesh file's slabs are cut where its nodes are.
        const unsigned int piece = slab_numbers.empty() ? slab : 0;
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto [it, is_new] =
              copy_of.try_emplace({cell->vertex_index(v), piece},
                                  vertices.size());
            if (is_new)
              vertices.push_back(cell->vertex(v));
            data.vertices[v] = it->second;
          }
        cells.push_back(data);
      }
    cut.create_triangulation(vertices, cells, SubCellData());

    mark_faces(whole, cut);
    for (const Joint &joint : joint_list)
      if (!joint.on_plane)
        {
          std::vector<GridTools::PeriodicFacePair<
            parallel::distributed::Triangulation<2>::cell_iterator>>
            pairs;
          GridTools::collect_periodic_faces(
            cut, joint.lower_side, joint.upper_side, joint.normal_axis, pairs);
          cut.add_periodicity(pairs);
        }
  }


  void
  SlabLayout::mark_faces(const Triangulation<2> &whole,
                         Triangulation<2>       &cut) const
  {
    // The edges' and planes' ids at the same places; the other faces on
    // the boundary now, a mesh file's joints and the joints on a symmetry
    // plane that are not tied, are the joints'.
    std::vector<std::pair<Point<2>, types::boundary_id>> edge_ids;
    for (const auto &face : whole.active_face_iterators())
      if (face->at_boundary() && joint_tag_ids.count(face->boundary_id()) == 0)
        edge_ids.emplace_back(face->center(), face->boundary_id());
    const double tolerance = 1e-10 * GridTools::minimal_cell_diameter(whole);
    for (const auto &cell : cut.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            const auto     joint =
              std::find_if(joint_list.begin(), joint_list.end(), [&](auto &j) {
                const unsigned int along = 1 - j.normal_axis;
                return std::abs(c[j.normal_axis] - j.position) < tolerance
                       && c[along] > j.start && c[along] < j.end
                       && !(j.on_plane && j.tied);
              });
            if (joint != joint_list.end())
              {
                face->set_boundary_id(cell->center()[joint->normal_axis]
                                          < joint->position
                                        ? joint->lower_side
                                        : joint->upper_side);
                continue;
              }
            const auto edge =
              std::find_if(edge_ids.begin(), edge_ids.end(), [&](auto &e) {
                return e.first.distance(c) < tolerance;
              });
            if (edge != edge_ids.end())
              face->set_boundary_id(edge->second);
          }
  }


  void
  SlabLayout::add_couplings(const DoFHandler<2>             &dof_handler,
                            const AffineConstraints<double> &constraints,
                            DynamicSparsityPattern          &pattern) const
  {
    const unsigned int n = dof_handler.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> both(2 * n), there(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            const Joint *joint = cell->face(f)->at_boundary()
                                   ? joint_of(cell->face(f)->boundary_id())
                                   : nullptr;
            // A joint on a plane couples a cell with its own mirror image.
            if (joint == nullptr || joint->tied || joint->on_plane)
              continue;
            // A finer neighbour couples from its side, as it sees this
            // cell as its coarser neighbour.
            const auto neighbor = cell->periodic_neighbor(f);
            if (neighbor->has_children())
              continue;
            cell->get_dof_indices(both);
            neighbor->get_dof_indices(there);
            both.resize(n);
            both.insert(both.end(), there.begin(), there.end());
            constraints.add_entries_local_to_global(both, pattern, false);
          }
  }


  void
  SlabLayout::tie(const DoFHandler<2>       &dof_handler,
                  AffineConstraints<double> &constraints) const
  {
    // A tied joint on a symmetry plane is the plane (psi . n = 0 there).
    // A base of its own runs on under every joint: its fields are tied
    // across the others, and on a plane it has no other side but the
    // plane's condition (PlateGeometry::held_components).
    const unsigned int layers = PlateFields::n_layers(dof_handler.get_fe());
    std::vector<bool>  of_base(dof_handler.get_fe().n_components(), false);
    for (unsigned int c = PlateFields::w_of(1); c < of_base.size(); ++c)
      of_base[c] = true;
    for (const Joint &joint : joint_list)
      if (!joint.on_plane && (joint.tied || layers == 2))
        DoFTools::make_periodicity_constraints(dof_handler,
                                               joint.lower_side,
                                               joint.upper_side,
                                               joint.normal_axis,
                                               constraints,
                                               joint.tied
                                                 ? ComponentMask()
                                                 : ComponentMask(of_base));
  }


  void
  SlabLayout::for_each_joint_face(
    const DoFHandler<2>                           &dof_handler,
    const std::function<void(const DoFHandler<2>::active_cell_iterator &,
                             const unsigned int,
                             const unsigned int)> &f) const
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int face : cell->face_indices())
          {
            if (!cell->face(face)->at_boundary())
              continue;
            const Joint *joint = joint_of(cell->face(face)->boundary_id());
            if (joint == nullptr || joint->tied)
              continue;
            // Each piece of the joint once: from the finer side, from the
            // lower one where both are alike; on a plane from the modelled
            // side, the only one.
            if (!joint->on_plane
                && (cell->periodic_neighbor(face)->has_children()
                    || (!cell->periodic_neighbor_is_coarser(face)
                        && cell->face(face)->boundary_id()
                             == joint->upper_side)))
              continue;
            f(cell, face, joint - joint_list.data());
          }
  }
} // namespace liftoff
