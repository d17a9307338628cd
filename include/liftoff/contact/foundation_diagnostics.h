#pragma once

#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/linear_algebra.h>
#include <liftoff/contact/contact_law.h>
#include <liftoff/contact/foundation_points.h>

#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * What the foundation's state says about the bed, for the history, the
   * fields, the energy balance and the checks: its resultant, the pressure
   * range, the contact area and how firmly it holds the plate, the springs'
   * energy and the gap's work. Reads the points, the law and the contact
   * status it is given; changes nothing.
   */
  class FoundationDiagnostics
  {
  public:
    FoundationDiagnostics(const FoundationPoints           &points,
                          const ContactLaw                 &law,
                          const std::vector<unsigned char> &status);

    /// The pressure Gamma (w - g) + c v at the Gauss points: its smallest
    /// value at a point in contact, its largest at a point out of contact,
    /// and its largest magnitude (collective; for tests).
    struct PressureRange
    {
      double smallest_in_contact    = 0;
      double largest_out_of_contact = 0;
      double largest_magnitude      = 0;
    };
    PressureRange
    pressure_range(const LA::MPI::Vector &ghosted_solution,
                   const LA::MPI::Vector &ghosted_velocity) const;

    /// Gamma int_S g (g - w): with a gap, Clapeyron's theorem for an
    /// equilibrium K u + K_f(S) u - f_g(S) = F reads
    /// E = 1/2 (F.u + gap_work(u)), the springs' energy being
    /// 1/2 Gamma int_S (w - g)^2. 0 without a gap.
    double
    gap_work(const LA::MPI::Vector &ghosted_solution) const;

    /// Energy stored in the springs, 1/2 Gamma int max(w - g, 0)^2 (or
    /// (w - g)^2 when bilateral), and in the shear layer,
    /// 1/2 G_p int_S |grad w|^2, on the meshed part.
    double
    energy(const LA::MPI::Vector &ghosted_solution) const;

    /// The bed's normal reaction on the full plate: the force of the
    /// springs and dashpots int_S (Gamma (w - g) + c v) over the points in
    /// contact, its centre (the point about which it has no moment), and
    /// the area in contact; a symmetric part's values times its copies, the
    /// centre on the symmetry planes. The shear layer adds no force (its
    /// G_p int_S grad w . grad 1 vanishes) and is left out. Without a
    /// force the centre is (0, 0). `ghosted_velocity` is read only with
    /// dashpots (collective).
    struct Resultant
    {
      double   force = 0;
      Point<2> centre;
      double   contact_area = 0;
      /// The largest bearing pressure at a Gauss point in contact (0 with
      /// none) and that point, in the meshed part (the same on every rank;
      /// of equal pressures, the point of smallest x, then y).
      double   largest_pressure = 0;
      Point<2> largest_pressure_at;
    };
    Resultant
    resultant(const LA::MPI::Vector &ghosted_solution,
              const LA::MPI::Vector &ghosted_velocity) const;

    /// Area in contact over the area of the meshed part.
    double
    contact_area_fraction() const;

    /// How firmly the springs in contact hold the rigid-body motions that
    /// nothing else holds on a plate with free edges (w = 1, and w = x,
    /// w = y unless x = 0 or y = 0 is a symmetry plane): the smallest
    /// eigenvalue of the contact set's moment matrix int_S r_i r_j over
    /// that of the whole meshed part (the modes taken about its centroid),
    /// in [0, 1]. Zero exactly when the set
    /// is empty or lies on a line, i.e. when K + K_f(S) is singular for a
    /// free plate (collective).
    double
    rigid_body_restraint() const;

    /// Fraction of each locally owned cell's Gauss points in contact,
    /// indexed by active cell index, for output and mesh refinement.
    Vector<float>
    contact_fraction_per_cell() const;

  private:
    const FoundationPoints           &points;
    const ContactLaw                 &law;
    const std::vector<unsigned char> &in_contact;

    /// The centroid of the meshed part, by its Gauss points (collective).
    Point<2>
    centroid() const;
    /// 1/2 G_p int_S |grad w_h|^2 over this rank's cells.
    double
    layer_energy(const LA::MPI::Vector &ghosted_solution) const;
  };
} // namespace liftoff
