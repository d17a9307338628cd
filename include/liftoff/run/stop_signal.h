#pragma once

#include <deal.II/base/mpi.h>

namespace liftoff
{
  /**
   * SIGINT and SIGTERM as a request to stop: the handler only notes the
   * signal, and the time loop asks after each step whether any rank got one,
   * so a run ends between steps with every file complete. Programs that do
   * not call install() (the tests) keep the default behaviour.
   */
  class StopSignal
  {
  public:
    /// Catch SIGINT and SIGTERM from now on.
    static void
    install();

    /// The signal any rank has received, or 0 (collective).
    static int
    received(const MPI_Comm comm);
  };
} // namespace liftoff
