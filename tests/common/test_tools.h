#pragma once

// Helpers shared by the test programs: run a scene given as prm text through
// the same Simulator the executable uses, and report checks as lines
// "PASS/FAIL <what>: <value> (limit <limit>)" with a non-zero exit on failure.

#include <deal.II/base/convergence_table.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <liftoff/run/simulator.h>

#include "test_registry.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace liftoff_tests
{
  using namespace dealii;

  /// Parse the scene (parameters it does not set keep their defaults; no
  /// output files unless it sets Output/Directory) and run it, started as
  /// `start` says (Simulator::Start).
  inline std::unique_ptr<liftoff::Simulator>
  run_scene(
    const std::string              &scene,
    Function<2>                    *body_force = nullptr,
    const MPI_Comm                  comm       = MPI_COMM_WORLD,
    const liftoff::Simulator::Start start = liftoff::Simulator::Start::fresh)
  {
    ParameterHandler prm;
    auto             simulator =
      std::make_unique<liftoff::Simulator>(comm, /*verbose*/ false);
    simulator->declare_scene(prm);
    std::istringstream text("subsection Output\n  set Directory =\n"
                            "  set VTU interval = 0\nend\n"
                            + scene);
    prm.parse_input(text, "test scene");
    simulator->parse_parameters(prm);
    simulator->set_body_force(body_force);
    simulator->run(prm, start);
    return simulator;
  }

  /// prm text that sets one entry, named by its path ("Time integration/End
  /// time"); numbers with every digit they have.
  template <typename Value>
  inline std::string
  set(const std::string &path, const Value &value)
  {
    const std::vector<std::string> names =
      Utilities::split_string_list(path, '/');
    std::ostringstream text;
    text << std::setprecision(17);
    for (unsigned int k = 0; k + 1 < names.size(); ++k)
      text << "subsection " << names[k] << "\n";
    text << "  set " << names.back() << " = " << value << "\n";
    for (unsigned int k = 0; k + 1 < names.size(); ++k)
      text << "end\n";
    return text.str();
  }

  /// prm text: the small dynamic scene of several tests, a quarter of the
  /// default square plate on 6 x 6 Q2 cells under a unit force suddenly
  /// applied at its centre, 40 steps of 5e-4 (the contact set moves in
  /// every step).
  inline std::string
  small_plate_scene()
  {
    return set("Discretization/Symmetry", "quarter")
           + set("Discretization/Cells along x", 6)
           + set("Discretization/Cells along y", 6)
           + set("Discretization/Polynomial degree", 2)
           + set("Loads/Point load 1/Magnitude", 1)
           + set("Time integration/Time step", 5e-4)
           + set("Time integration/End time", 0.02);
  }

  /// prm text: a square plate of the given section.
  inline std::string
  square_plate(const double thickness_ratio,
               const double poisson_ratio,
               const double shear_correction)
  {
    std::ostringstream text;
    text << std::setprecision(17) << "subsection Plate\n"
         << "  set Aspect ratio = 1\n"
         << "  set Thickness ratio = " << thickness_ratio << "\n"
         << "  set Poisson ratio = " << poisson_ratio << "\n"
         << "  set Shear correction factor = " << shear_correction << "\n"
         << "end\n";
    return text.str();
  }

  /// prm text: the same condition on all four edges.
  inline std::string
  all_edges(const std::string &condition)
  {
    std::string text = "subsection Boundary conditions\n";
    for (const char *edge : {"Left", "Right", "Bottom", "Top"})
      text += std::string("  set ") + edge + " = " + condition + "\n";
    return text + "end\n";
  }

  /**
   * The checks of a test program, and what every test's main() starts
   * with: constructing them starts MPI (one thread per rank) for the life
   * of the program, and a test written for `n_ranks` ranks (0: any number)
   * refuses to run on another number.
   */
  class Checks
  {
  public:
    Checks(int &argc, char **&argv, const unsigned int n_ranks = 0)
        : mpi(argc, argv, 1)
    {
      AssertThrow(
        n_ranks == 0
          || Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == n_ranks,
        ExcMessage("Run this test on " + std::to_string(n_ranks) + " ranks."));
    }

    /// Pass if value < limit (NaN fails).
    void
    less(const std::string &what, const double value, const double limit)
    {
      const bool ok = (value < limit);
      report(ok, what, value, "<", limit);
    }

    /// Pass if lower <= value <= upper.
    void
    within(const std::string &what,
           const double       value,
           const double       lower,
           const double       upper)
    {
      const bool ok = (value >= lower && value <= upper);
      if (is_root())
        std::cout << (ok ? "PASS " : "FAIL ") << what << ": "
                  << std::setprecision(4) << value << " (in [" << lower << ", "
                  << upper << "])" << std::endl;
      failures += !ok;
    }

    int
    exit_code() const
    {
      if (is_root())
        std::cout << (failures == 0
                        ? "all checks passed"
                        : std::to_string(failures) + " check(s) failed")
                  << std::endl;
      return failures == 0 ? 0 : 1;
    }

  private:
    Utilities::MPI::MPI_InitFinalize mpi;
    int                              failures = 0;

    static bool
    is_root()
    {
      return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    }

    void
    report(const bool         ok,
           const std::string &what,
           const double       value,
           const char        *relation,
           const double       limit)
    {
      if (is_root())
        std::cout << (ok ? "PASS " : "FAIL ") << what << ": "
                  << std::setprecision(4) << value << " (" << relation << ' '
                  << limit << ")" << std::endl;
      failures += !ok;
    }
  };

  /// Newmark's method written out for the scalar oscillator
  /// w'' + c w' + k w = q from rest (a_0 = q): w_0, ..., w_{n_steps} (and
  /// v_0, ..., v_{n_steps} in `velocities` if given). An
  /// independent reference for the plate's rigid motions on its bed.
  inline std::vector<double>
  scalar_newmark(const double         k,
                 const double         c,
                 const double         q,
                 const double         beta,
                 const double         gamma,
                 const double         dt,
                 const unsigned int   n_steps,
                 std::vector<double> *velocities = nullptr)
  {
    std::vector<double> history = {0.0};
    if (velocities)
      *velocities = {0.0};
    double w = 0, v = 0, a = q;
    while (history.size() < n_steps + 1)
      {
        const double w_new =
          (q + (w / (beta * dt * dt) + v / (beta * dt) + (0.5 / beta - 1) * a)
           + c
               * (gamma / (beta * dt) * w - (1 - gamma / beta) * v
                  - dt * (1 - 0.5 * gamma / beta) * a))
          / (1 / (beta * dt * dt) + c * gamma / (beta * dt) + k);
        const double a_new = (w_new - w) / (beta * dt * dt) - v / (beta * dt)
                             - (0.5 / beta - 1) * a;
        v += dt * ((1 - gamma) * a + gamma * a_new);
        w = w_new;
        a = a_new;
        history.push_back(w);
        if (velocities)
          velocities->push_back(v);
      }
    return history;
  }

  /// Largest difference of two runs' probe histories over all steps and
  /// probes, relative to the largest |w| of the first.
  inline double
  history_difference(const liftoff::Simulator &a, const liftoff::Simulator &b)
  {
    const auto &ha = a.history(), &hb = b.history();
    AssertThrow(ha.size() == hb.size(),
                ExcMessage("The runs have different numbers of steps."));
    double difference = 0, scale = 0;
    for (unsigned int n = 0; n < ha.size(); ++n)
      for (unsigned int k = 0; k < ha[n].probes("w").size(); ++k)
        {
          difference =
            std::max(difference,
                     std::abs(ha[n].probes("w")[k] - hb[n].probes("w")[k]));
          scale = std::max(scale, std::abs(ha[n].probes("w")[k]));
        }
    return difference / scale;
  }

  /// Largest difference of two runs' energies and work over all steps,
  /// relative to the largest work of the first.
  inline double
  energy_difference(const liftoff::Simulator &a, const liftoff::Simulator &b)
  {
    double difference = 0, scale = 0;
    for (unsigned int n = 0; n < a.history().size(); ++n)
      {
        const auto &ea = a.history()[n].energies(),
                   &eb = b.history()[n].energies();
        difference     = std::max({difference,
                                   std::abs(ea.kinetic - eb.kinetic),
                                   std::abs(ea.strain - eb.strain),
                                   std::abs(ea.supports - eb.supports),
                                   std::abs(ea.work - eb.work)});
        scale          = std::max(scale, std::abs(ea.work));
      }
    return difference / scale;
  }

  /**
   * deal.II's ConvergenceTable, whose observed orders can also be read back
   * for checks: add one row per run (add_value), then orders() of each error
   * column, then write_text().
   */
  class OrderTable : public ConvergenceTable
  {
  public:
    /// Observed orders of the error column `key` between successive rows,
    /// from ConvergenceTable's reduction_rate_log2: with `reference` (cells
    /// along a side) the rate in that column's growth, without it one
    /// halving (of h or dt) per row. Entry k - 1 is the order from row k - 1
    /// to row k.
    std::vector<double>
    orders(const std::string &key, const std::string &reference = "")
    {
      if (reference.empty())
        evaluate_convergence_rates(key, reduction_rate_log2);
      else
        evaluate_convergence_rates(key, reference, reduction_rate_log2, 1);
      // The column ConvergenceTable adds for these rates; its first row
      // holds "-".
      const auto         &rates = columns.at(key + "...red.rate.log2").entries;
      std::vector<double> result;
      for (unsigned int k = 1; k < rates.size(); ++k)
        result.push_back(rates[k].get_numeric_value());
      return result;
    }
  };
} // namespace liftoff_tests
