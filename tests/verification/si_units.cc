// Scenes in SI units (issue 37), against references that do not use
// liftoff's converter:
// - the concrete slab (5 m x 5 m x 0.25 m, E = 30 GPa, nu = 0.2,
//   rho = 2400 kg/m^3, k = 50 MPa/m, a 50 kN wheel) written in SI and its
//   dimensionless twin converted here by hand from doc/model.md's groups
//   (with another force scale, F0 = the wheel's load): the SI run's
//   history.csv equals the twin's rows times F0 L^2 / D and t0, static
//   and dynamic (a pulse, a pressure patch with a position-dependent
//   intensity, the self-weight);
// - a free slab under its self-weight alone settles by rho g H / k;
// - Westergaard's interior deflection P / (8 k l^2), l = (D / k)^(1/4),
//   of a point load on a thin slab 12.6 l wide on a bilateral bed, and
//   the Mindlin plate's shear deflection under the point on the issue's
//   slab, which grows by P ln 2 / (2 pi chi G H) as h halves;
// - the rigid-body bounce of a free slab on a bilateral bed at
//   sqrt(k / (rho H)) / (2 pi) Hz, from the zero crossings of t [s] and
//   w [m] in history.csv.

#include <deal.II/base/utilities.h>

#include <test_tools.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>

using namespace liftoff_tests;

namespace
{
  // The slab.
  constexpr double E = 30e9, nu = 0.2, rho = 2400, k = 50e6, g = 9.81;
  constexpr double P = 50e3; // the wheel [N]

  double
  bending_stiffness(const double H)
  {
    return E * H * H * H / (12 * (1 - nu * nu));
  }

  std::string
  si_slab(const double L, const double H, const double gravity)
  {
    return set("Units/System", "SI") + set("Units/Length", L)
           + set("Units/Thickness", H) + set("Units/Young's modulus", E)
           + set("Units/Density", rho) + set("Units/Subgrade modulus", k)
           + set("Units/Gravity", gravity) + set("Plate/Poisson ratio", nu);
  }

  // history.csv of a run into `folder`, by column name.
  std::map<std::string, std::vector<double>>
  read_history(const std::string &folder)
  {
    std::ifstream                              in(folder + "/history.csv");
    std::string                                line;
    std::map<std::string, std::vector<double>> columns;
    std::getline(in, line);
    const auto names = Utilities::split_string_list(line, ',');
    while (std::getline(in, line))
      {
        const auto values = Utilities::split_string_list(line, ',');
        for (unsigned int c = 0; c < names.size(); ++c)
          columns[names[c]].push_back(std::stod(values[c]));
      }
    return columns;
  }

  // Runs `scene` with its history in `folder` (replaced if there) and
  // returns the history's columns.
  std::map<std::string, std::vector<double>>
  run_into(const std::string &folder, const std::string &scene)
  {
    run_scene(scene + set("Output/Directory", folder),
              nullptr,
              MPI_COMM_WORLD,
              liftoff::Simulator::Start::overwrite);
    return read_history(folder);
  }

  // Largest difference of the SI history's column `si_name` from the
  // twin's rows times `scale`, relative to the largest of them.
  double
  difference(const std::vector<double>                                &si,
             const std::vector<liftoff::HistoryRow>                   &rows,
             const std::function<double(const liftoff::HistoryRow &)> &twin,
             const double                                              scale)
  {
    AssertThrow(si.size() == rows.size(),
                ExcMessage("The runs have different numbers of rows."));
    double largest = 0, size = 0;
    for (unsigned int n = 0; n < rows.size(); ++n)
      {
        largest = std::max(largest, std::abs(si[n] - scale * twin(rows[n])));
        size    = std::max(size, std::abs(scale * twin(rows[n])));
      }
    return largest / size;
  }

  /// (a) The slab in SI against its twin converted by hand.
  void
  check_twin(Checks &checks, const std::string &analysis)
  {
    const double      L = 5, H = 0.25, D = bending_stiffness(H);
    const double      t0 = L * L * std::sqrt(rho * H / D);
    const double      F0 = P; // not the converter's D / L
    const double      dt = 2e-4, end = 40 * dt;
    const std::string shared =
      set("Analysis/Type", analysis) + set("Discretization/Cells along x", 8)
      + set("Discretization/Cells along y", 8)
      + set("Discretization/Polynomial degree", 2)
      + set("Output/Write foundation resultant", "true")
      + set("Output/Write moment extremes", "true");
    const std::string si =
      shared + si_slab(L, H, g) + set("Loads/Point load 1/Magnitude", P)
      + set("Loads/Point load 1/Position", "1, 0.5")
      + set("Loads/Point load 1/Time history", "if(t < 0.00305, 1, 0)")
      + set("Loads/Pressure 1/Magnitude", 2e5)
      + set("Loads/Pressure 1/Region", "-2, -1, -2, -0.5")
      + set("Loads/Pressure 1/Intensity", "1 + 0.2 * x - 0.1 * y")
      + set("Output/Probe points", "0, 0; 1, 0.5; 2.5, 2.5; -1.5, -1")
      + set("Output/Probe quantities", "M_xx(1; 0.5), Q_y(-1.5; -1)")
      + set("Time integration/Time step", dt)
      + set("Time integration/End time", end);
    std::ostringstream x_m, y_m, history;
    x_m << std::setprecision(17) << L << " * x";
    y_m << std::setprecision(17) << L << " * y";
    history << std::setprecision(17) << "if(" << t0
            << " * tau < 0.00305, 1, 0)";
    const std::string twin =
      shared + set("Plate/Aspect ratio", 1)
      + set("Plate/Thickness ratio", H / L) + set("Plate/Poisson ratio", nu)
      + set("Foundation/Stiffness", k * std::pow(L, 4) / D)
      + set("Loads/Self weight", rho * g * H * L * L / F0)
      + set("Loads/Point load 1/Magnitude", P / F0)
      + set("Loads/Point load 1/Position", "0.2, 0.1")
      + set("Loads/Point load 1/Time history", history.str())
      + set("Loads/Pressure 1/Magnitude", 2e5 * L * L / F0)
      + set("Loads/Pressure 1/Region", "-0.4, -0.2, -0.4, -0.1")
      + set("Loads/Pressure 1/Intensity",
            "1 + 0.2 * " + x_m.str() + " - 0.1 * " + y_m.str())
      + set("Output/Probe points", "0, 0; 0.2, 0.1; 0.5, 0.5; -0.3, -0.2")
      + set("Output/Probe quantities", "M_xx(0.2; 0.1), Q_y(-0.3; -0.2)")
      + set("Time integration/Time step", dt / t0)
      + set("Time integration/End time", end / t0);

    auto         columns = run_into("si_units_" + analysis, si);
    const auto   solver  = run_scene(twin);
    const auto  &rows    = solver->history();
    const double w_unit  = F0 * L * L / D;
    using Row            = liftoff::HistoryRow;
    const std::vector<std::pair<std::string, unsigned int>> probes = {
      {"w(0;0) [m]", 0},
      {"w(1;0.5) [m]", 1},
      {"w(2.5;2.5) [m]", 2},
      {"w(-1.5;-1) [m]", 3}};
    double w_error = 0;
    for (const auto &[name, k] : probes)
      w_error = std::max(w_error,
                         difference(
                           columns[name],
                           rows,
                           [k = k](const Row &r) { return r.probes("w")[k]; },
                           w_unit));
    checks.less(analysis + ": w [m] of the SI run vs the twin's v F0 L^2 / D",
                w_error,
                1e-9);
    using Value = std::function<double(const Row &)>;
    for (const auto &[column, twin_value, scale, unit] :
         std::vector<std::tuple<std::string, Value, double, std::string>>{
           {"max_uplift [m]",
            [](const Row &r) { return r["max_uplift"]; },
            w_unit,
            "F0 L^2 / D"},
           {"resultant [N]",
            [](const Row &r) { return r["resultant"]; },
            F0,
            "F0"},
           {"max_pressure [Pa]",
            [](const Row &r) { return r["max_pressure"]; },
            F0 / (L * L),
            "F0 / L^2"},
           {"work [J]",
            [](const Row &r) { return r.energies().work; },
            F0 * w_unit,
            "F0^2 L^2 / D"},
           {"M_xx(1;0.5) [N m/m]",
            [](const Row &r) { return r["M_xx(0.2;0.1)"]; },
            F0,
            "F0"},
           {"Q_y(-1.5;-1) [N/m]",
            [](const Row &r) { return r["Q_y(-0.3;-0.2)"]; },
            F0 / L,
            "F0 / L"},
           {"max_M_1 [N m/m]",
            [](const Row &r) { return r["max_M_1"]; },
            F0,
            "F0"}})
      checks.less(analysis + ": " + column + " vs the twin's times " + unit,
                  difference(columns[column], rows, twin_value, scale),
                  1e-9);
    if (analysis == "dynamic")
      checks.less(
        "dynamic: t [s] vs the twin's tau t0",
        difference(
          columns["t [s]"], rows, [](const Row &r) { return r["tau"]; }, t0),
        1e-12);
  }


  /// (b) A free slab on a tensionless bed under its weight alone.
  void
  check_settlement(Checks &checks)
  {
    const double H = 0.25;
    auto         columns =
      run_into("si_units_settlement",
               si_slab(5, H, g) + set("Discretization/Cells along x", 4)
                 + set("Discretization/Cells along y", 4)
                 + set("Output/Probe points", "0, 0; 2.5, 2.5; -1, 2")
                 + set("Time integration/Time step", 1e-3)
                 + set("Time integration/End time", 5e-3));
    const double settlement = rho * g * H / k;
    double       error      = 0;
    for (const std::string name :
         {"w(0;0) [m]", "w(2.5;2.5) [m]", "w(-1;2) [m]"})
      for (const double w : columns[name])
        error = std::max(error, std::abs(w / settlement - 1));
    std::cout << "settlement rho g H / k = " << settlement << " m" << std::endl;
    checks.less("free slab under its weight: w / (rho g H / k) - 1 at every "
                "probe and step",
                error,
                1e-9);
  }


  // w(0;0) [m] of a static point load P at the centre of a square slab of
  // side L and thickness H (Young's modulus E, nu) on a bilateral bed of
  // modulus `bed`, quarter model, Q2, `cells` along each side.
  double
  centre_deflection(const double       L,
                    const double       H,
                    const double       bed,
                    const unsigned int cells)
  {
    auto columns =
      run_into("si_units_westergaard",
               si_slab(L, H, 0) + set("Units/Subgrade modulus", bed)
                 + set("Analysis/Type", "static")
                 + set("Foundation/Model", "bilateral")
                 + set("Discretization/Symmetry", "quarter")
                 + set("Discretization/Cells along x", cells)
                 + set("Discretization/Cells along y", cells)
                 + set("Discretization/Polynomial degree", 2)
                 + set("Loads/Point load 1/Magnitude", P));
    return columns["w(0;0) [m]"].back();
  }


  /// (c) Westergaard's interior point load on large slabs, bilateral bed.
  /// Westergaard's w = P / (8 k l^2) is Kirchhoff's; a Mindlin plate adds
  /// the shear's deflection under the point, which grows like
  /// P / (2 pi chi G H) ln(1 / h) as the mesh is refined. So: a thin slab
  /// (2 cm, k = 5 MPa/m), whose shear term is 0.2 % of w per unit of ln h,
  /// against Westergaard; and the slab, 2.2 % per unit, where the
  /// growth of w from one mesh to the one of half the cell size is that
  /// term's P ln 2 / (2 pi chi G H).
  void
  check_westergaard(Checks &checks)
  {
    const double thin = 0.02, soft = 5e6;
    const double l           = std::pow(bending_stiffness(thin) / soft, 0.25);
    const double westergaard = P / (8 * soft * l * l);
    const double w           = centre_deflection(12.6 * l, thin, soft, 48);
    std::cout << std::setprecision(6) << "Westergaard: l = " << l
              << " m, L = 12.6 l, P / (8 k l^2) = " << westergaard
              << " m, liftoff " << w << " m" << std::endl;
    checks.within("thin slab: w(0;0) / (P / (8 k l^2))",
                  w / westergaard,
                  1.0,
                  1.02);

    const double H = 0.25, chi = 5.0 / 6, G = E / (2 * (1 + nu));
    const double shear_growth = P * std::log(2.0) / (2 * M_PI * chi * G * H);
    const double growth =
      centre_deflection(12, H, k, 48) - centre_deflection(12, H, k, 24);
    std::cout << "the issue's slab: w(0;0) grows by " << growth
              << " m from 24 to 48 cells; P ln 2 / (2 pi chi G H) = "
              << shear_growth << " m" << std::endl;
    checks.within("the issue's slab: growth of w(0;0) / (P ln 2 / (2 pi chi "
                  "G H))",
                  growth / shear_growth,
                  0.97,
                  1.03);
  }


  /// (d) The rigid-body bounce of a free slab on a bilateral bed.
  void
  check_bounce(Checks &checks)
  {
    const double H = 0.25, frequency = std::sqrt(k / (rho * H)) / (2 * M_PI);
    const double dt = 1 / frequency / 200;
    auto         columns =
      run_into("si_units_bounce",
               si_slab(5, H, 0) + set("Foundation/Model", "bilateral")
                 + set("Discretization/Symmetry", "quarter")
                 + set("Discretization/Cells along x", 2)
                 + set("Discretization/Cells along y", 2)
                 + set("Initial conditions/Velocity", "0.01; 0; 0")
                 + set("Time integration/Time step", dt)
                 + set("Time integration/End time", 500 * dt));
    // Upward zero crossings of w, linearly interpolated.
    const auto         &t = columns["t [s]"], &w = columns["w(0;0) [m]"];
    std::vector<double> crossings;
    for (unsigned int n = 1; n < w.size(); ++n)
      if (w[n - 1] < 0 && w[n] >= 0)
        crossings.push_back(t[n - 1]
                            + (t[n] - t[n - 1]) * w[n - 1] / (w[n - 1] - w[n]));
    AssertThrow(crossings.size() >= 2, ExcMessage("No two periods."));
    const double measured =
      (crossings.size() - 1) / (crossings.back() - crossings.front());
    std::cout << std::setprecision(8)
              << "bounce: sqrt(k / (rho H)) / (2 pi) = " << frequency
              << " Hz, history " << measured << " Hz" << std::endl;
    // Average acceleration lengthens the period by (omega dt)^2 / 12 =
    // 8e-5 at 200 steps per period.
    checks.less("bounce frequency [Hz] / sqrt(k / (rho H)) / (2 pi) - 1",
                std::abs(measured / frequency - 1),
                2e-4);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  Checks checks(argc, argv, 1);
  check_twin(checks, "static");
  check_twin(checks, "dynamic");
  check_settlement(checks);
  check_westergaard(checks);
  check_bounce(checks);
  return checks.exit_code();
}
