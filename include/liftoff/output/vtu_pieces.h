#pragma once

#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>

#include <liftoff/base/physical_units.h>

#include <mpi.h>

#include <map>
#include <string>

namespace liftoff
{
  using namespace dealii;

  /// The liftoff that writes the files, as `liftoff --version` names it.
  extern const std::string written_by;

  /**
   * DataOut whose patches are put in a scene's units after
   * build_patches(), so that an SI run's field files hold metres, pascals,
   * seconds as its history does; and whose patches, names and vector ranges
   * are public, for outputs that build other patches from them.
   */
  class FieldDataOut : public DataOut<2>
  {
  public:
    using DataOut<2>::get_dataset_names;
    using DataOut<2>::get_nonscalar_data_ranges;
    using DataOut<2>::get_patches;

    /// Scales the coordinates and the data sets that `quantities` names
    /// (others are numbers: ranks, levels) to `units`, and returns every
    /// named data set's unit for DataOutBase::VtkFlags::physical_units. A
    /// dimensionless scene's patches stay as they are, bit for bit.
    std::map<std::string, std::string>
    put_in_units_of(
      const PhysicalUnits                                  &units,
      const std::map<std::string, PhysicalUnits::Quantity> &quantities);

    /// Puts the patches of build_patches() (one per own cell, in deal.II's
    /// order of the active cells) in the order of `cells`, this rank's own
    /// cells. deal.II's order depends on how a mesh was reached: a resumed
    /// adaptive run, whose mesh is loaded from its checkpoint, then writes
    /// the cells in the order of the run without a stop. (deal.II 9.4's
    /// DataOut::set_cell_selection() takes the cells in its own order only.)
    void
    sort_patches(const std::vector<DoFHandler<2>::active_cell_iterator> &cells);
  };


  /// The pieces of one output (stem.NNNN.vtu, one per rank) and the .pvtu
  /// that names them, each written atomically and with liftoff's metadata
  /// (the time as ParaView reads it, the version, and with `has_moments`
  /// the moments' sign convention). Collective; a failure on any rank stops
  /// all of them. Returns the name of the .pvtu.
  template <int spacedim>
  std::string
  write_vtu_pieces(const std::string                   &directory,
                   const DataOutInterface<2, spacedim> &data_out,
                   const MPI_Comm                       comm,
                   const double                         time,
                   const std::string                   &stem,
                   const bool                           has_moments);

  /// Rank 0's points (the others' are not written) as the file `name`,
  /// atomically and with liftoff's metadata: one file, which viewers read
  /// where an empty piece of a .pvtu stops them. Collective.
  void
  write_points_file(const std::string            &directory,
                    const DataOutInterface<0, 2> &points,
                    const MPI_Comm                comm,
                    const double                  time,
                    const std::string            &name);
} // namespace liftoff
