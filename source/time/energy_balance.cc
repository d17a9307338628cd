#include <liftoff/time/energy_balance.h>

namespace liftoff
{
  EnergyBalance
  energies_of(const std::vector<SystemTerm *> &terms,
              const LA::MPI::Vector           &u,
              const LA::MPI::Vector           &ghosted_u,
              const LA::MPI::Vector           &v,
              const double                     copies,
              const double                     work,
              LA::MPI::Vector                 &product)
  {
    EnergyBalance   e;
    const TermState state{u, ghosted_u, product};
    // The velocity's kinetic energy needs no ghosts.
    const TermState motion{v, v, product};
    // copies is a power of two: copies * (1/2 u.K u) is 1/2 copies u.K u
    // to the bit.
    for (const SystemTerm *term : terms)
      {
        e.kinetic += copies * term->kinetic_energy(motion);
        e.by_term.push_back(copies * term->energy(state));
        (term->stores() == SystemTerm::Stores::strain ? e.strain
                                                      : e.supports) +=
          e.by_term.back();
      }
    e.work = work;
    return e;
  }


  double
  work_of_step(const LA::MPI::Vector &u_old,
               const LA::MPI::Vector &u_new,
               const LA::MPI::Vector &load_old,
               const LA::MPI::Vector &load_new,
               const double           copies,
               LA::MPI::Vector       &increment,
               LA::MPI::Vector       &load_sum)
  {
    copy_values(u_new, increment);
    increment -= u_old;
    copy_values(load_old, load_sum);
    load_sum += load_new;
    return 0.5 * copies * (increment * load_sum);
  }
} // namespace liftoff
