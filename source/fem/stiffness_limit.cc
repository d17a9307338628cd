#include <deal.II/base/mpi.h>

#include <liftoff/base/number_text.h>
#include <liftoff/fem/stiffness_limit.h>

#include <algorithm>

namespace liftoff
{
  double
  StiffnessLimit::largest_relative_entry(
    const LA::MPI::Vector           &diagonal_per_unit,
    const LA::MPI::SparseMatrix     &plate_stiffness,
    const AffineConstraints<double> &constraints)
  {
    double largest = 0;
    for (const auto i : diagonal_per_unit.locally_owned_elements())
      if (const double d = diagonal_per_unit(i);
          d > 0 && !constraints.is_constrained(i))
        largest = std::max(largest, d / plate_stiffness.diag_element(i));
    return Utilities::MPI::max(largest,
                               diagonal_per_unit.get_mpi_communicator());
  }


  void
  StiffnessLimit::check(const LA::MPI::SparseMatrix     &plate_stiffness,
                        const AffineConstraints<double> &constraints,
                        const std::vector<SystemTerm *> &terms)
  {
    for (const SystemTerm *term : terms)
      for (const SystemTerm::Coupling &coupling : term->couplings())
        {
          const double per_unit =
            largest_relative_entry(coupling.diagonal_per_unit,
                                   plate_stiffness,
                                   constraints);
          if (per_unit == 0)
            continue;

          const double largest = largest_ratio / per_unit;
          AssertThrow(
            coupling.value <= largest,
            ExcMessage(
              coupling.entry + " = <" + format_number(coupling.value)
              + "> is more than this scene's solve can carry: its springs "
                "would add "
              + format_number(coupling.value * per_unit)
              + " times the plate's own stiffness to the diagonal of the "
                "rows they join, which drowns the plate's digits in double "
                "precision. The largest value that works for this scene is "
                "the given one divided by "
              + format_number(coupling.value / largest) + " ("
              + format_number(largest)
              + " in the dimensionless units the solver runs in, "
              + format_number(largest_ratio)
              + " times the plate's entry); from a tenth of that on, the "
                "joint is as stiff as it gets to about 1e-6 of the answer, "
                "so a larger value changes only the round-off."));
        }
  }
} // namespace liftoff
