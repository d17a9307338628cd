#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/numerics/data_out.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/output/point_fields.h>
#include <liftoff/output/vtu_pieces.h>

#include <map>

namespace liftoff
{
  void
  write_point_fields(const std::string             &directory,
                     const Discretization          &disc,
                     const std::vector<PointField> &fields,
                     const PhysicalUnits           &units,
                     const double                   time,
                     const std::string             &stem,
                     const bool                     has_moments)
  {
    const FE_DGQ<2> element(disc.element().degree());
    DoFHandler<2>   point_dofs(disc.triangulation);
    point_dofs.distribute_dofs(element);
    // The order of ResultantSweep::points(): this rank's cells, and in each
    // the support points of FE_DGQ(p), which are the output points.
    std::vector<LA::MPI::Vector> vectors(fields.size());
    for (auto &vector : vectors)
      vector.reinit(point_dofs.locally_owned_dofs(), disc.mpi_communicator);
    std::vector<types::global_dof_index> indices(element.n_dofs_per_cell());
    unsigned int                         i = 0;
    for (const auto &owned : disc.locally_owned_cells())
      {
        const DoFHandler<2>::active_cell_iterator cell(&disc.triangulation,
                                                       owned->level(),
                                                       owned->index(),
                                                       &point_dofs);
        cell->get_dof_indices(indices);
        for (const auto index : indices)
          {
            for (unsigned int f = 0; f < fields.size(); ++f)
              vectors[f][index] = fields[f].values[i];
            ++i;
          }
      }
    FieldDataOut                                   data_out;
    std::map<std::string, PhysicalUnits::Quantity> quantities;
    data_out.attach_dof_handler(point_dofs);
    for (unsigned int f = 0; f < fields.size(); ++f)
      {
        vectors[f].compress(VectorOperation::insert);
        data_out.add_data_vector(vectors[f], fields[f].name);
        quantities[fields[f].name] = fields[f].quantity;
      }
    data_out.build_patches(disc.mapping(), element.degree);
    const double scene_time = units.scale(PhysicalUnits::Quantity::time) * time;
    DataOutBase::VtkFlags flags;
    flags.time              = scene_time;
    flags.physical_units    = data_out.put_in_units_of(units, quantities);
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    write_vtu_pieces(directory,
                     data_out,
                     disc.mpi_communicator,
                     scene_time,
                     stem,
                     has_moments);
  }
} // namespace liftoff
