#include <deal.II/base/function_parser.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/time/static_equilibrium.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace
  {
    /// loads . r for the rigid motion r given as "w; psi_x; psi_y", in
    /// which x_c and y_c are the coordinates of `centre`.
    double
    work_on(const Discretization  &disc,
            const LA::MPI::Vector &load,
            const std::string     &motion,
            const Point<2>        &centre = Point<2>())
    {
      FunctionParser<2> rigid(3);
      rigid.initialize("x,y", motion, {{"x_c", centre[0]}, {"y_c", centre[1]}});
      LA::MPI::Vector r(load);
      VectorTools::interpolate(disc.mapping(), disc.dof_handler, rigid, r);
      return load * r;
    }
  } // namespace


  double
  StaticEquilibrium::imbalance(const Discretization               &disc,
                               const TensionlessWinklerFoundation &foundation,
                               const LA::MPI::Vector              &u,
                               const LA::MPI::Vector              &load)
  {
    const double copies = disc.geometry().n_symmetry_copies();
    const double scale  = copies * load.l1_norm();
    if (disc.geometry().has_kinematic_support()
        || foundation.law().model() == ContactLaw::Model::none || scale == 0)
      return -1;
    LA::MPI::Vector at_rest(u);
    at_rest        = 0;
    const auto bed = foundation.diagnostics().resultant(u, at_rest);
    double     largest =
      std::abs(copies * work_on(disc, load, "1; 0; 0") - bed.force);
    const auto &symmetric = disc.geometry().symmetry_axes();
    // Moments about the plate's middle: about the origin, those of a plate
    // far from it (site coordinates) would be the force times a large arm,
    // and their difference round-off of that.
    const auto     box = disc.geometry().plate_box().get_boundary_points();
    const Point<2> middle((box.first[0] + box.second[0]) / 2,
                          (box.first[1] + box.second[1]) / 2);
    if (!foundation.law().has_layer())
      for (const unsigned int axis : {0u, 1u})
        if (std::find(symmetric.begin(), symmetric.end(), axis)
            == symmetric.end())
          largest =
            std::max(largest,
                     std::abs(copies
                                * work_on(disc,
                                          load,
                                          axis == 0 ? "x - x_c; 1; 0"
                                                    : "y - y_c; 0; 1",
                                          middle)
                              - bed.force * (bed.centre[axis] - middle[axis])));
    return largest / scale;
  }
} // namespace liftoff
