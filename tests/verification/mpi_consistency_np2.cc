// The same scene on two ranks (MPI_COMM_WORLD) and on one (MPI_COMM_SELF of
// rank 0) must give the same history to 1e-10: the distributed mesh, the
// ownership of point loads and probes on partition boundaries, the contact
// status and the energies may not depend on the partition. The scene runs
// with the nine-node element (Q2) and with the eight-node serendipity
// element (S2, reduced shear integration), whose unknowns must also be
// those of its vertices and edges alone, and on an adaptive mesh (Q2,
// refined and coarsened every 5 steps; and above Kelly's cell limit),
// whose meshes must be the same at every step. Beyond the rectangle
// (issue 34): a disc (GridGenerator::hyper_ball_balanced, its manifolds and
// a MappingQ2 on every rank) and a mesh read from a gmsh file, each under
// a load off its centre on the tensionless bed, and an adaptive half disc
// whose rim is hard simply supported (normal-tangential constraints).

#include <deal.II/base/mpi.h>

#include "symmetric_scene.h"
#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  void
  compare_1_and_2_ranks(const std::string     &label,
                        const std::string     &scene,
                        const unsigned int     expected_n_dofs,
                        liftoff_tests::Checks &checks)
  {
    const auto parallel = liftoff_tests::run_scene(scene);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const auto serial = liftoff_tests::run_scene(scene, nullptr, MPI_COMM_SELF);
    double     contact_difference     = 0;
    unsigned int iteration_mismatches = 0, mesh_mismatches = 0;
    for (unsigned int n = 0; n < serial->history().size(); ++n)
      {
        const auto &a = serial->history()[n], &b = parallel->history()[n];
        contact_difference =
          std::max(contact_difference,
                   std::abs(a["contact_fraction"] - b["contact_fraction"]));
        iteration_mismatches +=
          (a["active_set_iterations"] != b["active_set_iterations"]);
        mesh_mismatches +=
          (a["cells"] != b["cells"]) || (a["dofs"] != b["dofs"]);
      }
    // 0: the mesh changes during the run (adaptive), and its unknowns are
    // checked step by step only.
    if (expected_n_dofs > 0)
      for (const auto *run : {serial.get(), parallel.get()})
        checks.less(label + ": unknowns vs " + std::to_string(expected_n_dofs),
                    std::abs(
                      double(run->get_discretization().dof_handler.n_dofs())
                      - expected_n_dofs),
                    0.5);
    checks.less(label + ", 1 vs 2 ranks: steps with different meshes",
                mesh_mismatches,
                0.5);
    checks.less(label + ", 1 vs 2 ranks: probe histories (relative)",
                liftoff_tests::history_difference(*serial, *parallel),
                1e-10);
    checks.less(label + ", 1 vs 2 ranks: contact fraction",
                contact_difference,
                1e-10);
    checks.less(label
                  + ", 1 vs 2 ranks: energies and work (relative to max work)",
                liftoff_tests::energy_difference(*serial, *parallel),
                1e-10);
    checks.less(label
                  + ", 1 vs 2 ranks: steps with a different iteration count",
                iteration_mismatches,
                0.5);
  }
} // namespace


LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv, 2);

  // 10 x 8 cells: 11 x 9 vertices, 10 x 9 + 8 x 11 edges and 80 cells,
  // three fields on each node (S2 has none inside the cells).
  const std::string scene = liftoff_tests::symmetric_scene("full", 10, 8);
  compare_1_and_2_ranks("Q2", scene, 3 * (99 + 178 + 80), checks);
  compare_1_and_2_ranks("S2",
                        scene
                          + "subsection Discretization\n"
                            "  set Element = serendipity\n"
                            "  set Shear integration = reduced\n"
                            "end\n",
                        3 * (99 + 178),
                        checks);
  const std::string adaptive = scene
                               + "subsection Mesh refinement\n"
                                 "  set Adaptive = true\n"
                                 "  set Interval = 5\n"
                                 "  set Maximum level = 2\n"
                                 "  set Initial refinements = 1\n"
                                 "end\n";
  compare_1_and_2_ranks("Q2 adaptive", adaptive, 0, checks);
  // Above Kelly's cell limit (the front and the loads refine past it),
  // from an initial displacement (the mesh first adapts to it): deal.II's
  // coarsening back to the limit chose other meshes on 1 and 2 ranks.
  compare_1_and_2_ranks("Q2 adaptive, above the cell limit",
                        adaptive
                          + "subsection Mesh refinement\n"
                            "  set Maximum number of cells = 100\n"
                            "  set Initial refinements = 2\n"
                            "end\n"
                            "subsection Initial conditions\n"
                            "  set Displacement = "
                            "0.01*exp(-50*((x-0.1)^2+y^2)); 0; 0\n"
                            "end\n",
                        0,
                        checks);

  const std::string off_centre = R"(
subsection Plate
  set Thickness ratio = 0.05
  set Poisson ratio = 0.3
end
subsection Foundation
  set Model = tensionless
  set Stiffness = 300
end
subsection Loads
  subsection Point load 1
    set Magnitude = 1
    set Position = 0.12, -0.05
    set Time history = 20*tau
  end
  subsection Pressure 1
    set Magnitude = 2
    set Region = whole plate
    set Intensity = if(x > -0.25 & x < 0.05 & y > -0.1 & y < 0.2, 1, 0)
  end
end
subsection Time integration
  set Time step = 2e-3
  set End time = 0.04
end
subsection Output
  set Probe points = 0.12, -0.05; 0, 0; 0.5, 0; -0.2, 0.3; 0, -0.5
end
)";
  compare_1_and_2_ranks("Q2 disc",
                        off_centre
                          + "subsection Discretization\n"
                            "  set Shape = disc\n"
                            "  set Global refinements = 1\n"
                            "  set Polynomial degree = 2\n"
                            "end\n",
                        0,
                        checks);
  // Hard simple support on the rim: psi . t = 0 by normal-tangential
  // constraints, whose normals must be the same on every rank that sees a
  // rim face; the half disc, where the rim meets the plane x = 0, adapted
  // (hanging nodes on the rim, refined and coarsened every 5 steps).
  compare_1_and_2_ranks("Q2 half disc, hard simply supported, adaptive",
                        R"(
subsection Plate
  set Thickness ratio = 0.05
end
subsection Foundation
  set Model = tensionless
  set Stiffness = 300
end
subsection Loads
  subsection Point load 1
    set Magnitude = 1
    set Position = 0, -0.2
    set Time history = 20*tau
  end
end
subsection Time integration
  set Time step = 2e-3
  set End time = 0.04
end
subsection Output
  set Probe points = 0, -0.2; 0, 0; 0.3, 0.1; 0.2, -0.4
end
subsection Boundary conditions
  set Outer = hard simply supported
end
subsection Mesh refinement
  set Adaptive = true
  set Interval = 5
  set Maximum level = 3
end
subsection Discretization
  set Shape = disc
  set Symmetry = half
  set Global refinements = 1
  set Polynomial degree = 2
end
)",
                        0,
                        checks);
  // 10 x 10 cells of the square: 21 x 21 nodes of Q2.
  compare_1_and_2_ranks("Q2 mesh file",
                        off_centre
                          + "subsection Discretization\n"
                            "  set Shape = mesh file\n"
                            "  set Mesh file = " LIFTOFF_SOURCE_DIR
                            "/tests/meshes/square.msh\n"
                            "  set Polynomial degree = 2\n"
                            "end\n",
                        3 * 21 * 21,
                        checks);
  const int code = checks.exit_code();
  return dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
}
