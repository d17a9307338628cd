// The dowels' law on its own, without a Simulator: two slabs of one cell
// each, one dowel on the joint between them (stiffness C, looseness g),
// and a jump [w] = w_lower - w_upper imposed by moving each slab as a
// rigid body. Against the law written out here: the status is slack while
// |[w]| <= g and engaged on the side of the jump beyond; the force is
// C ([w] - g sign [w]) beyond g and 0 within; the energy 1/2 C (|[w]| -
// g)^2; and the matrix and load of the status give that force again as a
// second method: the work u . (A u - f) of the term equals [w] F.

#include <deal.II/base/parameter_handler.h>

#include <liftoff/run/scene_parts.h>

#include "test_tools.h"

#include <cmath>
#include <sstream>

using namespace dealii;

namespace
{
  const double stiffness = 7.0, looseness = 0.01;

  // The scene: the unit square in two slabs across x, one cell each,
  // the dowel on joint x1 at y = -0.2.
  void
  read_scene(ParameterHandler &prm)
  {
    liftoff::SceneParts::declare_parameters(prm);
    std::istringstream scene("subsection Discretization\n"
                             "  set Cells along x = 2\n"
                             "  set Cells along y = 1\n"
                             "  set Polynomial degree = 1\n"
                             "end\n"
                             "subsection Slabs\n"
                             "  set Slabs along x = 2\n"
                             "  subsection Dowels\n"
                             "    set Joints = x1\n"
                             "    set Positions = 0.3\n"
                             "    set Stiffness = "
                             + std::to_string(stiffness)
                             + "\n    set Looseness = "
                             + std::to_string(looseness) + "\n  end\nend\n");
    prm.parse_input(scene, "dowel law scene");
  }


  // u: w = jump / 2 on the lower slab (x < 0), -jump / 2 on the upper one.
  void
  impose_jump(const liftoff::Discretization &discretization,
              const double                   jump,
              liftoff::LA::MPI::Vector      &u)
  {
    u = 0;
    std::vector<types::global_dof_index> dofs(
      discretization.dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : discretization.dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_indices(dofs);
        const double w = (cell->center()[0] < 0 ? 0.5 : -0.5) * jump;
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (cell->get_fe().system_to_component_index(i).first
                == liftoff::PlateFields::w
              && u.in_local_range(dofs[i]))
            u[dofs[i]] = w;
      }
    u.compress(VectorOperation::insert);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  ParameterHandler prm;
  read_scene(prm);
  liftoff::SectionTimer  timer;
  liftoff::SceneParts    parts(MPI_COMM_WORLD, timer);
  liftoff::PhysicalUnits units;
  parts.parse_parameters(prm, units);
  parts.setup_mesh();
  const liftoff::Discretization &disc   = parts.discretization;
  liftoff::JointDowels          &dowels = parts.joint_dowels;
  dowels.setup(disc);
  checks.within("one dowel", double(dowels.sites().size()), 1, 1);

  liftoff::LA::MPI::Vector u, ghosted_u, scratch, load;
  disc.reinit_vector(u);
  disc.reinit_vector(scratch);
  disc.reinit_vector(load);
  disc.reinit_ghosted_vector(ghosted_u);

  for (const double jump : {-0.03, -0.004, 0.0, 0.006, 0.025})
    {
      impose_jump(disc, jump, u);
      ghosted_u = u;
      dowels.update_status(ghosted_u);
      const std::string at = "[w] = " + std::to_string(jump) + ": ";

      // The law as written: slack within g, engaged on the side of the jump.
      const bool   engaged = std::abs(jump) > looseness;
      const double expected =
        engaged ? stiffness * (jump - std::copysign(looseness, jump)) : 0.0;
      const unsigned char status =
        dowels.status().empty() ? 255 : dowels.status()[0];
      const unsigned char expected_status =
        !engaged ? 0 : (jump > 0 ? 1 : 2); // slack, lower, upper
      if (!dowels.status().empty())
        checks.within(at + "status", status, expected_status, expected_status);

      const double force = dowels.forces(ghosted_u)[0];
      checks.within(at + "force", force, expected - 1e-12, expected + 1e-12);

      const liftoff::TermState state{u, ghosted_u, scratch};
      const double             energy = dowels.energy(state);
      const double             expected_energy =
        engaged ? 0.5 * stiffness * std::pow(std::abs(jump) - looseness, 2)
                            : 0.0;
      checks.within(at + "energy",
                    energy,
                    expected_energy - 1e-14,
                    expected_energy + 1e-14);

      // The term's force, A(status) u less its status load, does the work
      // [w] F on u (each slab moves by +-[w]/2 against the dowel's force).
      load = 0;
      dowels.add_force(state, load);
      double work = load * u;
      if (dowels.has_status_load())
        {
          load = 0;
          dowels.add_status_load(load);
          work -= load * u;
        }
      checks.within(at + "work of the term's force",
                    work,
                    jump * expected - 1e-12,
                    jump * expected + 1e-12);
    }
  return checks.exit_code();
}
