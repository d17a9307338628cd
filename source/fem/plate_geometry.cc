#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/reference_cell.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/base/selection.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/fem/plate_geometry.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace liftoff
{
  const std::array<std::string, 4> PlateGeometry::edge_names = {
    {"Left", "Right", "Bottom", "Top"}};

  namespace
  {
    const Selection<EdgeCondition> edge_conditions = {
      {"free", EdgeCondition::free},
      {"hard simply supported", EdgeCondition::hard_simply_supported},
      {"soft simply supported", EdgeCondition::soft_simply_supported},
      {"clamped", EdgeCondition::clamped}};

    // A tag of a mesh file may also be a symmetry plane or a joint.
    const Selection<EdgeCondition> tag_conditions = {
      {"free", EdgeCondition::free},
      {"hard simply supported", EdgeCondition::hard_simply_supported},
      {"soft simply supported", EdgeCondition::soft_simply_supported},
      {"clamped", EdgeCondition::clamped},
      {"symmetry plane", EdgeCondition::symmetry_plane},
      {"joint", EdgeCondition::joint}};

    const Selection<PlateShape> shapes = {{"rectangle", PlateShape::rectangle},
                                          {"disc", PlateShape::disc},
                                          {"annulus", PlateShape::annulus},
                                          {"mesh file", PlateShape::mesh_file}};

    // The components of (w, psi_x, psi_y) a boundary held by `condition`
    // holds, `direction` being 0 for a boundary along x, 1 along y and
    // another value for one along neither (a circle, an oblique curve). With
    // psi the slopes (gamma = grad w - psi), hard simple support holds the
    // rotation along the boundary, psi . t (w = 0 along it makes its
    // derivative along it vanish): psi_y on x = const, psi_x on y = const.
    // A symmetry plane holds the rotation across it, psi . n. Along neither
    // axis these are no components: held_rotations() names those
    // boundaries for normal-tangential constraints.
    ComponentMask
    held_on_edge(const EdgeCondition condition, const unsigned int direction)
    {
      const bool along_x = direction == 0, along_y = direction == 1;
      switch (condition)
        {
        case EdgeCondition::soft_simply_supported:
          return PlateFields::mask(true, false, false);
        case EdgeCondition::hard_simply_supported:
          return PlateFields::mask(true, along_x, along_y);
        case EdgeCondition::clamped:
          return PlateFields::mask(true, true, true);
        case EdgeCondition::symmetry_plane:
          return PlateFields::mask(false, along_y, along_x);
        default:
          return PlateFields::mask(false, false, false);
        }
    }

    const Selection<Symmetry> symmetries = {{"full", Symmetry::full},
                                            {"half", Symmetry::half},
                                            {"quarter", Symmetry::quarter}};

    // The sum of Slabs/`entry` as the scene writes it, 0 if it is empty or
    // not numbers (which SlabLayout refuses by name later).
    double
    sum_of_slab_sizes(ParameterHandler &scene, const std::string &entry)
    {
      scene.enter_subsection("Slabs");
      const std::string text = scene.get(entry);
      scene.leave_subsection();
      double sum = 0;
      try
        {
          for (const double size : Utilities::string_to_double(
                 Utilities::split_string_list(text, ',')))
            sum += size;
        }
      catch (...)
        {
          return 0;
        }
      return std::isfinite(sum) && sum > 0 ? sum : 0;
    }
  } // namespace


  void
  PlateGeometry::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    prm.declare_entry("Shape",
                      "rectangle",
                      shapes.pattern(),
                      "The plate's outline: rectangle, [-1/2, 1/2] x "
                      "[-mu/2, mu/2] with the edges Left, Right, Bottom and "
                      "Top; disc, of radius Radius about the origin with "
                      "the edge Outer, meshed by GridGenerator::"
                      "hyper_ball_balanced; annulus, between the circles of "
                      "radii Inner radius and Radius about the origin with "
                      "the edges Inner and Outer, meshed by GridGenerator::"
                      "hyper_shell (Cells along x and y unused by both); "
                      "mesh file, the quadrilaterals of the gmsh file Mesh "
                      "file, whose physical curves name the edges "
                      "(Boundary conditions/Mesh tags).");
    prm.declare_entry("Radius",
                      "0.5",
                      Patterns::Double(0.0),
                      "R / L, the radius of a disc (Shape = disc) or the "
                      "outer radius of an annulus in the length unit L; in "
                      "metres in a scene with Units/System = SI (unset "
                      "there: half of Units/Length)."
                        + quantity("length (if set)"));
    prm.declare_entry("Inner radius",
                      "0.25",
                      Patterns::Double(0.0),
                      "R_i / L, an annulus's hole radius, 0 < R_i < Radius."
                        + quantity("length (if set)"));
    prm.declare_entry("Mesh file",
                      "",
                      Patterns::Anything(),
                      "The gmsh mesh of Shape = mesh file: a .msh file (msh "
                      "2.2 or 4.1, ASCII) of quadrilaterals in the plane "
                      "z = 0, its coordinates in the length unit L, or in "
                      "metres in a scene with Units/System = SI (whose "
                      "Units/Length must then be the mesh's length along "
                      "x). A relative path is relative to the folder of the "
                      "scene file that names it, as include lines are (to "
                      "the working directory for a scene on standard input)."
                        + quantity("text"));
    prm.declare_entry("Symmetry",
                      "full",
                      symmetries.pattern(),
                      "Which part of the plate is meshed: full; half "
                      "(x >= 0, symmetry plane x = 0); quarter (x >= 0, "
                      "y >= 0). The scene always describes the full plate "
                      "and its full loads.");
    for (const std::string axis : {"x", "y"})
      prm.declare_entry("Cells along " + axis,
                        "10",
                        Patterns::Integer(1),
                        "Number of cells along " + axis
                          + " on the meshed part.");
    prm.leave_subsection();
    declare_boundary_conditions(prm);
    SlabLayout::declare_parameters(prm);
  }


  void
  PlateGeometry::declare_boundary_conditions(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    for (const auto &name : edge_names)
      prm.declare_entry(name,
                        "free",
                        edge_conditions.pattern(),
                        "Condition on this edge of the full plate. Left: "
                        "x = -1/2, Right: x = 1/2, Bottom: y = -mu/2, "
                        "Top: y = mu/2. Hard simple support fixes w and the "
                        "rotation along the edge, soft only w.");
    prm.declare_entry("Outer",
                      "free",
                      edge_conditions.pattern(),
                      "Condition on the circle of a disc or the outer circle "
                      "of an annulus.");
    prm.declare_entry("Inner",
                      "free",
                      edge_conditions.pattern(),
                      "Condition on the hole's circle of an annulus (Shape "
                      "= annulus).");
    prm.declare_entry(
      "Mesh tags",
      "",
      Patterns::Map(Patterns::Anything(),
                    tag_conditions.pattern(),
                    0,
                    Patterns::Map::max_int_value,
                    ",",
                    ":"),
      "Conditions on the edges of a mesh file (Discretization/Shape = mesh "
      "file), as 'tag: condition, tag: condition', a tag being the name or "
      "the number of a physical curve of the file (e.g. 'Wall: clamped, "
      "Hole: free'). Tags not listed are free. Where a held curve turns "
      "(two faces meet at an angle), hard simple support and symmetry "
      "planes hold the whole rotation, as at a rectangle's corner."
        + quantity("text"));
    prm.leave_subsection();
  }


  void
  describe_shape_for_units(ParameterHandler            &scene,
                           PhysicalUnits::SceneOutline &outline)
  {
    scene.enter_subsection("Discretization");
    const std::string shape = scene.get("Shape");
    scene.leave_subsection();
    outline.is_rectangle    = shape == "rectangle";
    outline.length_of_slabs = sum_of_slab_sizes(scene, "Slab lengths");
    outline.width_of_slabs  = sum_of_slab_sizes(scene, "Slab widths");
    // A mesh file's outline is its own; its length along x is checked
    // against Units/Length where the mesh is read (parse_parameters()).
    if (shape == "mesh file")
      outline.refused.emplace_back(
        "Width",
        "Units/Width is the width of the rectangle; with "
        "Discretization/Shape = mesh file the mesh, in "
        "metres, is the plate and Units/Length its length "
        "along x: leave Units/Width out.");
  }


  void
  PlateGeometry::parse_parameters(ParameterHandler    &prm,
                                  const MindlinPlate  &plate,
                                  const PhysicalUnits &units)
  {
    aspect_ratio = plate.aspect_ratio;
    prm.enter_subsection("Discretization");
    outline = shapes.parse(prm.get("Shape"), "Discretization/Shape");
    radius  = prm.get_double("Radius");
    mesh.reset();
    if (outline == PlateShape::mesh_file)
      {
        const double length = units.scale(PhysicalUnits::Quantity::length);
        mesh = std::make_shared<const MeshFile>(prm.get("Mesh file"), length);
        if (units.is_physical())
          check_mesh_length(prm.get("Mesh file"), length);
      }
    else
      AssertThrow(prm.get("Mesh file").empty(),
                  ExcMessage("Discretization/Mesh file is read only with "
                             "Discretization/Shape = mesh file, not with "
                             + shape_setting() + "."));
    inner_radius                    = prm.get_double("Inner radius");
    const std::string symmetry_name = prm.get("Symmetry");
    modelled_part = symmetries.parse(symmetry_name, "Discretization/Symmetry");
    n_cells_x     = prm.get_integer("Cells along x");
    n_cells_y     = prm.get_integer("Cells along y");
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    for (unsigned int e = 0; e < 4; ++e)
      edges[e] = edge_conditions.parse(prm.get(edge_names[e]),
                                       "Boundary conditions/" + edge_names[e]);
    outer =
      edge_conditions.parse(prm.get("Outer"), "Boundary conditions/Outer");
    inner =
      edge_conditions.parse(prm.get("Inner"), "Boundary conditions/Inner");
    parse_mesh_tags(prm.get("Mesh tags"));
    prm.leave_subsection();
    std::vector<std::pair<types::boundary_id, std::string>> joint_tags;
    for (const HeldTag &tag : mesh_tags)
      if (tag.condition == EdgeCondition::joint)
        joint_tags.emplace_back(tag.id, tag.name);
    check_shape_choices(symmetry_name);

    // A symmetric model is only right for a symmetric plate.
    if (modelled_part != Symmetry::full)
      AssertThrow(edges[left_edge] == edges[right_edge],
                  ExcMessage(
                    "Discretization/Symmetry = " + symmetry_name
                    + " needs Boundary conditions/Left and Right to be "
                      "equal (the plate must be symmetric about x = 0)."));
    if (modelled_part == Symmetry::quarter)
      AssertThrow(edges[bottom_edge] == edges[top_edge],
                  ExcMessage("Discretization/Symmetry = quarter needs Boundary "
                             "conditions/Bottom and Top to be equal (the plate "
                             "must be symmetric about y = 0)."));
    slab_layout.parse_parameters(prm, *this, mesh, joint_tags);
  }


  const SlabLayout &
  PlateGeometry::slabs() const
  {
    return slab_layout;
  }


  void
  PlateGeometry::check_shape_choices(const std::string &symmetry_name) const
  {
    const auto refuse = [](const bool wrong, const std::string &message) {
      AssertThrow(!wrong, ExcMessage(message));
    };
    // A mesh file models a symmetric part by its symmetry-plane curves.
    refuse(outline == PlateShape::mesh_file && modelled_part != Symmetry::full,
           "Discretization/Symmetry = " + symmetry_name
             + " is not available on " + shape_setting() + " yet; use full.");
    if (outline == PlateShape::mesh_file)
      {
        check_mesh_file_choices();
        return;
      }
    refuse(outline != PlateShape::annulus && inner != EdgeCondition::free,
           "Boundary conditions/Inner is the hole's edge of an annulus; "
             + shape_setting() + " has no hole.");
    if (outline == PlateShape::rectangle)
      {
        refuse(outer != EdgeCondition::free,
               "Boundary conditions/Outer is the edge of a disc or an "
               "annulus; a rectangle (Discretization/Shape = rectangle) has "
               "Left, Right, Bottom and Top.");
        return;
      }
    refuse(radius <= 0,
           "Discretization/Radius must be > 0 for " + shape_setting() + ".");
    if (outline == PlateShape::annulus)
      refuse(inner_radius <= 0 || inner_radius >= radius,
             "Discretization/Inner radius = " + format_exact(inner_radius)
               + " must lie strictly between 0 and Discretization/Radius = "
               + format_exact(radius) + " for an annulus.");
    for (unsigned int e = 0; e < 4; ++e)
      refuse(edges[e] != EdgeCondition::free,
             "Boundary conditions/" + edge_names[e]
               + " is an edge of the rectangle; " + shape_setting()
               + " has the edges "
               + (outline == PlateShape::annulus ? "Inner and Outer."
                                                 : "Outer."));
  }


  void
  PlateGeometry::check_mesh_file_choices() const
  {
    // The built-in shapes' edges are not those of the file.
    std::vector<std::pair<std::string, EdgeCondition>> named_edges = {
      {"Outer", outer}, {"Inner", inner}};
    for (unsigned int e = 0; e < 4; ++e)
      named_edges.emplace_back(edge_names[e], edges[e]);
    for (const auto &[name, condition] : named_edges)
      AssertThrow(condition == EdgeCondition::free,
                  ExcMessage("Boundary conditions/" + name
                             + " is an edge of a built-in shape; "
                             + shape_setting()
                             + " holds the physical curves of its file by "
                               "Boundary conditions/Mesh tags."));
  }


  void
  PlateGeometry::check_mesh_length(const std::string &file_name,
                                   const double       length) const
  {
    // Units/Length is the plate along x on every shape that has no radius:
    // the groups (Gamma = k L^4 / D, t0, ...) are those of the rectangle
    // of the same length, and a mesh drawn in another unit (in L, in mm)
    // is caught rather than run as a plate of another size.
    const double along_x = mesh->bounding_box().side_length(0);
    AssertThrow(std::abs(along_x - 1.0) <= 1e-6,
                ExcMessage("Units/Length = " + format_number(length)
                           + " m is not the length along x of the mesh of "
                           + file_name + ", " + format_number(along_x * length)
                           + " m: with Units/System = SI the mesh file is in "
                             "metres and Units/Length is its length along x "
                             "(set Units/Length = "
                           + format_number(along_x * length) + ")."));
  }


  void
  PlateGeometry::parse_mesh_tags(const std::string &text)
  {
    const std::string parameter = "Boundary conditions/Mesh tags";
    mesh_tags.clear();
    if (Utilities::trim(text).empty())
      return;
    AssertThrow(mesh != nullptr,
                ExcMessage(parameter
                           + " holds the physical curves of a mesh "
                             "file; "
                           + shape_setting()
                           + " has none (Discretization/Shape = mesh file "
                             "has)."));
    for (const std::string &entry : Utilities::split_string_list(text, ','))
      {
        const auto parts = Utilities::split_string_list(entry, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage(parameter + ": '" + abbreviated(entry)
                               + "' is not 'tag: condition'."));
        const types::boundary_id id = mesh->boundary_id(parts[0], parameter);
        const EdgeCondition      condition =
          tag_conditions.parse(parts[1], parameter + " (" + parts[0] + ")");
        for (const HeldTag &other : mesh_tags)
          AssertThrow(other.id != id,
                      ExcMessage(parameter + " gives the tag "
                                 + std::to_string(id) + " two conditions ("
                                 + other.name + " and " + parts[0]
                                 + "); give each tag one."));
        mesh_tags.push_back({id, parts[0], condition});
      }
  }


  void
  PlateGeometry::create_coarse_mesh(Triangulation<2> &triangulation) const
  {
    if (outline == PlateShape::mesh_file)
      {
        mesh->copy_to(triangulation);
        return;
      }
    if (outline == PlateShape::rectangle)
      {
        create_rectangle(triangulation);
        return;
      }
    if (modelled_part == Symmetry::full)
      {
        create_round_plate(triangulation);
        return;
      }
    // The cells of the whole plate's coarse mesh on the modelled side of
    // the planes (both generators put cell faces on x = 0 and y = 0): the
    // cells, the manifolds and so every refined point are those of the
    // whole plate, and a reduced model of a symmetric scene gives the whole
    // plate's answer to round-off.
    Triangulation<2> whole;
    create_round_plate(whole);
    std::set<Triangulation<2>::active_cell_iterator> beyond;
    for (const auto &cell : whole.active_cell_iterators())
      for (const unsigned int axis : symmetry_axes())
        if (cell->center()[axis] < 0)
          beyond.insert(cell);
    GridGenerator::create_triangulation_with_removed_cells(whole,
                                                           beyond,
                                                           triangulation);
    copy_round_plate_marks(whole, triangulation);
  }


  void
  PlateGeometry::copy_round_plate_marks(const Triangulation<2> &whole,
                                        Triangulation<2>       &part) const
  {
    // The removal keeps the cells but drops the boundary and manifold ids;
    // they are found again on the whole plate's cells and faces at the same
    // places. A face that was inside the whole plate lies on a plane.
    const auto same_place = [](const auto &a, const auto &b) {
      return a->center().distance(b->center()) < 1e-10 * a->diameter();
    };
    for (const auto &cell : part.active_cell_iterators())
      for (const auto &original : whole.active_cell_iterators())
        if (same_place(cell, original))
          {
            cell->set_manifold_id(original->manifold_id());
            for (const auto &face : cell->face_iterators())
              for (const auto &was : original->face_iterators())
                if (same_place(face, was))
                  {
                    face->set_manifold_id(was->manifold_id());
                    if (face->at_boundary())
                      face->set_boundary_id(
                        was->at_boundary() ? was->boundary_id()
                        : std::abs(face->center()[0]) < 1e-12
                          ? x_symmetry_plane
                          : y_symmetry_plane);
                  }
          }
    part.set_manifold(0, SphericalManifold<2>(Point<2>()));
    if (outline == PlateShape::disc)
      {
        TransfiniteInterpolationManifold<2> inside;
        inside.initialize(part);
        part.set_manifold(1, inside);
      }
  }


  void
  PlateGeometry::create_round_plate(Triangulation<2> &triangulation) const
  {
    if (outline == PlateShape::disc)
      {
        // The generator attaches a SphericalManifold to the boundary and a
        // TransfiniteInterpolationManifold inside, so refined cells stay on
        // the circle and keep their shape.
        GridGenerator::hyper_ball_balanced(triangulation, Point<2>(), radius);
        for (const auto &face : triangulation.active_face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(outer_boundary);
        return;
      }
    if (outline == PlateShape::annulus)
      {
        // A SphericalManifold on every cell and face keeps both circles
        // round and the cells' radial lines straight under refinement.
        GridGenerator::hyper_shell(triangulation,
                                   Point<2>(),
                                   inner_radius,
                                   radius,
                                   n_ring_cells(),
                                   /*colorize*/ true);
        for (const auto &face : triangulation.active_face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(face->boundary_id() == 0 ? inner_boundary
                                                           : outer_boundary);
      }
  }


  void
  PlateGeometry::create_rectangle(Triangulation<2> &triangulation) const
  {
    const BoundingBox<2> box = modelled_box();
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {n_cells_x, n_cells_y},
                                              box.get_boundary_points().first,
                                              box.get_boundary_points().second,
                                              /*colorize*/ true);
    // Faces on x = 0 or y = 0 of a symmetric model are symmetry planes, not
    // plate edges. Refined faces inherit the ids of the coarse ones.
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            if (modelled_part != Symmetry::full
                && face->boundary_id() == left_edge && std::abs(c[0]) < 1e-12)
              face->set_boundary_id(x_symmetry_plane);
            if (modelled_part == Symmetry::quarter
                && face->boundary_id() == bottom_edge && std::abs(c[1]) < 1e-12)
              face->set_boundary_id(y_symmetry_plane);
          }
  }


  unsigned int
  PlateGeometry::coarse_cells_along(const unsigned int axis) const
  {
    // A mesh file's cells count as one row of them.
    if (outline == PlateShape::mesh_file)
      return axis == 0 ? mesh->n_cells() : 1;
    // The 12 cells of hyper_ball_balanced count as 4 x 4 in estimates, a
    // half or quarter of them as 2 x 4 or 2 x 2.
    const auto &axes   = symmetry_axes();
    const bool  halved = std::count(axes.begin(), axes.end(), axis) > 0;
    if (outline == PlateShape::disc)
      return halved ? 2 : 4;
    // The ring's cells count as one row of them.
    if (outline == PlateShape::annulus)
      return axis == 0 ? n_ring_cells() / n_symmetry_copies() : 1;
    return axis == 0 ? n_cells_x : n_cells_y;
  }


  unsigned int
  PlateGeometry::n_ring_cells() const
  {
    // About as many as make the cells square at the mean radius, the
    // choice hyper_shell makes for n_cells = 0, and at least 8: a mapping
    // of degree 2 on arcs of 90 degrees (4 cells, a thin hole) loses 1.2 %
    // of the area, on 45 degrees 7.8e-4 (the coarse disc's arcs).
    const unsigned int n = std::max(8u,
                                    static_cast<unsigned int>(std::ceil(
                                      numbers::PI * (radius + inner_radius)
                                      / (radius - inner_radius))));
    // hyper_shell's first vertex lies on the x axis, so faces lie on both
    // axes when n is a multiple of 4.
    return modelled_part == Symmetry::full ? n : 4 * ((n + 3) / 4);
  }


  double
  PlateGeometry::largest_cell_aspect_ratio() const
  {
    // Refinement splits cells in both directions: the coarse cells' ratio.
    if (outline == PlateShape::rectangle)
      {
        const double width  = 1.0 / n_cells_x;
        const double height = aspect_ratio / n_cells_y;
        return std::max(width / height, height / width);
      }
    // The other coarse meshes, the same on every rank: the largest ratio of
    // the singular values of the bilinear map's Jacobian at a cell's 2 x 2
    // Gauss points (deal.II's measure, width / height on a rectangle).
    Triangulation<2> coarse;
    create_coarse_mesh(coarse);
    return GridTools::compute_maximum_aspect_ratio(
      ReferenceCells::Quadrilateral.get_default_linear_mapping<2, 2>(),
      coarse,
      QGauss<2>(2));
  }


  std::vector<PlateGeometry::HeldBoundary>
  PlateGeometry::held_boundaries() const
  {
    std::vector<HeldBoundary> held;
    const auto                hold = [&](const types::boundary_id id,
                          const EdgeCondition      condition,
                          const unsigned int       direction) {
      if (condition != EdgeCondition::free && condition != EdgeCondition::joint)
        held.push_back({id, condition, direction});
    };
    const unsigned int curved = numbers::invalid_unsigned_int;
    hold(outer_boundary, outer, curved);
    hold(inner_boundary, inner, curved);
    for (unsigned int e = 0; e < 4; ++e)
      hold(e, edges[e], (e == left_edge || e == right_edge) ? 1 : 0);
    for (const HeldTag &tag : mesh_tags)
      hold(tag.id, tag.condition, mesh->direction_of(tag.id));
    if (outline == PlateShape::mesh_file)
      return held;
    hold(x_symmetry_plane, EdgeCondition::symmetry_plane, 1);
    hold(y_symmetry_plane, EdgeCondition::symmetry_plane, 0);
    return held;
  }


  std::vector<std::pair<types::boundary_id, ComponentMask>>
  PlateGeometry::held_components(const unsigned int layers) const
  {
    std::vector<std::pair<types::boundary_id, ComponentMask>> held;
    const auto hold = [&](const types::boundary_id id,
                          const ComponentMask     &of_layer,
                          const unsigned int       first_layer) {
      const ComponentMask mask = PlateFields::mask(of_layer[PlateFields::w],
                                                   of_layer[PlateFields::psi_x],
                                                   of_layer[PlateFields::psi_y],
                                                   layers,
                                                   first_layer);
      if (mask.n_selected_components() > 0)
        held.emplace_back(id, mask);
    };
    for (const HeldBoundary &boundary : held_boundaries())
      hold(boundary.id,
           held_on_edge(boundary.condition, boundary.direction),
           0);
    // The slab's edge on such a joint acts against its mirror image
    // (JointSprings), so the slab is free there; a base of its own runs on
    // through the plane and keeps the plane's condition.
    for (const Joint &joint : slab_layout.joints())
      if (joint.on_plane && !joint.tied)
        for (const types::boundary_id id : {joint.lower_side, joint.upper_side})
          hold(id,
               held_on_edge(EdgeCondition::symmetry_plane,
                            1 - joint.normal_axis),
               1);
    return held;
  }


  HeldRotations
  PlateGeometry::held_rotations() const
  {
    HeldRotations held;
    for (const HeldBoundary &boundary : held_boundaries())
      {
        const bool along =
          boundary.condition == EdgeCondition::hard_simply_supported;
        if (!along && boundary.condition != EdgeCondition::symmetry_plane)
          continue;
        (along ? held.along : held.across).insert(boundary.id);
        if (boundary.direction > 1)
          held.projected.insert(boundary.id);
      }
    return held;
  }


  bool
  PlateGeometry::has_kinematic_support() const
  {
    std::vector<EdgeCondition> conditions(edges.begin(), edges.end());
    conditions.insert(conditions.end(), {outer, inner});
    for (const HeldTag &tag : mesh_tags)
      conditions.push_back(tag.condition);
    return std::any_of(conditions.begin(),
                       conditions.end(),
                       [](const EdgeCondition condition) {
                         return held_on_edge(condition, 0)[0];
                       });
  }


  std::string
  PlateGeometry::only_supported_edge() const
  {
    unsigned int n_supported = 0, supported = 0;
    for (unsigned int e = 0; e < edges.size(); ++e)
      if (edges[e] != EdgeCondition::free)
        {
          ++n_supported;
          supported = e;
        }
    return (n_supported == 1 && edges[supported] != EdgeCondition::clamped)
             ? edge_names[supported]
             : std::string();
  }


  PlateShape
  PlateGeometry::shape() const
  {
    return outline;
  }


  std::string
  PlateGeometry::shape_setting() const
  {
    return "Discretization/Shape = " + shapes.name(outline);
  }


  bool
  PlateGeometry::has_curved_boundary() const
  {
    return outline == PlateShape::disc || outline == PlateShape::annulus;
  }


  Symmetry
  PlateGeometry::symmetry() const
  {
    return modelled_part;
  }


  unsigned int
  PlateGeometry::n_symmetry_copies() const
  {
    return 1u << symmetry_axes().size();
  }


  std::vector<unsigned int>
  PlateGeometry::symmetry_axes() const
  {
    switch (modelled_part)
      {
      case Symmetry::full:
        return {};
      case Symmetry::half:
        return {0};
      default:
        return {0, 1};
      }
  }


  BoundingBox<2>
  PlateGeometry::plate_box() const
  {
    if (outline == PlateShape::mesh_file)
      return mesh->bounding_box();
    if (outline != PlateShape::rectangle)
      return BoundingBox<2>(
        std::make_pair(Point<2>(-radius, -radius), Point<2>(radius, radius)));
    return BoundingBox<2>(std::make_pair(Point<2>(-0.5, -0.5 * aspect_ratio),
                                         Point<2>(0.5, 0.5 * aspect_ratio)));
  }


  BoundingBox<2>
  PlateGeometry::modelled_box() const
  {
    auto corners = plate_box().get_boundary_points();
    for (const unsigned int axis : symmetry_axes())
      corners.first[axis] = 0.0;
    return BoundingBox<2>(corners);
  }


  double
  PlateGeometry::modelled_area() const
  {
    double area = plate_box().volume();
    if (outline == PlateShape::mesh_file)
      area = mesh->area();
    if (outline == PlateShape::disc)
      area = numbers::PI * radius * radius;
    if (outline == PlateShape::annulus)
      area = numbers::PI * (radius * radius - inner_radius * inner_radius);
    return area / n_symmetry_copies();
  }


  bool
  PlateGeometry::is_on_plate(const Point<2> &p) const
  {
    if (outline == PlateShape::mesh_file)
      return mesh->contains(p);
    if (outline == PlateShape::disc)
      return p.norm() <= radius * (1 + 1e-12);
    if (outline == PlateShape::annulus)
      return p.norm() <= radius * (1 + 1e-12)
             && p.norm() >= inner_radius * (1 - 1e-12);
    // Relative to the plate's size, so that a point written on an edge is
    // on the plate whatever the round-off of its decimal digits.
    return plate_box().point_inside(p, 1e-12 * std::max(1.0, aspect_ratio));
  }


  bool
  PlateGeometry::is_on_modelled_part(const Point<2> &p) const
  {
    if (outline == PlateShape::rectangle)
      return modelled_box().point_inside(p, 1e-12);
    for (const unsigned int axis : symmetry_axes())
      if (p[axis] < -1e-12 * radius)
        return false;
    return is_on_plate(p);
  }


  std::string
  PlateGeometry::plate_description() const
  {
    std::ostringstream text;
    text.precision(6);
    if (outline == PlateShape::mesh_file)
      return mesh->description();
    if (outline == PlateShape::disc)
      {
        text << "the disc of radius " << radius << " about (0, 0)";
        return text.str();
      }
    if (outline == PlateShape::annulus)
      {
        text << "the annulus " << inner_radius << " <= r <= " << radius
             << " about (0, 0)";
        return text.str();
      }
    text << "the plate [-0.5, 0.5] x [" << -0.5 * aspect_ratio << ", "
         << 0.5 * aspect_ratio << "]";
    return text.str();
  }


  Point<2>
  PlateGeometry::to_modelled_part(const Point<2> &p) const
  {
    Point<2> q = p;
    for (const unsigned int axis : symmetry_axes())
      q[axis] = std::abs(q[axis]);
    return q;
  }


  double
  PlateGeometry::share_of_point_load(const Point<2> &p) const
  {
    double share = 1.0;
    for (const unsigned int axis : symmetry_axes())
      if (std::abs(p[axis]) < 1e-12)
        share *= 0.5;
    return share;
  }
} // namespace liftoff
