#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>

#include <liftoff/base/number_text.h>
#include <liftoff/base/output_files.h>
#include <liftoff/fem/mesh_file.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace liftoff
{
  namespace
  {
    // The first line of a message, its blanks run together: deal.II's
    // exceptions span several lines.
    std::string
    text_of(const Point<2> &p)
    {
      return "(" + format_number(p[0]) + ", " + format_number(p[1]) + ")";
    }


    // "(x0, y0), (x1, y1), ...": a cell by its corners in the file's
    // coordinates, as messages name it.
    std::string
    corners_of(const Triangulation<2>::active_cell_iterator &cell)
    {
      std::string text;
      for (const unsigned int v : {0u, 1u, 3u, 2u})
        text += (text.empty() ? "" : ", ") + text_of(cell->vertex(v));
      return text;
    }


    std::string
    first_line(const std::string &message)
    {
      std::istringstream words(message.substr(0, message.find('\n')));
      std::string        word, line;
      while (words >> word)
        line += (line.empty() ? "" : " ") + word;
      return line;
    }
  } // namespace


  MeshFile::MeshFile(const std::string &file_name, const double length_scale)
      : name(file_name)
      , coarse(std::make_unique<Triangulation<2>>())
  {
    const std::string parameter = "Discretization/Mesh file = " + name;
    AssertThrow(!name.empty(),
                ExcMessage("Discretization/Mesh file must name a gmsh .msh "
                           "file for Discretization/Shape = mesh file."));
    AssertThrow(!std::filesystem::is_directory(name),
                ExcMessage(parameter + " is a folder, not a mesh file."));
    AssertThrow(std::filesystem::is_regular_file(name),
                ExcMessage(parameter + ": there is no such file."));
    std::ifstream      file(name);
    std::ostringstream text;
    text << file.rdbuf();
    AssertThrow(file.good() || file.eof(),
                ExcMessage(parameter + ": the file cannot be read."));
    read_physical_names(text.str());
    read_cells(text.str());
    // Divided rather than multiplied by 1 / L, as the SI scene's other
    // lengths are, so that a mesh in metres lands where they do.
    if (length_scale != 1.0)
      GridTools::transform(
        [length_scale](const Point<2> &p) {
          return Point<2>(p[0] / length_scale, p[1] / length_scale);
        },
        *coarse);
  }


  void
  MeshFile::read_physical_names(const std::string &text)
  {
    // GridIn reads the numbers of physical curves, not their names.
    const std::size_t start = text.find("$PhysicalNames");
    if (start == std::string::npos)
      return;
    std::istringstream section(text.substr(start + 14));
    unsigned int       n_names = 0;
    section >> n_names;
    for (unsigned int i = 0; i < n_names && section; ++i)
      {
        int         dimension = 0, tag = 0;
        std::string line;
        section >> dimension >> tag;
        std::getline(section, line);
        const std::string quoted = Utilities::trim(line);
        const std::string tag_name =
          quoted.size() >= 2 ? quoted.substr(1, quoted.size() - 2) : quoted;
        // Names of surfaces or volumes name no boundary.
        if (dimension != 1)
          continue;
        const auto known = physical_names.find(tag_name);
        AssertThrow(known == physical_names.end()
                      || known->second == static_cast<types::boundary_id>(tag),
                    ExcMessage("Discretization/Mesh file = " + name
                               + ": the physical name \"" + tag_name
                               + "\" is given to the curves "
                               + std::to_string(known->second) + " and "
                               + std::to_string(tag)
                               + "; a name must stand for one tag."));
        physical_names[tag_name] = tag;
      }
  }


  void
  MeshFile::read_cells(const std::string &text)
  {
    const std::string parameter = "Discretization/Mesh file = " + name;
    try
      {
        GridIn<2> grid_in;
        grid_in.attach_triangulation(*coarse);
        std::istringstream in(text);
        grid_in.read_msh(in);
      }
    catch (const std::exception &e)
      {
        AssertThrow(false,
                    ExcMessage(parameter
                               + ": GridIn cannot read it as a planar gmsh "
                                 "mesh (msh 2.2 or 4.1 in ASCII, 2D cells "
                                 "only): "
                               + first_line(message_of(e))));
      }
    for (const auto &cell : coarse->active_cell_iterators())
      AssertThrow(cell->reference_cell() == ReferenceCells::Quadrilateral,
                  ExcMessage(parameter
                             + ": it holds cells that are not quadrilaterals "
                               "(triangles?); liftoff's elements are "
                               "quadrilaterals (gmsh: Mesh.RecombineAll = 1, "
                               "or Recombine Surface)."));
    for (const auto &cell : coarse->active_cell_iterators())
      check_cell_shape(cell);
  }


  void
  MeshFile::check_cell_shape(
    const Triangulation<2>::active_cell_iterator &cell) const
  {
    const std::string parameter = "Discretization/Mesh file = " + name;
    const double      size      = cell->diameter();
    for (const unsigned int i : cell->vertex_indices())
      for (unsigned int j = i + 1; j < cell->n_vertices(); ++j)
        AssertThrow(cell->vertex(i).distance(cell->vertex(j)) > 1e-10 * size,
                    ExcMessage(parameter + ": the cell " + corners_of(cell)
                               + " has two nodes at " + text_of(cell->vertex(i))
                               + "; a quadrilateral needs four distinct "
                                 "corners (a triangle cannot be written as "
                                 "a quadrilateral with a repeated node)."));
    // The bilinear map is one to one where its Jacobian keeps its sign at
    // the four corners (deal.II's vertices 0, 1, 3, 2 run round the cell):
    // a non-convex or self-crossing cell fails at one of them.
    const std::array<unsigned int, 4> round      = {{0, 1, 3, 2}};
    unsigned int                      n_positive = 0, n_negative = 0;
    for (unsigned int k = 0; k < 4; ++k)
      {
        const Point<2> &at = cell->vertex(round[k]);
        const double    turn =
          cross_product_2d(at - cell->vertex(round[(k + 3) % 4]))
          * (cell->vertex(round[(k + 1) % 4]) - at);
        n_positive += turn > 1e-10 * size * size;
        n_negative += turn < -1e-10 * size * size;
      }
    AssertThrow(n_positive == 4 || n_negative == 4,
                ExcMessage(parameter + ": the cell " + corners_of(cell)
                           + " is not convex (or its corners are not in "
                             "order round it); liftoff's cells must be "
                             "convex quadrilaterals."));
  }


  void
  MeshFile::require_conforming(const std::set<types::boundary_id> &joints) const
  {
    // GridIn joins cells by shared node numbers only. A node lying on
    // another cell's edge without being one of its nodes (a hanging node,
    // or a second node at the place of one) leaves both edges at the
    // boundary: the plate would be cut there, silently.
    std::vector<unsigned int> by_x;
    const auto               &vertices = coarse->get_vertices();
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (coarse->get_used_vertices()[v])
        by_x.push_back(v);
    std::sort(by_x.begin(), by_x.end(), [&](const auto a, const auto b) {
      return vertices[a][0] < vertices[b][0];
    });
    std::vector<Triangulation<2>::active_face_iterator> joint_faces;
    for (const auto &face : coarse->active_face_iterators())
      if (face->at_boundary() && joints.count(face->boundary_id()) > 0)
        joint_faces.push_back(face);
    std::set<unsigned int> joint_ends;
    for (const auto &face : joint_faces)
      {
        require_facing_edge(face, joint_faces);
        joint_ends.insert({face->vertex_index(0), face->vertex_index(1)});
      }
    for (const auto &face : coarse->active_face_iterators())
      if (face->at_boundary())
        check_edge(face, by_x, joint_ends);
  }


  void
  MeshFile::require_facing_edge(
    const Triangulation<2>::active_face_iterator              &face,
    const std::vector<Triangulation<2>::active_face_iterator> &joint_faces)
    const
  {
    const double tolerance = 1e-10 * face->diameter();
    const auto   same      = [&](const Point<2> &a, const Point<2> &b) {
      return a.distance(b) <= tolerance;
    };
    const Point<2> a = face->vertex(0), b = face->vertex(1);
    for (const auto &other : joint_faces)
      if (other != face && other->boundary_id() == face->boundary_id()
          && ((same(other->vertex(0), a) && same(other->vertex(1), b))
              || (same(other->vertex(0), b) && same(other->vertex(1), a))))
        return;
    const auto named = std::find_if(physical_names.begin(),
                                    physical_names.end(),
                                    [&](const auto &n) {
                                      return n.second == face->boundary_id();
                                    });
    AssertThrow(false,
                ExcMessage("Discretization/Mesh file = " + name + ": the joint "
                           + (named != physical_names.end()
                                ? named->first
                                : std::to_string(face->boundary_id()))
                           + " has the edge from " + text_of(a) + " to "
                           + text_of(b)
                           + ", which faces no edge of the joint with the "
                             "same ends: a joint is a curve given on both "
                             "slabs, with the nodes of both at the same "
                             "places."));
  }


  void
  MeshFile::check_edge(const Triangulation<2>::active_face_iterator &face,
                       const std::vector<unsigned int>              &by_x,
                       const std::set<unsigned int> &joint_ends) const
  {
    const auto        &vertices = coarse->get_vertices();
    const Point<2>     a = face->vertex(0), b = face->vertex(1);
    const Tensor<1, 2> along     = b - a;
    const double       tolerance = 1e-10 * along.norm();
    const auto         first =
      std::lower_bound(by_x.begin(),
                       by_x.end(),
                       std::min(a[0], b[0]) - tolerance,
                       [&](const unsigned int v, const double x) {
                         return vertices[v][0] < x;
                       });
    for (auto v = first;
         v != by_x.end() && vertices[*v][0] <= std::max(a[0], b[0]) + tolerance;
         ++v)
      {
        if (*v == face->vertex_index(0) || *v == face->vertex_index(1))
          continue;
        const Point<2> &p = vertices[*v];
        const double    s =
          std::clamp((p - a) * along / along.norm_square(), 0.0, 1.0);
        if (p.distance(a + s * along) > tolerance)
          continue;
        // Slabs cut at a joint have a node each at the joint's nodes.
        const unsigned int end =
          p.distance(a) <= tolerance   ? face->vertex_index(0)
          : p.distance(b) <= tolerance ? face->vertex_index(1)
                                       : numbers::invalid_unsigned_int;
        if (end != numbers::invalid_unsigned_int && joint_ends.count(*v) > 0
            && joint_ends.count(end) > 0)
          continue;
        const std::string parameter = "Discretization/Mesh file = " + name;
        AssertThrow(end == numbers::invalid_unsigned_int,
                    ExcMessage(parameter + ": two nodes lie at " + text_of(p)
                               + ", and the cells of each are not joined "
                                 "there: the plate would be cut. Let the "
                                 "cells share one node (gmsh: one surface, "
                                 "or Coherence), or name the curve a joint "
                                 "(Boundary conditions/Mesh tags = ...: "
                                 "joint)."));
        AssertThrow(false,
                    ExcMessage(parameter + ": the node at " + text_of(p)
                               + " lies inside the edge from " + text_of(a)
                               + " to " + text_of(b)
                               + " of a cell that does not have it (a "
                                 "hanging node): the plate would be cut "
                                 "there. Mesh both sides with the node "
                                 "shared (a conforming mesh)."));
      }
  }


  void
  MeshFile::copy_to(Triangulation<2> &triangulation) const
  {
    triangulation.copy_triangulation(*coarse);
  }


  unsigned int
  MeshFile::n_cells() const
  {
    return coarse->n_active_cells();
  }


  types::boundary_id
  MeshFile::boundary_id(const std::string &tag,
                        const std::string &parameter) const
  {
    const auto named = physical_names.find(tag);
    if (named != physical_names.end())
      return named->second;
    const std::vector<types::boundary_id> ids = coarse->get_boundary_ids();
    for (const types::boundary_id id : ids)
      if (tag == std::to_string(id))
        return id;
    AssertThrow(false,
                ExcMessage(parameter + ": " + name
                           + " has no physical curve called \"" + tag
                           + "\"; it has " + known_tags() + "."));
    return 0;
  }


  std::string
  MeshFile::known_tags() const
  {
    std::string            list;
    std::set<unsigned int> named;
    for (const auto &[tag_name, id] : physical_names)
      {
        list += (list.empty() ? "" : ", ") + tag_name + " ("
                + std::to_string(id) + ")";
        named.insert(id);
      }
    for (const types::boundary_id id : coarse->get_boundary_ids())
      if (named.count(id) == 0)
        list += (list.empty() ? "" : ", ") + std::to_string(id)
                + (id == 0 ? " (faces of no physical curve)" : " (unnamed)");
    return list.empty() ? "no boundary" : list;
  }


  unsigned int
  MeshFile::direction_of(const types::boundary_id id) const
  {
    std::set<unsigned int> directions;
    for (const auto &face : coarse->active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == id)
        {
          const Tensor<1, 2> d = face->vertex(1) - face->vertex(0);
          // Parallel to x: the face's y extent is round-off of its length.
          const double tolerance = 1e-12 * d.norm();
          directions.insert(std::abs(d[1]) <= tolerance   ? 0u
                            : std::abs(d[0]) <= tolerance ? 1u
                                                          : 2u);
        }
    return (directions.size() == 1 && *directions.begin() < 2)
             ? *directions.begin()
             : numbers::invalid_unsigned_int;
  }


  bool
  MeshFile::contains(const Point<2> &p) const
  {
    return material_id_at(p) != numbers::invalid_material_id;
  }


  types::material_id
  MeshFile::material_id_at(const Point<2> &p) const
  {
    // Exact for the coarse mesh's straight-sided cells; a point on an edge
    // is inside to round-off of the cell's size.
    const auto &mapping =
      ReferenceCells::Quadrilateral.get_default_linear_mapping<2, 2>();
    for (const auto &cell : coarse->active_cell_iterators())
      if (cell->bounding_box().point_inside(p, 1e-12))
        try
          {
            const Point<2> unit = mapping.transform_real_to_unit_cell(cell, p);
            if (GeometryInfo<2>::is_inside_unit_cell(unit, 1e-12))
              return cell->material_id();
          }
        catch (const Mapping<2>::ExcTransformationFailed &)
          {
            // Not in this cell.
          }
    return numbers::invalid_material_id;
  }


  BoundingBox<2>
  MeshFile::bounding_box() const
  {
    return GridTools::compute_bounding_box(*coarse);
  }


  double
  MeshFile::area() const
  {
    return GridTools::volume(*coarse);
  }


  std::string
  MeshFile::description() const
  {
    const auto         corners = bounding_box().get_boundary_points();
    std::ostringstream text;
    text.precision(6);
    text << "the mesh of " << name << " (inside [" << corners.first[0] << ", "
         << corners.second[0] << "] x [" << corners.first[1] << ", "
         << corners.second[1] << "])";
    return text.str();
  }
} // namespace liftoff
