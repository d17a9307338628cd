#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <liftoff/base/located_maximum.h>
#include <liftoff/contact/foundation_diagnostics.h>

#include <array>
#include <cmath>
#include <limits>

namespace liftoff
{
  namespace
  {
    // The smallest eigenvalue of `a` relative to the positive definite
    // `b`: that of L^-1 a L^-T with b = L L^T (Cholesky).
    double
    smallest_relative_eigenvalue(const Tensor<2, 3> &a, const Tensor<2, 3> &b)
    {
      Tensor<2, 3> lower;
      for (unsigned int j = 0; j < 3; ++j)
        {
          double diagonal = b[j][j];
          for (unsigned int k = 0; k < j; ++k)
            diagonal -= lower[j][k] * lower[j][k];
          lower[j][j] = std::sqrt(diagonal);
          for (unsigned int i = j + 1; i < 3; ++i)
            {
              double entry = b[i][j];
              for (unsigned int k = 0; k < j; ++k)
                entry -= lower[i][k] * lower[j][k];
              lower[i][j] = entry / lower[j][j];
            }
        }
      const Tensor<2, 3> inverse = invert(lower);
      return eigenvalues(symmetrize(inverse * a * transpose(inverse)))[2];
    }
  } // namespace

  FoundationDiagnostics::FoundationDiagnostics(
    const FoundationPoints           &points,
    const ContactLaw                 &law,
    const std::vector<unsigned char> &status)
      : points(points)
      , law(law)
      , in_contact(status)
  {}


  FoundationDiagnostics::PressureRange
  FoundationDiagnostics::pressure_range(const LA::MPI::Vector &u,
                                        const LA::MPI::Vector &v) const
  {
    PressureRange       range;
    std::vector<double> w, v_at_points;
    double              smallest = std::numeric_limits<double>::max();
    double              largest  = -std::numeric_limits<double>::max();
    double              size     = 0;
    const unsigned int  n_q      = points.n_q_points();
    for (unsigned int c = 0; c < points.n_cells(); ++c)
      {
        points.values_at_points(u, c, w);
        points.values_at_points(v, c, v_at_points);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int i  = c * n_q + q;
            const double pressure = law.pressure_at(i, w[q], v_at_points[q]);
            size                  = std::max(size, std::abs(pressure));
            if (in_contact[i])
              smallest = std::min(smallest, pressure);
            else
              largest = std::max(largest, pressure);
          }
      }
    const MPI_Comm comm          = points.discretization().mpi_communicator;
    range.smallest_in_contact    = Utilities::MPI::min(smallest, comm);
    range.largest_out_of_contact = Utilities::MPI::max(largest, comm);
    range.largest_magnitude      = Utilities::MPI::max(size, comm);
    return range;
  }


  double
  FoundationDiagnostics::gap_work(const LA::MPI::Vector &u) const
  {
    if (!law.has_initial_gap())
      return 0;
    const unsigned int  n_q   = points.n_q_points();
    const double        gamma = law.stiffness();
    double              local = 0;
    std::vector<double> w;
    for (unsigned int c = 0; c < points.n_cells(); ++c)
      {
        points.values_at_points(u, c, w);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int i = c * n_q + q;
            const double       g = law.gap(i);
            local += in_contact[i] * gamma * g * (g - w[q]) * points.JxW(i);
          }
      }
    return Utilities::MPI::sum(local, points.discretization().mpi_communicator);
  }


  double
  FoundationDiagnostics::energy(const LA::MPI::Vector &u) const
  {
    double              local = 0;
    std::vector<double> w;
    const unsigned int  n_q = points.n_q_points();
    if (law.model() != ContactLaw::Model::none)
      for (unsigned int c = 0; c < points.n_cells(); ++c)
        {
          // The springs' own compression w - g: the dashpots store nothing.
          points.values_at_points(u, c, w);
          for (unsigned int q = 0; q < n_q; ++q)
            local += law.spring_energy(w[q] - law.gap(c * n_q + q))
                     * points.JxW(c * n_q + q);
        }
    if (law.has_layer())
      local += layer_energy(u);
    return Utilities::MPI::sum(local, points.discretization().mpi_communicator);
  }


  double
  FoundationDiagnostics::layer_energy(const LA::MPI::Vector &u) const
  {
    // 1/2 G_p int_S |grad w|^2, S the current status (all points when
    // bilateral): the layer acts where the springs do.
    double                    local = 0;
    std::vector<Tensor<1, 2>> gradient;
    const unsigned int        n_q = points.n_q_points();
    for (unsigned int c = 0; c < points.n_cells(); ++c)
      {
        points.gradients_at_points(u, c, gradient);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int i = c * n_q + q;
            local += 0.5 * law.layer_modulus() * in_contact[i] * gradient[q]
                     * gradient[q] * points.JxW(i);
          }
      }
    return local;
  }


  FoundationDiagnostics::Resultant
  FoundationDiagnostics::resultant(const LA::MPI::Vector &u,
                                   const LA::MPI::Vector &v) const
  {
    // Force, its moments about the axes x = 0 and y = 0, area in contact.
    std::vector<double> sums(4, 0.0), w, v_at_points;
    LocatedMaximum      largest;
    const unsigned int  n_q = points.n_q_points();
    if (law.model() != ContactLaw::Model::none)
      for (unsigned int c = 0; c < points.n_cells(); ++c)
        {
          points.values_at_points(u, c, w);
          v_at_points.assign(n_q, 0.0);
          if (law.has_damping())
            points.values_at_points(v, c, v_at_points);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const unsigned int i = c * n_q + q;
              if (!in_contact[i])
                continue;
              const double pressure = law.pressure_at(i, w[q], v_at_points[q]);
              const double force    = pressure * points.JxW(i);
              largest.consider(pressure, points.point(i));
              sums[0] += force;
              sums[1] += force * points.point(i)[0];
              sums[2] += force * points.point(i)[1];
              sums[3] += points.JxW(i);
            }
        }
    const Discretization &disc = points.discretization();
    Utilities::MPI::sum(sums, disc.mpi_communicator, sums);
    // The mirror images of a symmetric part carry the same force; their
    // moments about a symmetry plane cancel that part's.
    const double copies = disc.geometry().n_symmetry_copies();
    Resultant    r;
    r.force        = copies * sums[0];
    r.contact_area = copies * sums[3];
    if (sums[0] != 0.0)
      for (unsigned int d = 0; d < 2; ++d)
        r.centre[d] = sums[1 + d] / sums[0];
    for (const unsigned int axis : disc.geometry().symmetry_axes())
      r.centre[axis] = 0;
    largest               = largest.over_ranks(disc.mpi_communicator);
    r.largest_pressure    = largest.value;
    r.largest_pressure_at = largest.point;
    return r;
  }


  double
  FoundationDiagnostics::contact_area_fraction() const
  {
    double in_contact_area = 0, area = 0;
    for (unsigned int i = 0; i < points.n_points(); ++i)
      {
        area += points.JxW(i);
        in_contact_area += in_contact[i] * points.JxW(i);
      }
    const MPI_Comm comm = points.discretization().mpi_communicator;
    return Utilities::MPI::sum(in_contact_area, comm)
           / Utilities::MPI::sum(area, comm);
  }


  Point<2>
  FoundationDiagnostics::centroid() const
  {
    std::vector<double> sums(3, 0.0);
    for (unsigned int i = 0; i < points.n_points(); ++i)
      {
        sums[0] += points.JxW(i);
        sums[1] += points.JxW(i) * points.point(i)[0];
        sums[2] += points.JxW(i) * points.point(i)[1];
      }
    Utilities::MPI::sum(sums, points.discretization().mpi_communicator, sums);
    return Point<2>(sums[1] / sums[0], sums[2] / sums[0]);
  }


  double
  FoundationDiagnostics::rigid_body_restraint() const
  {
    // Modes r = (1, x - x_c, y - y_c) about the meshed part's centroid: about
    // the origin, a plate far from it (a mesh in site coordinates) has
    // modes 1, x and y nearly parallel, and the measure would be round-off.
    // A symmetry plane x = 0 (y = 0) fixes the rotation that w = x (w = y)
    // needs, so that mode is held already.
    std::array<bool, 3> is_free = {{true, true, true}};
    for (const unsigned int axis :
         points.discretization().geometry().symmetry_axes())
      is_free[1 + axis] = false;
    const Point<2> c = centroid();
    // Moments of the contact set and of the whole part, entry by entry.
    std::vector<double> moments(18, 0.0);
    for (unsigned int i = 0; i < points.n_points(); ++i)
      {
        const Point<2>             &p = points.point(i);
        const std::array<double, 3> r = {{1.0, p[0] - c[0], p[1] - c[1]}};
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            {
              moments[3 * a + b] += in_contact[i] * points.JxW(i) * r[a] * r[b];
              moments[9 + 3 * a + b] += points.JxW(i) * r[a] * r[b];
            }
      }
    Utilities::MPI::sum(moments,
                        points.discretization().mpi_communicator,
                        moments);
    // The contact set's moments relative to the whole part's, W^-1/2 C
    // W^-T/2 with W = L L^T, so that full contact gives the identity on
    // any outline (a part not symmetric about its centroid's axes has
    // int x y != 0); held modes enter as 1.
    Tensor<2, 3> contact, whole;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        {
          const bool free = is_free[a] && is_free[b];
          contact[a][b]   = free ? moments[3 * a + b] : (a == b ? 1.0 : 0.0);
          whole[a][b] = free ? moments[9 + 3 * a + b] : (a == b ? 1.0 : 0.0);
        }
    return smallest_relative_eigenvalue(contact, whole);
  }


  Vector<float>
  FoundationDiagnostics::contact_fraction_per_cell() const
  {
    Vector<float> fraction(
      points.discretization().triangulation.n_active_cells());
    const unsigned int n_q = points.n_q_points();
    for (unsigned int c = 0; c < points.n_cells(); ++c)
      {
        double sum = 0, area = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            area += points.JxW(c * n_q + q);
            sum += in_contact[c * n_q + q] * points.JxW(c * n_q + q);
          }
        fraction[points.active_cell_index(c)] = sum / area;
      }
    return fraction;
  }
} // namespace liftoff
