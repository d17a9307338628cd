#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/thread_local_storage.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/fem/transverse_shear_strain.h>
#include <liftoff/loads/free_bending.h>
#include <liftoff/output/plate_field_at_points.h>

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  class Discretization;

  /// The largest principal stress at each face of the plate: `top` at the
  /// face away from the bed (z = -H/2), `bottom` at the bed-side face
  /// (z = +H/2); positive in tension.
  struct FaceStresses
  {
    double top    = 0;
    double bottom = 0;
    /// The base's faces, where there is a base (BaseLayer).
    double base_top    = 0;
    double base_bottom = 0;

    /// The faces in the order of name(): the slab's top and bottom, then
    /// the base's.
    double
    of(const unsigned int face) const
    {
      const double values[] = {top, bottom, base_top, base_bottom};
      return values[face];
    }
    /// "top", "bottom", "base_top", "base_bottom": the faces in the names
    /// of fields and columns (sigma_1_ + name).
    static const char *
    name(const unsigned int face)
    {
      const char *names[] = {"top", "bottom", "base_top", "base_bottom"};
      return names[face];
    }
    /// A face's name in the summary: "top", "base top".
    static std::string
    text(const unsigned int face)
    {
      std::string words = name(face);
      std::replace(words.begin(), words.end(), '_', ' ');
      return words;
    }
    /// How many faces a section has: the slab's two, and the base's.
    static unsigned int
    count(const bool with_base)
    {
      return with_base ? 4 : 2;
    }
  };

  /**
   * The plate's stress resultants from (w, psi_x, psi_y) at any points of a
   * cell: the moments M_xx, M_yy, M_xy by the plate's constitutive law, the
   * shear forces Q_x, Q_y from the shear strain the element uses (for mitc
   * the assumed strain interpolated from its tying points, not the raw
   * grad w - psi, which oscillates), the principal moments and the angle
   * of the larger, and the bending stresses at the faces. A
   * DataPostprocessor, so DataOut evaluates it at the output points;
   * at_point() evaluates the same code at one point. doc/model.md
   * ("Moments, shear forces and stresses") has the formulas, the units and
   * the sign convention.
   */
  class StressResultants : public DataPostprocessor<2>
  {
  public:
    /// `solution` is the ghosted (w, psi_x, psi_y) the output writes; the
    /// shear forces of mitc need its values at the cell's tying points.
    /// `free_bending` (the temperature loads' at the step's time; empty:
    /// none) shifts the moments and adds the face stresses. With
    /// `face_fields` the output (get_names()) also has sigma_1_top and
    /// sigma_1_bottom, which at_point() and evaluate() always give.
    StressResultants(const MindlinPlate                    &plate,
                     const Mapping<2>                      &mapping,
                     const TransverseShearStrain::Treatment treatment,
                     const LA::MPI::Vector                 &solution,
                     const FreeBendingField                &free_bending = {},
                     const bool face_fields = false);

    /// Field name -> what it is, for its unit and scale.
    static const std::map<std::string, PhysicalUnits::Quantity> &
    quantities();
    /// Which face a positive moment puts in tension, for the files.
    static const std::string sign_convention;

    std::vector<std::string>
    get_names() const override;
    UpdateFlags
    get_needed_update_flags() const override;
    void
    evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &inputs,
                          std::vector<Vector<double>> &computed) const override;

    /// Every field at the point p of the plate (in the meshed part), by
    /// the same evaluation the output makes; empty on the ranks that do not
    /// own the cell around p.
    /// The fields, in the order of evaluate_vector_field()'s output.
    static const std::vector<std::string> &
    field_names();
    /// The position of a field in that order.
    static unsigned int
    field_index(const std::string &name);

    /// The fields at the points of `values`, reinitialised on `cell` with
    /// gradients.
    void
    evaluate(const DoFHandler<2>::cell_iterator &cell,
             const FEValues<2>                  &values,
             std::vector<Vector<double>>        &computed) const;

    std::map<std::string, double>
    at_point(const Discretization &discretization, const Point<2> &p) const;

    /// The principal moments, the shear force and the faces' largest
    /// principal stresses at the points of
    /// `fields`, reinitialised on `cell` with its dof values `dof_values`,
    /// as evaluate() gives M_1, M_2, Q_x, Q_y, sigma_1_top and
    /// sigma_1_bottom to the bit, without the other fields (the design outputs'
    /// pass over every output point). The vectors of `out` are kept by the
    /// caller from cell to cell.
    struct PrincipalValues
    {
      std::vector<double>       m_1, m_2;
      std::vector<Tensor<1, 2>> q;
      /// The largest principal stress of each face (sigma_1_top,
      /// sigma_1_bottom), computed `with_faces` only.
      std::vector<FaceStresses> faces;
      bool                      with_faces = true;
    };
    void
    principal(const DoFHandler<2>::active_cell_iterator &cell,
              const PlateFieldAtPoints                  &fields,
              const ArrayView<const double>             &dof_values,
              PrincipalValues                           &out) const;

  private:
    /// How many of the fields the output has: the moments, shear forces
    /// and bed-side stresses; `with_faces` the faces' (the base's too,
    /// where there is one).
    unsigned int
    n_fields(const bool with_faces) const;
    /// The faces' stresses of a base of its own (BaseLayer, tensionless),
    /// from its own moments and the temperature at each point (`thermal`,
    /// empty: none), into `computed` at every point; nothing
    /// without one.
    void
    add_own_base_faces(const std::vector<FreeBending>               &thermal,
                       const std::vector<std::vector<Tensor<1, 2>>> &gradient,
                       std::vector<Vector<double>> &computed) const;
    /// The same at the points of `fields`, into `out.faces`.
    void
    add_own_base_faces(const PlateFieldAtPoints       &fields,
                       const std::vector<FreeBending> &thermal,
                       PrincipalValues                &out) const;
    /// The base's faces of `faces` from the gradients of its own psi_x and
    /// psi_y, with its own section `base`, and the temperature there (the
    /// plate's FreeBending; none: nullptr).
    void
    own_base_faces(const SectionCoefficients &base,
                   const Tensor<1, 2>        &grad_psi_x,
                   const Tensor<1, 2>        &grad_psi_y,
                   const FreeBending         *temperature,
                   FaceStresses              &faces) const;

    const MindlinPlate                    &plate;
    const Mapping<2>                      &mapping;
    const TransverseShearStrain::Treatment treatment;
    const LA::MPI::Vector                 &solution;
    const FreeBendingField                 free_bending;
    const bool                             face_fields;

    /// The shear strains of the shape functions at one set of reference
    /// points, rebuilt when the points change (DataOut asks for the same
    /// points in every cell). One per thread: DataOut builds its patches
    /// in parallel.
    struct StrainsAtPoints
    {
      std::vector<Point<2>>                  unit_points;
      std::unique_ptr<TransverseShearStrain> strains;
    };
    mutable Threads::ThreadLocalStorage<StrainsAtPoints> strains_at_points;

    /// The cell's assumed (or raw) shear strain at `unit_points`.
    /// The fields at points of `cell` given in its unit coordinates, from
    /// the solution's values and gradients there.
    void
    compute(const DoFHandler<2>::cell_iterator           &cell,
            const std::vector<Point<2>>                  &unit_points,
            const std::vector<Point<2>>                  &points,
            const std::vector<Vector<double>>            &values,
            const std::vector<std::vector<Tensor<1, 2>>> &gradients,
            std::vector<Vector<double>>                  &computed) const;

    void
    shear_strains(const DoFHandler<2>::cell_iterator &cell,
                  const std::vector<Point<2>>        &unit_points,
                  const ArrayView<const double>      &dof_values,
                  std::vector<Tensor<1, 2>>          &gamma) const;
  };
} // namespace liftoff
