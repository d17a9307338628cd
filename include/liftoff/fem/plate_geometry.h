#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/grid/tria.h>

#include <liftoff/base/physical_units.h>
#include <liftoff/fem/mesh_file.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/slab_layout.h>

#include <array>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /// How an edge of the plate is held.
  enum class EdgeCondition
  {
    free,
    hard_simply_supported, // w = 0 and the tangential rotation is zero
    soft_simply_supported, // w = 0 only
    clamped,               // w = psi_x = psi_y = 0
    symmetry_plane,        // the rotation normal to the edge is zero
    joint                  // a mesh file's curve between slabs (SlabLayout)
  };

  /// The plate's outline: the rectangle [-1/2, 1/2] x [-mu/2, mu/2], the
  /// disc of radius R about the origin, the annulus between the circles
  /// of radii R_i and R about it, or the mesh of a gmsh file.
  enum class PlateShape
  {
    rectangle,
    disc,
    annulus,
    mesh_file
  };

  /// Which part of the plate is meshed. The scene always describes the full
  /// plate; symmetry planes are x = 0 (half and quarter) and y = 0 (quarter),
  /// on every shape.
  enum class Symmetry
  {
    full,
    half,
    quarter
  };

  /// The boundaries that hold the rotation along them, psi . t = 0 (hard
  /// simple support), and across them, psi . n = 0 (symmetry planes);
  /// `projected` those of them along no axis (circles, oblique curves of a
  /// mesh file), where that rotation is no component of psi and
  /// PlateGeometry::held_components() holds w alone: Discretization
  /// constrains psi there by normal-tangential constraints.
  struct HeldRotations
  {
    std::set<types::boundary_id> along;
    std::set<types::boundary_id> across;
    std::set<types::boundary_id> projected;
  };

  /**
   * The shape of the plate and how it is held: the rectangle
   * [-1/2, 1/2] x [-mu/2, mu/2], a disc, an annulus or the mesh of a gmsh
   * file (MeshFile), the part of it that is meshed (full, half, quarter;
   * the rectangle only), its coarse mesh with the boundary ids of edges
   * and symmetry planes, and the condition on each edge (on each physical
   * curve of a mesh file that `Boundary conditions/Mesh tags` names). Every
   * question of the form "is this point on the plate" or "which part carries
   * this load" is answered here, so that another shape is a change of this
   * class alone.
   */
  class PlateGeometry
  {
  public:
    /// Boundary ids: the four plate edges, then the symmetry planes.
    enum BoundaryId : types::boundary_id
    {
      left_edge        = 0,
      right_edge       = 1,
      bottom_edge      = 2,
      top_edge         = 3,
      x_symmetry_plane = 4, // x = 0
      y_symmetry_plane = 5, // y = 0
      outer_boundary   = 6, // the circle of a disc, the outer of an annulus
      inner_boundary   = 7  // the hole's circle of an annulus
    };

    /// Entries in "Discretization" (Shape, Radius, Inner radius, Mesh file,
    /// Symmetry, Cells along x and y) and "Boundary conditions".
    static void
    declare_parameters(ParameterHandler &prm);
    /// The plate's aspect ratio is taken here, so that every check of a
    /// point against the plate made while parsing sees the real plate.
    /// A mesh file is in the length unit of the scene as written (`units`):
    /// L in a dimensionless scene, metres in an SI one.
    void
    parse_parameters(ParameterHandler    &prm,
                     const MindlinPlate  &plate,
                     const PhysicalUnits &units);

    /// The `Cells along x` x `Cells along y` cells of the meshed part with
    /// the boundary ids of edges and symmetry planes, in an empty
    /// triangulation.
    void
    create_coarse_mesh(Triangulation<2> &triangulation) const;
    /// Cells of the coarse mesh along x (axis 0) or y (axis 1).
    unsigned int
    coarse_cells_along(const unsigned int axis) const;
    /// The largest aspect ratio of the coarse cells (refinement keeps it):
    /// the larger of width / height and height / width of the rectangle's
    /// cells; on the other shapes the largest ratio of the singular values
    /// of a cell's Jacobian at its 2 x 2 Gauss points.
    double
    largest_cell_aspect_ratio() const;

    /// The components of an element of `layers` layers held at zero on
    /// each boundary that holds any: the supported edges, then the
    /// symmetry planes (every layer), then the joints on a symmetry plane
    /// (a base of its own alone).
    std::vector<std::pair<types::boundary_id, ComponentMask>>
    held_components(const unsigned int layers) const;
    /// The boundaries that hold a rotation, and those along no axis.
    HeldRotations
    held_rotations() const;
    /// True when some edge restrains w, so the stiffness alone is regular
    /// enough for a static solve without foundation contact.
    bool
    has_kinematic_support() const;
    /// The name of the edge ("Left", ...) if it is the only one that holds
    /// the plate and it is not clamped: the plate can turn about it, so
    /// only a foundation makes a static problem regular. Else "".
    std::string
    only_supported_edge() const;

    /// The slabs the rectangle is made of and the joints between them.
    const SlabLayout &
    slabs() const;

    PlateShape
    shape() const;
    /// "Discretization/Shape = disc": messages about what a shape does not
    /// support name it as the scene does.
    std::string
    shape_setting() const;
    /// True when the boundary is curved, so the mapping must follow it.
    bool
    has_curved_boundary() const;

    Symmetry
    symmetry() const;
    /// How many copies of the modelled part make the plate (1, 2 or 4).
    unsigned int
    n_symmetry_copies() const;
    /// Axes normal to the symmetry planes (0: plane x = 0, 1: plane y = 0).
    std::vector<unsigned int>
    symmetry_axes() const;

    /// The full plate and the part of it that is meshed.
    BoundingBox<2>
    plate_box() const;
    BoundingBox<2>
    modelled_box() const;
    /// The area of the meshed part as the outline has it (the circles'
    /// exact, not the mesh's).
    double
    modelled_area() const;
    /// True for a point of the plate, its edges included.
    bool
    is_on_plate(const Point<2> &p) const;
    /// True for a point of the meshed part, its edges included.
    bool
    is_on_modelled_part(const Point<2> &p) const;
    /// "the plate [-0.5, 0.5] x [-1, 1]": messages about points off it name
    /// the plate in numbers, since mu is a parameter of another class.
    std::string
    plate_description() const;
    /// Mirror a point of the full plate into the modelled part.
    Point<2>
    to_modelled_part(const Point<2> &p) const;
    /// Share of a concentrated load at p (in the modelled part) that the
    /// modelled part carries: 1/2 for each symmetry plane p lies on.
    double
    share_of_point_load(const Point<2> &p) const;

  private:
    /// The entries of `Boundary conditions`, in the order of the edges'
    /// boundary ids.
    static const std::array<std::string, 4> edge_names;

    static void
    declare_boundary_conditions(ParameterHandler &prm);
    void
    check_shape_choices(const std::string &symmetry_name) const;
    void
    check_mesh_file_choices() const;
    /// An SI scene's Units/Length (`length`, in m) against the length of
    /// the mesh in metres along x, which it must be.
    void
    check_mesh_length(const std::string &file_name, const double length) const;
    /// The conditions of `Boundary conditions/Mesh tags` on the tags of the
    /// mesh file, each tag once.
    void
    parse_mesh_tags(const std::string &text);
    /// Cells of the coarse ring GridGenerator::hyper_shell makes: at
    /// least 8, so that a mapping of degree 2 carries the area to 1e-3
    /// (7.8e-4 on 8 arcs, 1.2e-2 on 4), and a multiple of 4 (2) on a
    /// quarter (half) model, so that the planes x = 0 and y = 0 run along
    /// cell faces.
    unsigned int
    n_ring_cells() const;
    void
    create_rectangle(Triangulation<2> &triangulation) const;
    /// The whole disc or annulus.
    void
    create_round_plate(Triangulation<2> &triangulation) const;
    /// The boundary and manifold ids of `whole` on the cells of `part`
    /// (cut from it), the planes' ids on the cut, and the manifolds.
    void
    copy_round_plate_marks(const Triangulation<2> &whole,
                           Triangulation<2>       &part) const;

    PlateShape                      outline       = PlateShape::rectangle;
    double                          radius        = 0.5;
    double                          inner_radius  = 0.25;
    EdgeCondition                   outer         = EdgeCondition::free;
    EdgeCondition                   inner         = EdgeCondition::free;
    double                          aspect_ratio  = 1.0;
    Symmetry                        modelled_part = Symmetry::full;
    unsigned int                    n_cells_x     = 10;
    unsigned int                    n_cells_y     = 10;
    std::array<EdgeCondition, 4>    edges         = {{EdgeCondition::free,
                                                      EdgeCondition::free,
                                                      EdgeCondition::free,
                                                      EdgeCondition::free}};
    std::shared_ptr<const MeshFile> mesh;
    SlabLayout                      slab_layout;
    /// A boundary that is not free: its condition and its direction (0
    /// along x, 1 along y, another value along neither).
    struct HeldBoundary
    {
      types::boundary_id id;
      EdgeCondition      condition;
      unsigned int       direction;
    };
    std::vector<HeldBoundary>
    held_boundaries() const;

    /// Boundary id of a tag of the mesh file, its name in the scene and
    /// its condition, for the tags the scene holds.
    struct HeldTag
    {
      types::boundary_id id;
      std::string        name;
      EdgeCondition      condition;
    };
    std::vector<HeldTag> mesh_tags;
  };

  /// PlateGeometry's part of the SI conversion's outline: whether the
  /// scene as written is the rectangle of Units/Length x Units/Width, and
  /// Units/Width refused beside a mesh file (a function beside the class,
  /// which has members enough).
  void
  describe_shape_for_units(ParameterHandler            &scene,
                           PhysicalUnits::SceneOutline &outline);
} // namespace liftoff
