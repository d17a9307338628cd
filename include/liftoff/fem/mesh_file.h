#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * A plate's coarse mesh read from a gmsh file (`Discretization/Mesh
   * file`): quadrilaterals in the plane, read by GridIn::read_msh, whose
   * physical curves name parts of the boundary. A physical curve's number
   * is the boundary id of its faces (GridIn's rule); its name, read here
   * from the file's $PhysicalNames, stands for that number. Faces of no
   * physical curve have the boundary id 0. A cell's material id is the
   * number of its physical surface. Also answers which points the mesh
   * covers, its edges included.
   */
  class MeshFile
  {
  public:
    /// Read `file_name`, whose coordinates are in a unit of which the
    /// solver's length unit L is `length_scale` (1 in a dimensionless
    /// scene, L in metres in an SI one): they are divided by it. Refused in
    /// one line that names Discretization/Mesh file and the cause: no file,
    /// a file GridIn cannot read as a planar mesh (a 3D mesh among them),
    /// cells that are not quadrilaterals, cells with two nodes at one place
    /// or not convex, cells that touch without sharing their nodes (a
    /// physical name given to two curves. Whether cells touch without
    /// sharing their nodes is checked by require_conforming(), once the
    /// joints are known.
    explicit MeshFile(const std::string &file_name,
                      const double       length_scale = 1.0);

    /// Refuses cells that touch without sharing nodes (a node on another
    /// cell's edge, two nodes at one place: GridIn would take the plate as
    /// cut there, silently) except along the curves `joints`, where the
    /// plate is cut on purpose: there each edge must face one edge of the
    /// same curve with the same two ends.
    void
    require_conforming(const std::set<types::boundary_id> &joints) const;

    /// The coarse mesh, with the boundary ids of the file, into an empty
    /// triangulation (a distributed one too).
    void
    copy_to(Triangulation<2> &triangulation) const;
    unsigned int
    n_cells() const;

    /// The boundary id of the physical curve called `tag`, by its name or
    /// its number; refused, with the names and numbers of the file, if it
    /// has none such. `parameter` names the entry in the message.
    types::boundary_id
    boundary_id(const std::string &tag, const std::string &parameter) const;
    /// 0 if every face of the boundary `id` is parallel to the x axis, 1 if
    /// every one is parallel to the y axis, else numbers::invalid_unsigned_int.
    unsigned int
    direction_of(const types::boundary_id id) const;

    /// True for a point of a cell of the mesh, its edges included.
    bool
    contains(const Point<2> &p) const;
    /// The material id (physical surface) of a cell holding `p`, or
    /// numbers::invalid_material_id off the mesh.
    types::material_id
    material_id_at(const Point<2> &p) const;
    BoundingBox<2>
    bounding_box() const;
    /// The area its cells cover.
    double
    area() const;
    /// "the mesh of FILE (inside the box [x0, x1] x [y0, y1])", for messages.
    std::string
    description() const;

  private:
    void
    read_physical_names(const std::string &text);
    void
    read_cells(const std::string &text);
    /// Refuses a cell with two nodes at one place, or one that is not
    /// convex: its bilinear map would not be one to one.
    void
    check_cell_shape(const Triangulation<2>::active_cell_iterator &cell) const;
    /// The nodes (`by_x`: the used vertices sorted by x) on the boundary
    /// edge `face` other than its own ends: refused, except the nodes of
    /// the joints' edges (`joint_ends`) at the ends of another's.
    void
    check_edge(const Triangulation<2>::active_face_iterator &face,
               const std::vector<unsigned int>              &by_x,
               const std::set<unsigned int>                 &joint_ends) const;
    /// Refuses a joint's edge that faces no edge of the same joint (in
    /// `joint_faces`) with the same two ends.
    void
    require_facing_edge(
      const Triangulation<2>::active_face_iterator              &face,
      const std::vector<Triangulation<2>::active_face_iterator> &joint_faces)
      const;
    /// The named tags of the file and the unnamed boundary ids, for messages.
    std::string
    known_tags() const;

    std::string                               name;
    std::unique_ptr<Triangulation<2>>         coarse;
    std::map<std::string, types::boundary_id> physical_names;
  };
} // namespace liftoff
