#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/number_text.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/joint_springs.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/fem/plate_geometry.h>
#include <liftoff/output/joint_probes.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/stress_resultants.h>
#include <liftoff/output/time_history.h>
#include <liftoff/time/plate_state.h>

#include <cmath>

namespace liftoff
{


  void
  JointProbes::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Joint probe points",
      "",
      Patterns::List(Patterns::List(Patterns::Double(), 2, 2, ","),
                     0,
                     Patterns::List::max_int_value,
                     ";"),
      "Points x, y of the full plate on joints that are not tied, "
      "separated by ';': at each, history.csv gets w of the lower (left, "
      "bottom) and the upper slab, w_lower(x;y) and w_upper(x;y), their "
      "load transfer lte(x;y) (the smaller over the larger), the face "
      "stress along the joint on each side (sigma_yy on a joint x = const, "
      "sigma_xx on y = const), sigma_lower(x;y) and sigma_upper(x;y), and "
      "its transfer lte_sigma(x;y), at every step. The transfers are of "
      "the load's part, the changes since the plate at rest, as a "
      "deflectometer measures: since tau = 0 in a time integration (the "
      "plate settled under its weight and permanent loads), since the "
      "equilibrium under the weight and the temperature loads alone in a "
      "static analysis; empty where the larger side moves by less than a "
      "tenth of the plate's largest change (the load far from the joint)."
        + quantity("position"));
  }


  void
  JointProbes::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    const PlateGeometry &geometry = scene.discretization.geometry();
    plate                         = &scene.plate;
    probes.clear();
    const auto &joints = geometry.slabs().joints();
    for (const auto &entry :
         Utilities::split_string_list(prm.get("Joint probe points"), ';'))
      {
        const auto xy =
          Utilities::string_to_double(Utilities::split_string_list(entry, ','));
        const Point<2> p(xy[0], xy[1]);
        const Point<2> modelled =
          geometry.is_on_plate(p) ? geometry.to_modelled_part(p) : p;
        const double size = geometry.plate_box().side_length(0);
        const auto   on   = [&](const Joint &joint) {
          const double along = modelled[1 - joint.normal_axis];
          return !joint.tied
                 && std::abs(modelled[joint.normal_axis] - joint.position)
                      <= 1e-10 * size
                 && along >= joint.start - 1e-10 * size
                 && along <= joint.end + 1e-10 * size;
        };
        unsigned int j = 0;
        while (j < joints.size() && !on(joints[j]))
          ++j;
        AssertThrow(geometry.is_on_plate(p) && j < joints.size(),
                    ExcMessage("Output/Joint probe points: the point "
                               + format_number(p[0]) + ", "
                               + format_number(p[1])
                               + " lies on no joint of the plate that is "
                                 "not tied."));
        probes.push_back({p, modelled, j});
      }
  }


  void
  JointProbes::add_columns_to(TimeHistory &history) const
  {
    if (probes.empty())
      return;
    using Quantity        = PhysicalUnits::Quantity;
    const Quantity stress = StressResultants::quantities().at("sigma_xx");
    const std::vector<std::pair<std::string, Quantity>> kinds = {
      {"w_lower", Quantity::deflection},
      {"w_upper", Quantity::deflection},
      {"lte", Quantity::number},
      {"sigma_lower", stress},
      {"sigma_upper", stress},
      {"lte_sigma", Quantity::number}};
    std::vector<std::string> names;
    std::vector<Point<2>>    points;
    for (const Probe &probe : probes)
      for (const auto &kind : kinds)
        {
          names.push_back(kind.first);
          points.push_back(probe.point);
        }
    const std::vector<std::string> columns =
      history.probe_column_names(names, points);
    std::vector<HistoryColumns::Column> group;
    for (unsigned int k = 0; k < columns.size(); ++k)
      group.push_back({columns[k], kinds[k % kinds.size()].second});
    history.add_columns(group,
                        [this](const StepData &step) { return values(step); });
  }


  void
  JointProbes::setup(const SceneView &scene, const std::string &)
  {
    rest.clear();
    mesh_changed(scene);
  }


  void
  JointProbes::mesh_changed(const SceneView &scene)
  {
    const Discretization &disc = scene.discretization;
    discretization             = &disc;
    located.clear();
    if (probes.empty())
      return;
    const SlabLayout &slabs = disc.geometry().slabs();
    const Point<2>    high =
      disc.geometry().modelled_box().get_boundary_points().second;
    slabs.for_each_joint_face(
      disc.dof_handler,
      [&](const DoFHandler<2>::active_cell_iterator &cell,
          const unsigned int                         face,
          const unsigned int                         joint) {
        const Joint       &j     = slabs.joints()[joint];
        const unsigned int along = 1 - j.normal_axis;
        const double       a     = cell->face(face)->vertex(0)[along];
        const double       b     = cell->face(face)->vertex(1)[along];
        const double       tol   = 1e-10 * std::abs(b - a);
        // Half-open pieces, the last one closed: a point at a vertex
        // belongs to one piece.
        const double end = std::max(a, b);
        for (unsigned int k = 0; k < probes.size(); ++k)
          {
            const double x = probes[k].modelled[along];
            if (probes[k].joint == joint && x >= std::min(a, b) - tol
                && (x < end - tol || end >= high[along] - tol))
              {
                const auto opposite = slabs.across(cell, face);
                const bool is_lower =
                  cell->face(face)->boundary_id() == j.lower_side;
                located.push_back(
                  {k, is_lower ? cell : opposite, is_lower ? opposite : cell});
              }
          }
      });
  }


  std::vector<double>
  JointProbes::sides_at(const LA::MPI::Vector &ghosted_u,
                        const StepData        &step) const
  {
    const Discretization  &disc = *discretization;
    const StressResultants resultants(*plate,
                                      disc.mapping(),
                                      disc.element().shear_integration(),
                                      ghosted_u,
                                      step.resultants.free_bending());
    std::vector<double>    result(6 * probes.size(), 0.0);
    for (const Located &l : located)
      {
        const Probe       &probe = probes[l.probe];
        const unsigned int sigma = StressResultants::field_index(
          disc.geometry().slabs().joints()[probe.joint].normal_axis == 0
            ? "sigma_yy"
            : "sigma_xx");
        double *out = &result[6 * l.probe];
        for (unsigned int side = 0; side < 2; ++side)
          {
            const auto    &cell = side == 0 ? l.lower : l.upper;
            const Point<2> unit = GeometryInfo<2>::project_to_unit_cell(
              disc.mapping().transform_real_to_unit_cell(cell, probe.modelled));
            FEValues<2> fe_values(disc.mapping(),
                                  cell->get_fe(),
                                  Quadrature<2>(unit),
                                  update_values | update_gradients
                                    | update_quadrature_points);
            fe_values.reinit(cell);
            std::vector<Vector<double>> computed,
              u(1, Vector<double>(cell->get_fe().n_components()));
            resultants.evaluate(cell, fe_values, computed);
            fe_values.get_function_values(ghosted_u, u);
            out[side]     = u[0][PlateFields::w];
            out[3 + side] = computed[0][sigma];
          }
      }
    Utilities::MPI::sum(result, disc.mpi_communicator, result);
    return result;
  }


  std::vector<double>
  JointProbes::values(const StepData &step) const
  {
    std::vector<double> result = sides_at(step.state.ghosted_u, step);
    if (step.state.clock.step() == 0)
      rest = sides_at(step.state.ghosted_rest, step);
    rest.resize(result.size(), 0.0);
    const double reference =
      step.scene.joints.largest_load_deflection(step.state.ghosted_u,
                                                step.state.ghosted_rest);
    for (unsigned int k = 0; k < result.size(); k += 6)
      {
        result[k + 2] = JointSprings::load_transfer(result[k] - rest[k],
                                                    result[k + 1] - rest[k + 1],
                                                    reference);
        // The stress's ratio where the deflection's has a meaning.
        const double a = result[k + 3] - rest[k + 3];
        const double b = result[k + 4] - rest[k + 4];
        result[k + 5] =
          std::isnan(result[k + 2])
            ? result[k + 2]
            : JointSprings::load_transfer(a,
                                          b,
                                          std::max(std::abs(a), std::abs(b)));
      }
    return result;
  }


  void
  JointProbes::save(OutputArchive &archive) const
  {
    archive << rest;
  }


  void
  JointProbes::load(InputArchive &archive)
  {
    archive >> rest;
  }
} // namespace liftoff
