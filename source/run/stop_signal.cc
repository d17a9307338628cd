#include <liftoff/run/stop_signal.h>

#include <csignal>

namespace liftoff
{
  namespace
  {
    // Only a lock-free write is allowed in a signal handler.
    volatile std::sig_atomic_t signal_received = 0;

    extern "C" void
    note_signal(int number)
    {
      signal_received = number;
    }
  } // namespace


  void
  StopSignal::install()
  {
    std::signal(SIGINT, note_signal);
    std::signal(SIGTERM, note_signal);
  }


  int
  StopSignal::received(const MPI_Comm comm)
  {
    return dealii::Utilities::MPI::max(static_cast<int>(signal_received), comm);
  }
} // namespace liftoff
