#pragma once

#include <deal.II/base/data_out_base.h>

#include <mpi.h>

#include <string>

namespace liftoff
{
  using namespace dealii;

  /// The liftoff that writes the files, as `liftoff --version` names it.
  extern const std::string written_by;

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
} // namespace liftoff
