// Foundation/Shear modulus G_p: a Pasternak shear layer on the springs,
// 1/2 G_p |grad w|^2 over the contact region. Checks, each against
// something the layer code does not compute itself:
//  - bilateral, static: a hard simply supported square Mindlin plate under
//    the load q0 sin(pi X) sin(pi Y) deflects in that one mode with the
//    amplitude of Navier's solution with the bed's terms (navier_plate.h);
//    the error falls under refinement, on uniform meshes and on an
//    adaptive one (hanging nodes);
//  - bilateral, dynamic: a linear system, whose energy (the layer's
//    included) the average acceleration rule conserves to round-off;
//  - tensionless, static, with lift-off: Clapeyron's identity
//    strain + foundation energy = 1/2 F.u, which holds only if the layer's
//    energy is taken over the same contact set as its stiffness;
//  - G_p = 0 given explicitly: the same numbers as a scene without the
//    parameter (bit for bit).

#include "energy_checks.h"
#include "navier_plate.h"
#include "test_tools.h"

#include <cmath>

namespace
{
  using liftoff_tests::set;
  constexpr double thickness_ratio = 0.1, gamma_f = 50, shear_modulus = 10;

  std::string
  sinusoidal_scene(const unsigned int cells_full)
  {
    return set("Analysis/Type", "static")
           + liftoff_tests::square_plate(thickness_ratio,
                                         navier::poisson_ratio,
                                         navier::shear_correction)
           + liftoff_tests::all_edges("hard simply supported")
           + set("Foundation/Model", "bilateral")
           + set("Foundation/Stiffness", gamma_f)
           + set("Foundation/Shear modulus", shear_modulus)
           + set("Discretization/Symmetry", "quarter")
           + set("Discretization/Cells along x", cells_full / 2)
           + set("Discretization/Cells along y", cells_full / 2)
           + set("Discretization/Polynomial degree", 2)
           + set("Loads/Pressure 1/Magnitude", 1)
           + set("Loads/Pressure 1/Intensity", "cos(pi*x)*cos(pi*y)");
  }

  double
  relative_error(const liftoff::Simulator &run, const double reference)
  {
    return std::abs(run.deflection_at(dealii::Point<2>(0, 0)) - reference)
           / reference;
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  // Navier's mode on a Pasternak bed, under refinement.
  const double reference =
    navier::pasternak_mode_amplitude(navier::shear_stiffness(thickness_ratio),
                                     gamma_f,
                                     shear_modulus);
  {
    std::vector<double> errors;
    for (const unsigned int cells : {4u, 8u, 16u})
      {
        errors.push_back(
          relative_error(*liftoff_tests::run_scene(sinusoidal_scene(cells)),
                         reference));
        std::cout << "  " << cells << " x " << cells
                  << " cells (Q2): centre deflection vs Navier, rel. error "
                  << std::setprecision(3) << errors.back() << std::endl;
      }
    checks.less(
      "Navier mode on a Pasternak bed, 16 x 16 Q2: rel. error of w(0, "
      "0)",
      errors.back(),
      1e-5);
    checks.less("the error falls under refinement: error(16) / error(8)",
                errors[2] / errors[1],
                0.2);
    // Without the layer the same scene is far from the reference: the check
    // sees the layer.
    const double without =
      navier::pasternak_mode_amplitude(navier::shear_stiffness(thickness_ratio),
                                       gamma_f,
                                       0.0);
    checks.within("the layer matters: |W(G_p) - W(0)| / W(G_p)",
                  std::abs(without - reference) / reference,
                  0.1,
                  1e9);
    // An adaptive mesh (hanging nodes) from the coarse one: the error falls.
    const auto adaptive = liftoff_tests::run_scene(
      sinusoidal_scene(4) + set("Mesh refinement/Adaptive", "true")
      + set("Mesh refinement/Static cycles", 2)
      + set("Mesh refinement/Refine fraction", 0.3)
      + set("Mesh refinement/Coarsen fraction", 0));
    const double adaptive_error = relative_error(*adaptive, reference);
    std::cout
      << "  adaptive from 4 x 4, 2 cycles ("
      << adaptive->get_discretization().triangulation.n_global_active_cells()
      << " cells of the quarter): rel. error " << adaptive_error << std::endl;
    checks.less("adaptive mesh: error / error on its 4 x 4 start",
                adaptive_error / errors[0],
                0.5);
  }

  // Bilateral, dynamic: a conservative linear system.
  {
    const auto run = liftoff_tests::run_scene(
      liftoff_tests::small_plate_scene() + set("Foundation/Model", "bilateral")
      + set("Foundation/Stiffness", 200)
      + set("Foundation/Shear modulus", shear_modulus));
    checks.less("bilateral Pasternak, dynamic: max |energy balance error| / "
                "max work",
                liftoff_tests::relative_balance_error(*run),
                1e-10);
  }

  // Tensionless, static, lift-off under an eccentric force: Clapeyron.
  {
    const auto run = liftoff_tests::run_scene(
      set("Analysis/Type", "static") + set("Foundation/Stiffness", 10)
      + set("Foundation/Shear modulus", 0.5)
      + set("Discretization/Cells along x", 8)
      + set("Discretization/Cells along y", 8)
      + set("Discretization/Polynomial degree", 2)
      + set("Loads/Point load 1/Magnitude", 1)
      + set("Loads/Point load 1/Position", "0.4, 0.3"));
    const auto &row = run->history().back();
    checks.less("tensionless Pasternak, static: the plate lifts off (contact "
                "fraction)",
                row["contact_fraction"],
                0.95);
    checks.less("tensionless Pasternak, static: |strain + foundation energy - "
                "F.u / 2| / that",
                liftoff_tests::clapeyron_error(row),
                1e-10);
  }

  // G_p = 0 given explicitly: Winkler, bit for bit.
  {
    const std::string scene = liftoff_tests::small_plate_scene()
                              + set("Foundation/Stiffness", 200)
                              + set("Output/Probe points", "0, 0; 0.5, 0.5");
    const auto plain = liftoff_tests::run_scene(scene);
    const auto zero =
      liftoff_tests::run_scene(scene + set("Foundation/Shear modulus", 0));
    checks.less("G_p = 0 against no layer: probe histories (relative)",
                liftoff_tests::history_difference(*plain, *zero),
                1e-300);
    checks.less("G_p = 0 against no layer: energies (relative)",
                liftoff_tests::energy_difference(*plain, *zero),
                1e-300);
  }
  return checks.exit_code();
}
