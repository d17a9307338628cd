// The foundation term (springs, then springs and a Pasternak shear layer)
// is kept in the system matrix by updates that add or
// remove only the Gauss points whose contact status flipped. A second
// method, a fresh assembly of K_f for the final status, must give the same
// matrix; and K_f u from the matrix must equal the springs' reaction that
// the foundation computes point by point. Runs on two ranks so that cells
// on the partition boundary add to rows another rank owns. Edges are
// clamped and simply supported so that constrained rows are present. With
// dashpots, the stiffness Gamma + c kappa of the matrices against a bed of
// springs alone of that stiffness (check_velocity_factor()).

#include <deal.II/base/function_lib.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/numerics/vector_tools.h>

#include <liftoff/contact/tensionless_winkler_foundation.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>

#include "test_tools.h"

#include <cmath>
#include <numeric>
#include <sstream>

using namespace dealii;

namespace
{
  // A deflection whose sign pattern changes with `phase`, so successive
  // status updates flip different sets of points.
  class WavyDeflection : public Function<2>
  {
  public:
    explicit WavyDeflection(const double phase)
        : Function<2>(3)
        , phase(phase)
    {}

    double
    value(const Point<2> &p, const unsigned int component) const override
    {
      if (component != 0)
        return 0.0;
      return std::sin(7.0 * p[0] + phase) * std::cos(5.0 * p[1] - 2 * phase)
             + 0.3 * std::sin(11.0 * p[0] * p[1] + 3 * phase);
    }

  private:
    double phase;
  };


  double
  matrix_difference(const liftoff::LA::MPI::SparseMatrix &a,
                    const liftoff::LA::MPI::SparseMatrix &b)
  {
    liftoff::LA::MPI::SparseMatrix difference;
    difference.copy_from(a);
    difference.add(-1.0, b);
    return difference.frobenius_norm() / b.frobenius_norm();
  }
} // namespace


namespace
{
  void
  check_updates(const double shear_modulus, liftoff_tests::Checks &checks)
  {
    const std::string label = (shear_modulus > 0 ? "with a shear layer: " : "");
    ParameterHandler  prm;
    liftoff::MindlinPlate::declare_parameters(prm);
    liftoff::Discretization::declare_parameters(prm);
    liftoff::TensionlessWinklerFoundation::declare_parameters(prm);
    std::istringstream scene("subsection Discretization\n"
                             "  set Symmetry = full\n"
                             "  set Cells along x = 12\n"
                             "  set Cells along y = 10\n"
                             "  set Polynomial degree = 2\n"
                             "end\n"
                             "subsection Boundary conditions\n"
                             "  set Left = clamped\n"
                             "  set Bottom = hard simply supported\n"
                             "end\n"
                             "subsection Foundation\n"
                             "  set Stiffness = 37\n"
                             "  set Shear modulus = "
                             + std::to_string(shear_modulus)
                             + "\n"
                               "end\n");
    prm.parse_input(scene, "test scene");

    liftoff::MindlinPlate plate;
    plate.parse_parameters(prm);
    liftoff::Discretization discretization(MPI_COMM_WORLD);
    discretization.parse_parameters(prm, plate);
    discretization.setup();
    liftoff::TensionlessWinklerFoundation foundation;
    foundation.parse_parameters(prm);
    foundation.setup(discretization);

    liftoff::LA::MPI::SparseMatrix updated, fresh;
    discretization.reinit_matrix(updated);
    discretization.reinit_matrix(fresh);
    foundation.add_to_matrix({}, updated); // all points in contact

    liftoff::LA::MPI::Vector u, ghosted_u;
    discretization.reinit_vector(u);
    discretization.reinit_ghosted_vector(ghosted_u);

    unsigned long              n_flipped = 0;
    std::vector<unsigned char> reference;
    for (unsigned int round = 0; round < 5; ++round)
      {
        if (round == 2)
          reference = foundation.status_in_matrix();
        VectorTools::interpolate(discretization.mapping(),
                                 discretization.dof_handler,
                                 WavyDeflection(0.9 * round),
                                 u);
        discretization.constraints.distribute(u);
        ghosted_u = u;
        n_flipped += foundation.update_status(ghosted_u);
        // Update only every other round, so some points flip twice between
        // two updates.
        if (round % 2 == 1)
          foundation.update_matrix(0.0, updated);
      }
    foundation.update_matrix(0.0, updated);
    checks.within(label + "status changes seen", double(n_flipped), 100, 1e9);
    checks.within(label + "contact fraction is partial",
                  foundation.diagnostics().contact_area_fraction(),
                  0.1,
                  0.9);

    foundation.add_to_matrix({}, fresh);
    checks.less(
      label + "updated vs freshly assembled K_f (relative Frobenius norm)",
      matrix_difference(updated, fresh),
      1e-14);

    // The change since `reference` as a product (what CG uses instead of
    // a product with the matrix), against the difference of the two
    // assembled matrices, for a vector with every component and ghosts.
    {
      liftoff::LA::MPI::SparseMatrix earlier;
      discretization.reinit_matrix(earlier);
      foundation.add_to_matrix(reference, 0.0, earlier);
      liftoff::LA::MPI::Vector x(u), from_matrices(u), change(u);
      liftoff::LA::MPI::Vector ghosted_x(ghosted_u);
      VectorTools::interpolate(discretization.mapping(),
                               discretization.dof_handler,
                               Functions::CosineFunction<2>(3),
                               x);
      discretization.constraints.distribute(x);
      ghosted_x = x;
      fresh.vmult(from_matrices, x);
      liftoff::LA::MPI::Vector earlier_x(u);
      earlier.vmult(earlier_x, x);
      from_matrices -= earlier_x;
      change = 0;
      foundation.add_change_product(reference, 0.0, ghosted_x, change);
      checks.within(
        label + "points whose status differs from the reference",
        double(Utilities::MPI::sum(
          std::inner_product(reference.begin(),
                             reference.end(),
                             foundation.status_in_matrix().begin(),
                             0u,
                             std::plus<>(),
                             [](const unsigned char a, const unsigned char b) {
                               return static_cast<unsigned int>(a != b);
                             }),
          MPI_COMM_WORLD)),
        10,
        1e9);
      change -= from_matrices;
      checks.less(label
                    + "product with the change since a reference status vs "
                      "difference of the matrices (relative)",
                  change.l2_norm() / from_matrices.l2_norm(),
                  1e-13);
    }

    liftoff::LA::MPI::Vector from_matrix(u), reaction(u), scratch(u);
    fresh.vmult(from_matrix, u);
    reaction = 0;
    foundation.add_force({u, ghosted_u, scratch}, reaction);
    from_matrix -= reaction;
    checks.less(label + "K_f u vs point-wise reaction (relative)",
                from_matrix.l2_norm() / reaction.l2_norm(),
                1e-13);
  }


  // With dashpots c, a system matrix holds the springs' stiffness
  // Gamma + c kappa, kappa the velocity factor that every matrix call
  // takes as its argument: the matrix assembled, kept up to date through
  // status changes, and its change product. The foundation is set up
  // again in between, as after a new mesh: when kappa was a setting of
  // the foundation, that setup reset it to 0, and a damped adaptive run
  // solved with Gamma alone (issue 31). Against a second method: the
  // same statuses on a bed without dashpots whose Stiffness is
  // Gamma + c kappa.
  void
  check_velocity_factor(liftoff_tests::Checks &checks)
  {
    const double     gamma = 37, c = 3, kappa = 5;
    ParameterHandler prm;
    liftoff::MindlinPlate::declare_parameters(prm);
    liftoff::Discretization::declare_parameters(prm);
    liftoff::TensionlessWinklerFoundation::declare_parameters(prm);
    using liftoff_tests::set;
    std::istringstream scene(set("Discretization/Symmetry", "full")
                             + set("Discretization/Cells along x", 12)
                             + set("Discretization/Cells along y", 10)
                             + set("Discretization/Polynomial degree", 2)
                             + set("Boundary conditions/Left", "clamped")
                             + set("Foundation/Stiffness", gamma)
                             + set("Foundation/Damping", c));
    prm.parse_input(scene, "test scene");
    liftoff::MindlinPlate plate;
    plate.parse_parameters(prm);
    liftoff::Discretization discretization(MPI_COMM_WORLD);
    discretization.parse_parameters(prm, plate);
    discretization.setup();
    liftoff::TensionlessWinklerFoundation damped, reference;
    damped.parse_parameters(prm);
    std::istringstream springs_only(
      set("Foundation/Stiffness", gamma + c * kappa)
      + set("Foundation/Damping", 0));
    prm.parse_input(springs_only, "springs only");
    reference.parse_parameters(prm);
    reference.setup(discretization);

    liftoff::LA::MPI::SparseMatrix held, fresh;
    discretization.reinit_matrix(held);
    discretization.reinit_matrix(fresh);
    damped.setup(discretization);
    damped.add_to_matrix({0.0, kappa}, held); // all points in contact
    damped.setup(discretization);             // the same mesh again
    const std::vector<unsigned char> all_in = damped.status();

    liftoff::LA::MPI::Vector u, ghosted_u;
    discretization.reinit_vector(u);
    discretization.reinit_ghosted_vector(ghosted_u);
    VectorTools::interpolate(discretization.mapping(),
                             discretization.dof_handler,
                             WavyDeflection(0.9),
                             u);
    discretization.constraints.distribute(u);
    ghosted_u = u;
    damped.update_status(ghosted_u);
    checks.within("dashpots: points updated",
                  double(damped.update_matrix(kappa, held)),
                  100,
                  1e9);
    reference.set_status(damped.status());
    reference.add_to_matrix({}, fresh);
    checks.less("dashpots: matrix held with kappa vs springs Gamma + c kappa "
                "(relative Frobenius norm)",
                matrix_difference(held, fresh),
                1e-14);

    liftoff::LA::MPI::Vector product(u), expected(u);
    product  = 0;
    expected = 0;
    damped.add_change_product(all_in, kappa, ghosted_u, product);
    reference.add_change_product(all_in, 0.0, ghosted_u, expected);
    product -= expected;
    checks.less("dashpots: change product with kappa vs springs Gamma + c "
                "kappa (relative)",
                product.l2_norm() / expected.l2_norm(),
                1e-14);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv, 2);
  // Without a layer, and with one: its gradient terms go the same way.
  for (const double shear_modulus : {0.0, 3.0})
    check_updates(shear_modulus, checks);
  check_velocity_factor(checks);
  return checks.exit_code();
}
