#include <liftoff/time/plate_state.h>

namespace liftoff
{
  void
  PlateState::reinit(const Discretization &discretization)
  {
    for (LA::MPI::Vector *vector : {&u, &v, &a, &load, &balance})
      discretization.reinit_vector(*vector);
    discretization.reinit_ghosted_vector(ghosted_u);
  }
} // namespace liftoff
