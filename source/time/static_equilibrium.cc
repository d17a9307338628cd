#include <deal.II/base/function_parser.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/contact/bed.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/time/static_equilibrium.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace liftoff
{
  namespace
  {
    /// The rigid motion r given as "w; psi_x; psi_y" at the unknowns, laid
    /// out as `like`; x_c and y_c in `motion` are the coordinates of
    /// `centre`.
    LA::MPI::Vector
    rigid_motion(const Discretization  &disc,
                 const LA::MPI::Vector &like,
                 const std::string     &motion,
                 const Point<2>        &centre)
    {
      FunctionParser<2> rigid(3);
      rigid.initialize("x,y", motion, {{"x_c", centre[0]}, {"y_c", centre[1]}});
      LA::MPI::Vector r(like);
      VectorTools::interpolate(disc.mapping(), disc.dof_handler, rigid, r);
      return r;
    }

    /// |A| |u| row by row, laid out as `like` (`u` ghosted). Epetra's view
    /// of each row: deal.II's row iterators copy the row at each begin()
    /// and end() (the 96 x 96 Q2 quarter of westergaard_stress: 13.7 s with
    /// them, 4.0 s with the view, 5.7 s without the check).
    LA::MPI::Vector
    absolute_product(const LA::MPI::SparseMatrix &a,
                     const LA::MPI::Vector       &u,
                     const LA::MPI::Vector       &like)
    {
      const Epetra_CrsMatrix &matrix = a.trilinos_matrix();
      LA::MPI::Vector         result(like);
      result = 0;
      for (int row = 0; row < matrix.NumMyRows(); ++row)
        {
          int     n       = 0;
          double *values  = nullptr;
          int    *columns = nullptr;
          matrix.ExtractMyRowView(row, n, values, columns);
          double sum = 0;
          for (int k = 0; k < n; ++k)
            sum += std::abs(values[k])
                   * std::abs(u(TrilinosWrappers::global_index(matrix.ColMap(),
                                                               columns[k])));
          result(TrilinosWrappers::global_index(matrix.RowMap(), row)) = sum;
        }
      result.compress(VectorOperation::insert);
      return result;
    }

    /// (sum (a_i b_i)^2)^(1/2) over all ranks.
    double
    weighted_norm(const LA::MPI::Vector &a,
                  const LA::MPI::Vector &b,
                  const MPI_Comm         comm)
    {
      double sum = 0;
      for (auto x = a.begin(), y = b.begin(); x != a.end(); ++x, ++y)
        sum += (*x) * (*x) * (*y) * (*y);
      return std::sqrt(Utilities::MPI::sum(sum, comm));
    }
  } // namespace


  double
  StaticEquilibrium::Result::accepted() const
  {
    return std::max(tolerance, round_off);
  }


  bool
  StaticEquilibrium::Result::holds() const
  {
    return imbalance <= accepted();
  }


  StaticEquilibrium::Result
  StaticEquilibrium::check(const Discretization        &disc,
                           const Bed                   &foundation,
                           const LA::MPI::Vector       &u,
                           const LA::MPI::Vector       &load,
                           const LA::MPI::SparseMatrix &matrix)
  {
    const double copies = disc.geometry().n_symmetry_copies();
    const double scale  = copies * load.l1_norm();
    Result       result;
    if (disc.geometry().has_kinematic_support()
        || foundation.law().model() == ContactLaw::Model::none || scale == 0)
      return result;
    LA::MPI::Vector at_rest(u);
    at_rest                    = 0;
    const auto            bed  = foundation.diagnostics().resultant(u, at_rest);
    const LA::MPI::Vector size = absolute_product(matrix, u, load);
    // Moments about the plate's middle: about the origin, those of a plate
    // far from it (site coordinates) would be the force times a large arm,
    // and their difference round-off of that.
    const auto     box = disc.geometry().plate_box().get_boundary_points();
    const Point<2> middle((box.first[0] + box.second[0]) / 2,
                          (box.first[1] + box.second[1]) / 2);
    const auto compare = [&](const std::string &motion, const double bed_side) {
      const LA::MPI::Vector r = rigid_motion(disc, load, motion, middle);
      result.imbalance =
        std::max(result.imbalance, std::abs(copies * (load * r) - bed_side));
      result.round_off =
        std::max(result.round_off,
                 16 * std::numeric_limits<double>::epsilon() * copies
                   * weighted_norm(size, r, disc.mpi_communicator));
    };
    compare("1; 0; 0", bed.force);
    const auto &symmetric = disc.geometry().symmetry_axes();
    if (!foundation.law().has_layer())
      for (const unsigned int axis : {0u, 1u})
        if (std::find(symmetric.begin(), symmetric.end(), axis)
            == symmetric.end())
          compare(axis == 0 ? "x - x_c; 1; 0" : "y - y_c; 0; 1",
                  bed.force * (bed.centre[axis] - middle[axis]));
    result.imbalance /= scale;
    result.round_off /= scale;
    return result;
  }
} // namespace liftoff
