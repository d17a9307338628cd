// Output/Write foundation resultant: per step the normal reaction of the
// springs and dashpots (`resultant`), its centre (`resultant_x`,
// `resultant_y`) and the area in contact (`contact_area`), all of the full
// plate, and `max_uplift` = max (g - w)^+ on a gap. Checks against statics
// and closed forms:
//  - a free plate under its self-weight q alone sits in uniform full
//    contact: resultant = q * area, centre = centroid, contact area = plate
//    area; the same columns from a quarter model;
//  - a free plate lifting off under an eccentric force P (on a flat bed
//    and on a linear gap): static equilibrium of a free plate makes the
//    bed's resultant equal P and its centre the point of application;
//    a half model of a force on the symmetry plane gives the columns of
//    the full one;
//  - a free plate on a bilateral damped bed under a uniform pressure is
//    the oscillator w'' + c w' + Gamma w = q: the resultant is
//    area * (Gamma w_n + c v_n) with w_n, v_n of Newmark's scalar recursion
//    (the dashpots are part of it);
//  - a free plate thrown upwards off a bed with a constant gap g0: the
//    uplift is g0 + V tau (free flight);
//  - `max_pressure` at (`max_pressure_x`, `max_pressure_y`): q under the
//    self-weight alone (uniform contact); under the eccentric force
//    Gamma (w - g) there, with w from the solution at that point (the
//    point evaluation of the probes, not the foundation's Gauss point
//    values), and above the mean bearing pressure resultant / contact area;
//    the quarter model's the full plate's;
//  - the run's own check of the static equilibrium (StaticEquilibrium):
//    it applies to these free plates and finds them balanced to 1e-10.

#include "test_tools.h"

#include <cmath>

namespace
{
  using liftoff_tests::set;
  constexpr double aspect_ratio = 0.8, area = aspect_ratio, stiffness = 10;

  std::string
  free_plate(const std::string &symmetry = "full")
  {
    const unsigned int copies_x = (symmetry == "full" ? 1 : 2),
                       copies_y = (symmetry == "quarter" ? 2 : 1);
    return set("Analysis/Type", "static")
           + set("Plate/Aspect ratio", aspect_ratio)
           + set("Foundation/Stiffness", stiffness)
           + set("Discretization/Symmetry", symmetry)
           + set("Discretization/Cells along x", 8 / copies_x)
           + set("Discretization/Cells along y", 6 / copies_y)
           + set("Discretization/Polynomial degree", 2)
           + set("Output/Write foundation resultant", "true");
  }

  /// Largest difference of the four resultant columns of two rows.
  double
  column_difference(const liftoff::HistoryRow &a, const liftoff::HistoryRow &b)
  {
    return std::max({std::abs(a["resultant"] - b["resultant"]),
                     std::abs(a["resultant_x"] - b["resultant_x"]),
                     std::abs(a["resultant_y"] - b["resultant_y"]),
                     std::abs(a["contact_area"] - b["contact_area"])});
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  // Self-weight alone: uniform full contact.
  {
    const double q = 0.3;
    const auto   full =
      liftoff_tests::run_scene(free_plate() + set("Loads/Self weight", q));
    const auto &row = full->history().back();
    checks.less("self-weight: |resultant - q area| / (q area)",
                std::abs(row["resultant"] - q * area) / (q * area),
                1e-10);
    checks.less("self-weight: |centre - centroid|",
                std::hypot(row["resultant_x"], row["resultant_y"]),
                1e-10);
    checks.less("self-weight: |contact area - plate area| / plate area",
                std::abs(row["contact_area"] - area) / area,
                1e-12);
    const auto quarter = liftoff_tests::run_scene(
      free_plate("quarter") + set("Loads/Self weight", q));
    checks.less("self-weight: quarter model vs full plate, resultant columns",
                column_difference(quarter->history().back(), row),
                1e-10);
    checks.less("self-weight: |max_pressure - q| / q",
                std::abs(row["max_pressure"] - q) / q,
                1e-10);
    checks.within("self-weight, quarter model: the run's static "
                  "equilibrium imbalance (force only)",
                  quarter->static_equilibrium_imbalance(),
                  0,
                  1e-10);
    checks.less("self-weight: quarter model vs full plate, max_pressure",
                std::abs(quarter->history().back()["max_pressure"]
                         - row["max_pressure"]),
                1e-10);
  }

  // An eccentric force: the resultant balances it, at its point.
  {
    const double      P = 1, x = 0.3, y = 0.2;
    const std::string force =
      set("Loads/Point load 1/Magnitude", P)
      + set("Loads/Point load 1/Position",
            std::to_string(x) + ", " + std::to_string(y));
    for (const std::string gap : {"0", "0.01 - 0.03*x + 0.02*y"})
      {
        const auto run = liftoff_tests::run_scene(
          free_plate() + force + set("Foundation/Initial gap", gap));
        const auto       &row   = run->history().back();
        const std::string label = "eccentric force, gap " + gap + ": ";
        checks.less(label + "the plate lifts off (contact fraction)",
                    row["contact_fraction"],
                    0.95);
        checks.less(label + "|resultant - P| / P",
                    std::abs(row["resultant"] - P) / P,
                    1e-9);
        // The run's own check of the same balance, force and moments.
        checks.within(label + "the run's static equilibrium imbalance",
                      run->static_equilibrium_imbalance(),
                      0,
                      1e-10);
        checks.less(label + "|centre - point of the force|",
                    std::hypot(row["resultant_x"] - x, row["resultant_y"] - y),
                    1e-9);
        checks.less(label + "|contact area - contact fraction * area|",
                    std::abs(row["contact_area"]
                             - row["contact_fraction"] * area),
                    1e-12);
        const dealii::Point<2> at(row["max_pressure_x"], row["max_pressure_y"]);
        const double g = gap == "0" ? 0.0 : 0.01 - 0.03 * at[0] + 0.02 * at[1];
        checks.less(label + "|max_pressure - Gamma (w - g)| at its point",
                    std::abs(row["max_pressure"]
                             - stiffness * (run->deflection_at(at) - g)),
                    1e-9 * row["max_pressure"]);
        checks.less(label + "mean bearing pressure / max_pressure",
                    row["resultant"] / row["contact_area"]
                      / row["max_pressure"],
                    1.0);
      }
    // On the symmetry plane x = 0: a half model carries half the force.
    const std::string on_plane =
      set("Loads/Point load 1/Magnitude", P)
      + set("Loads/Point load 1/Position", "0, 0.25");
    const auto  full = liftoff_tests::run_scene(free_plate() + on_plane);
    const auto  half = liftoff_tests::run_scene(free_plate("half") + on_plane);
    const auto &a = full->history().back(), &b = half->history().back();
    checks.less("force on the symmetry plane: |centre - (0, 0.25)|",
                std::hypot(a["resultant_x"], a["resultant_y"] - 0.25),
                1e-9);
    checks.less("force on the symmetry plane: half model vs full plate, "
                "resultant columns",
                column_difference(a, b),
                1e-9);
    checks.less("force on the symmetry plane: half model vs full plate, "
                "max uplift",
                std::abs(a["max_uplift"] - b["max_uplift"]),
                1e-9 * a["max_uplift"]);
  }

  // The damped oscillator: springs and dashpots.
  {
    const double gamma_f = 10, c = 1.2, q = 1, dt = 0.05;
    const auto   run = liftoff_tests::run_scene(
      set("Plate/Aspect ratio", aspect_ratio)
      + set("Foundation/Model", "bilateral")
      + set("Foundation/Stiffness", gamma_f) + set("Foundation/Damping", c)
      + set("Discretization/Cells along x", 4)
      + set("Discretization/Cells along y", 3)
      + set("Discretization/Polynomial degree", 2)
      + set("Loads/Pressure 1/Magnitude", q)
      + set("Time integration/Time step", dt)
      + set("Time integration/End time", 2)
      + set("Output/Write foundation resultant", "true"));
    const auto               &history = run->history();
    std::vector<double>       v;
    const std::vector<double> w = liftoff_tests::scalar_newmark(
      gamma_f, c, q, 0.25, 0.5, dt, history.size() - 1, &v);
    double error = 0, centre = 0;
    for (unsigned int n = 0; n < history.size(); ++n)
      {
        error  = std::max(error,
                         std::abs(history[n]["resultant"]
                                  - area * (gamma_f * w[n] + c * v[n])));
        centre = std::max(centre,
                          std::hypot(history[n]["resultant_x"],
                                     history[n]["resultant_y"]));
      }
    checks.less("damped oscillator: max |resultant - area (Gamma w_n + c "
                "v_n)| / (q area)",
                error / (q * area),
                1e-9);
    checks.less("damped oscillator: max |centre|", centre, 1e-9);
  }

  // Free flight off a bed with a constant gap: uplift g0 + V tau.
  {
    const double V = 0.5, g0 = 0.01;
    const auto   run = liftoff_tests::run_scene(
      set("Plate/Aspect ratio", aspect_ratio)
      + set("Foundation/Initial gap", g0)
      + set("Discretization/Cells along x", 4)
      + set("Discretization/Cells along y", 3)
      + set("Discretization/Polynomial degree", 2)
      + set("Initial conditions/Velocity", "-0.5; 0; 0")
      + set("Time integration/Time step", 0.05)
      + set("Time integration/End time", 1)
      + set("Output/Write foundation resultant", "true"));
    double error = 0, force = 0;
    for (const auto &row : run->history())
      {
        error =
          std::max(error, std::abs(row["max_uplift"] - (g0 + V * row["tau"])));
        // The row of tau = 0 has the status the first step starts from
        // (all points in contact), as its contact fraction says.
        if (row["tau"] > 0)
          force =
            std::max({force, std::abs(row["resultant"]), row["contact_area"]});
      }
    checks.less("free flight over a gap g0: max |max uplift - (g0 + V tau)| / "
                "V",
                error / V,
                1e-10);
    checks.less("free flight: largest |resultant| and contact area",
                force,
                1e-300);
  }
  return checks.exit_code();
}
