#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <liftoff/fem/mindlin_plate.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class PlateGeometry;

  /// A straight joint between two neighbouring slabs of the rectangle: x1,
  /// x2, ... the transverse joints x = const (normal along x), y1, ... the
  /// longitudinal ones y = const. Its faces carry two boundary ids, one per
  /// side: `lower_side` that of the slab with the smaller coordinate.
  struct Joint
  {
    std::string        name;
    unsigned int       normal_axis;
    double             position;
    types::boundary_id lower_side;
    types::boundary_id upper_side;
    bool               tied;
  };

  /**
   * The rectangle as a grid of slabs, `Slabs along x` by `Slabs along y` of
   * equal size, with a joint between neighbours. The slabs share no vertex:
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
    /// another shape than the rectangle, where a joint's line is no line
    /// of the coarse cells, or on a symmetry plane.
    void
    parse_parameters(ParameterHandler &prm, const PlateGeometry &geometry);

    /// Whether the plate is more than one slab.
    bool
    is_jointed() const;
    /// The joints inside the modelled part of the plate.
    const std::vector<Joint> &
    joints() const;
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
    /// The number of the slab a point of the full plate is on (x first).
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
    std::array<unsigned int, 2> n_slabs = {{1, 1}};
    /// The lowest corner and the size of a slab of the full plate.
    std::array<double, 2> origin    = {{0, 0}};
    std::array<double, 2> slab_size = {{1, 1}};
    std::vector<Joint>    joint_list;

    /// The joints inside the modelled part, each on a line of the coarse
    /// cells.
    void
    place_joints(const PlateGeometry &geometry);
    /// The boundary ids of `whole`'s faces on the same faces of `cut`, and
    /// the joints' on the faces that are new.
    void
    mark_faces(const Triangulation<2> &whole, Triangulation<2> &cut) const;
  };
} // namespace liftoff
