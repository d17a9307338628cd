#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <liftoff/fem/mesh_file.h>
#include <liftoff/fem/mindlin_plate.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class PlateGeometry;

  /// A straight joint between neighbouring slabs, x = const (normal along
  /// x) or y = const, from `start` to `end` along it: on the rectangle x1,
  /// x2, ... the transverse joints, y1, ... the longitudinal ones; in a
  /// mesh file a physical curve. Its faces carry two boundary ids, one per
  /// side: `lower_side` that of the slab with the smaller coordinate. A
  /// joint on a symmetry plane (`on_plane`) has the modelled slab on its
  /// upper side only; the lower side is that slab's mirror image.
  struct Joint
  {
    std::string        name;
    unsigned int       normal_axis;
    double             position;
    types::boundary_id lower_side;
    types::boundary_id upper_side;
    bool               tied;
    double             start;
    double             end;
    bool               on_plane = false;
    /// Its place among the whole plate's joints (x1, x2, ..., y1, ...; a
    /// mesh file's in its order), which lists per joint follow also on a
    /// half or quarter model.
    unsigned int number = 0;
  };

  /**
   * The plate as slabs: the rectangle as a grid of `Slabs along x` by
   * `Slabs along y` of equal size, or of the lengths and widths given
   * (`Slab lengths`, `Slab widths`), with a joint between neighbours; or a
   * mesh file's physical surfaces (slab numbers in the order of theirs),
   * cut along its curves of the condition `joint`, each a straight line
   * along x or y given on both slabs with the nodes of both at the same
   * places. Surfaces that share nodes are joined monolithically. The slabs
   * of the rectangle share no vertex:
   * the coarse mesh is cut along the joints, so that w and psi may jump
   * there, and each joint's two faces are paired as periodic faces of the
   * triangulation (with no offset), which puts the cells across a joint
   * into each other's ghost layer on every rank and keeps the refinement
   * 2:1 across it. What a joint passes (springs, JointSprings) is a system
   * term; a tied joint is monolithic, its dofs identified by periodicity
   * constraints, and a slab whose joints are all free is computed alone.
   */
  class SlabLayout
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    /// The joints of `geometry`'s plate, refused (naming the entries) on
    /// a disc or annulus, or where a joint's line is no line of the coarse
    /// cells; the slabs and joints (`joint_tags`,
    /// boundary id and name) of `mesh` if there is one.
    void
    parse_parameters(
      ParameterHandler                      &prm,
      const PlateGeometry                   &geometry,
      const std::shared_ptr<const MeshFile> &mesh,
      const std::vector<std::pair<types::boundary_id, std::string>>
        &joint_tags);

    /// The number of slabs.
    unsigned int
    n_slabs() const;
    /// Whether the plate is more than one slab or has joints.
    bool
    is_jointed() const;
    /// The joints inside the modelled part of the plate.
    const std::vector<Joint> &
    joints() const;
    /// The number of joints of the whole plate, modelled or not.
    unsigned int
    n_joints_of_plate() const;
    /// The joint a boundary id belongs to, or nullptr (an edge, a plane).
    const Joint *
    joint_of(const types::boundary_id id) const;

    /// `whole` cut along the joints into `cut` (vertices on a joint once
    /// per slab; boundary ids kept, the joints' faces given theirs; the
    /// material id of a cell its slab's number), with the joints' faces
    /// paired as periodic. `whole` is the geometry's coarse mesh.
    void
    cut(const Triangulation<2>                  &whole,
        parallel::distributed::Triangulation<2> &cut) const;
    /// The couplings between the dofs of cells facing each other across
    /// the joints that are not tied, with `constraints`, in `pattern`.
    void
    add_couplings(const DoFHandler<2>             &dof_handler,
                  const AffineConstraints<double> &constraints,
                  DynamicSparsityPattern          &pattern) const;
    /// f(cell, face, joint) once for each piece of the joints that are not
    /// tied, from the locally owned cell on its finer side (the lower one
    /// where both are alike): each piece of a joint is visited on one rank
    /// exactly once, with the cell opposite its periodic neighbour.
    void
    for_each_joint_face(
      const DoFHandler<2>                           &dof_handler,
      const std::function<void(const DoFHandler<2>::active_cell_iterator &,
                               const unsigned int,
                               const unsigned int)> &f) const;
    /// The cell across the joint face `face` of `cell`: its periodic
    /// neighbour, or on a symmetry plane the cell itself, whose mirror
    /// image is across (the same w and stresses, the opposite psi . n).
    DoFHandler<2>::cell_iterator
    across(const DoFHandler<2>::active_cell_iterator &cell,
           const unsigned int                         face) const;
    /// The number of the slab a point of the full plate is on (x first on
    /// the rectangle).
    unsigned int
    slab_of(const Point<2> &p) const;
    /// Refuse sections that differ between a slab and its mirror image in a
    /// plane of `symmetry_axes` (normals): the model would not be
    /// symmetric.
    void
    require_symmetric(const std::vector<SlabSection>  &sections,
                      const std::vector<unsigned int> &symmetry_axes,
                      const std::string               &symmetry_name) const;
    /// The tied joints' dofs identified across them.
    void
    tie(const DoFHandler<2> &dof_handler, AffineConstraints<double> &c) const;

  private:
    std::array<unsigned int, 2> slab_grid = {{1, 1}};
    /// A mesh file's slabs: the slab number of each physical surface.
    std::shared_ptr<const MeshFile>            mesh;
    std::map<types::material_id, unsigned int> slab_numbers;
    std::set<types::boundary_id>               joint_tag_ids;
    /// Slab lengths along x and widths along y as the scene gives them
    /// (empty: equal slabs), and the entries' text for messages.
    std::array<std::vector<double>, 2> given_sizes;
    std::array<std::string, 2>         given_texts;
    /// The ends of the slabs of the full plate along x and y: slab j from
    /// edges[axis][j] to edges[axis][j + 1].
    std::array<std::vector<double>, 2> edges;
    std::vector<Joint>                 joint_list;

    /// Slab lengths and widths of the current subsection (Slabs), which
    /// set the slabs along x and y; refused naming the entry.
    void
    read_given_sizes(ParameterHandler &prm);
    /// edges[axis] on the plate from `low` to `high`: equal slabs, or the
    /// given sizes, refused naming the entry unless they add up to the
    /// plate's size and, on a symmetry plane normal to `axis`
    /// (`mirrored`), are mirrored.
    void
    place_edges(const unsigned int axis,
                const double       low,
                const double       high,
                const bool         mirrored);

    /// The joints inside the modelled part, each on a line of the coarse
    /// cells.
    void
    place_joints(const PlateGeometry &geometry);
    /// The joints along the mesh file's curves `joint_tags`, and its slabs.
    void
    place_mesh_joints(
      const std::vector<std::pair<types::boundary_id, std::string>>
        &joint_tags);
    /// The boundary ids of `whole`'s faces on the same faces of `cut`, and
    /// the joints' on the faces that are new.
    void
    mark_faces(const Triangulation<2> &whole, Triangulation<2> &cut) const;
  };
} // namespace liftoff
