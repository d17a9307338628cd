#include <deal.II/base/mpi.h>

#include <liftoff/base/output_files.h>
#include <liftoff/output/stress_resultants.h>
#include <liftoff/output/vtu_pieces.h>

#include <liftoff/version.h>

#include <sstream>

namespace liftoff
{
  const std::string written_by =
    LIFTOFF_VERSION " (git " LIFTOFF_GIT_COMMIT ")";


  namespace
  {
    /// A .vtu or .pvtu as deal.II writes it, with two additions. ParaView
    /// takes the time of such files opened as a series (without the .pvd)
    /// from a field-data array named TimeValue, in the .pvtu itself for a
    /// .pvtu; deal.II names its array TIME and writes it in the pieces only.
    /// So TimeValue is added, beside TIME in a piece and as the .pvtu's own
    /// field data. And a comment names the version and git commit of the
    /// liftoff that wrote the file.
    std::string
    with_liftoff_metadata(const std::string &vtk,
                          const double       time,
                          const bool         has_moments)
    {
      std::ostringstream array;
      array.precision(17);
      array << "\n<DataArray type=\"Float64\" Name=\"TimeValue\" "
               "NumberOfTuples=\"1\" format=\"ascii\">"
            << time << "</DataArray>";
      std::string       text       = vtk;
      const std::string field_data = "<FieldData>";
      std::size_t       at         = text.find(field_data);
      if (at != std::string::npos)
        text.insert(at + field_data.size(), array.str());
      else
        {
          at = text.find("<PUnstructuredGrid");
          Assert(at != std::string::npos, ExcInternalError());
          at = text.find('>', at) + 1;
          text.insert(at, "\n" + field_data + array.str() + "\n</FieldData>");
        }
      const std::size_t line_end = text.find('\n');
      return text.insert(
        line_end + 1,
        "<!-- liftoff " + written_by + " -->\n"
          + (has_moments
               ? "<!-- moments: " + StressResultants::sign_convention + " -->\n"
               : ""));
    }
  } // namespace


  std::map<std::string, std::string>
  FieldDataOut::put_in_units_of(
    const PhysicalUnits                                  &units,
    const std::map<std::string, PhysicalUnits::Quantity> &quantities)
  {
    using Quantity                           = PhysicalUnits::Quantity;
    const std::vector<std::string>     names = get_dataset_names();
    std::map<std::string, std::string> symbols;
    std::vector<double>                row_scales(names.size(), 1.0);
    for (unsigned int r = 0; r < names.size(); ++r)
      if (const auto q = quantities.find(names[r]); q != quantities.end())
        {
          symbols[names[r]] = units.unit_symbol(q->second);
          row_scales[r]     = units.scale(q->second);
        }
    if (!units.is_physical())
      return symbols;
    const double length = units.scale(Quantity::length);
    for (auto &patch : patches)
      {
        for (auto &vertex : patch.vertices)
          vertex *= length;
        // The rows: the data sets, then (where the mapping gave them) the
        // coordinates of the points.
        for (unsigned int r = 0; r < patch.data.n_rows(); ++r)
          {
            const double scale = r < names.size() ? row_scales[r] : length;
            for (unsigned int k = 0; k < patch.data.n_cols(); ++k)
              patch.data(r, k) *= scale;
          }
      }
    return symbols;
  }


  void
  FieldDataOut::sort_patches(
    const std::vector<DoFHandler<2>::active_cell_iterator> &cells)
  {
    if (cells.empty())
      return;
    const Triangulation<2>   &tria = cells.front()->get_triangulation();
    std::vector<unsigned int> position(tria.n_active_cells(),
                                       numbers::invalid_unsigned_int);
    for (unsigned int k = 0; k < cells.size(); ++k)
      position[cells[k]->active_cell_index()] = k;
    // Patch i is of the i-th own cell in deal.II's order.
    std::vector<unsigned int> new_index;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        new_index.push_back(position[cell->active_cell_index()]);
    AssertThrow(new_index.size() == patches.size(), ExcInternalError());
    std::vector<Patch> sorted(patches.size());
    for (unsigned int i = 0; i < patches.size(); ++i)
      {
        Patch &patch      = sorted[new_index[i]];
        patch             = std::move(patches[i]);
        patch.patch_index = new_index[i];
        for (unsigned int &neighbor : patch.neighbors)
          if (neighbor != Patch::no_neighbor)
            neighbor = new_index[neighbor];
      }
    patches.swap(sorted);
  }


  // Every file goes to a temporary name first and is renamed when
  // complete, and the record naming the pieces is written only after every
  // rank has renamed its piece: a viewer never finds a half-written file.
  // Returns the name of the record (the .pvtu).
  void
  write_points_file(const std::string            &directory,
                    const DataOutInterface<0, 2> &points,
                    const MPI_Comm                comm,
                    const double                  time,
                    const std::string            &name)
  {
    collective_attempt(comm, "Writing " + name + " failed", [&]() {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      write_file_atomically(directory + "/" + name, [&](std::ostream &out) {
        std::ostringstream vtu;
        points.write_vtu(vtu);
        out << with_liftoff_metadata(vtu.str(), time, false);
      });
    });
  }


  template <int spacedim>
  std::string
  write_vtu_pieces(const std::string                   &directory,
                   const DataOutInterface<2, spacedim> &data_out,
                   const MPI_Comm                       comm,
                   const double                         time,
                   const std::string                   &stem,
                   const bool                           has_moments)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const auto         piece   = [&](const unsigned int r) {
      return stem + "." + Utilities::int_to_string(r, 4) + ".vtu";
    };
    // A failure on one rank stops all of them here (this is also the
    // barrier before the record), not in a later collective call.
    const std::string what = "Writing " + stem + " failed";
    collective_attempt(comm, what, [&]() {
      write_file_atomically(
        directory + "/" + piece(rank), [&](std::ostream &out) {
          std::ostringstream vtu;
          data_out.write_vtu(vtu);
          out << with_liftoff_metadata(vtu.str(), time, has_moments);
        });
    });
    const std::string master = stem + ".pvtu";
    collective_attempt(comm, what, [&]() {
      if (rank != 0)
        return;
      std::vector<std::string> pieces;
      for (unsigned int r = 0; r < n_ranks; ++r)
        pieces.push_back(piece(r));
      write_file_atomically(directory + "/" + master, [&](std::ostream &out) {
        std::ostringstream pvtu;
        data_out.write_pvtu_record(pvtu, pieces);
        out << with_liftoff_metadata(pvtu.str(), time, has_moments);
      });
    });
    return master;
  }


  template std::string
  write_vtu_pieces(const std::string &,
                   const DataOutInterface<2, 2> &,
                   const MPI_Comm,
                   const double,
                   const std::string &,
                   const bool);
  template std::string
  write_vtu_pieces(const std::string &,
                   const DataOutInterface<2, 3> &,
                   const MPI_Comm,
                   const double,
                   const std::string &,
                   const bool);
} // namespace liftoff
