#include <deal.II/base/data_out_base.h>
#include <deal.II/base/hdf5.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <liftoff/base/archives.h>
#include <liftoff/base/output_files.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/output/dowel_forces.h>
#include <liftoff/output/field_output.h>
#include <liftoff/output/resultant_sweep.h>
#include <liftoff/output/scene_view.h>
#include <liftoff/output/stress_resultants.h>
#include <liftoff/output/vtu_pieces.h>
#include <liftoff/time/plate_state.h>

#include <liftoff/version.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace liftoff
{
  namespace
  {
    /// Pressure of the springs on the plate, Gamma (w - g)^+ (Gamma (w - g)
    /// when bilateral): what the foundation's springs carry, positive in
    /// compression; and the uplift (g - w)^+, the gap between plate and bed
    /// where the plate is lifted. The same for the springs between a slab
    /// and its base, with w_slab - w_base for w (`between_layers`).
    class FoundationPressure : public DataPostprocessor<2>
    {
    public:
      FoundationPressure(const ContactLaw              &law,
                         const std::vector<std::string> names,
                         const bool                     between_layers)
          : law(law)
          , names(names)
          , between_layers(between_layers)
      {}

      std::vector<std::string>
      get_names() const override
      {
        return names;
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        // The points only where g needs them.
        return law.has_gap() ? update_values | update_quadrature_points
                             : update_values;
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &input,
        std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int q = 0; q < input.solution_values.size(); ++q)
          {
            const Vector<double> &u = input.solution_values[q];
            const double          g =
              (law.has_gap() ? law.gap_at(input.evaluation_points[q]) : 0.0);
            const double w =
              (between_layers
                 ? u[PlateFields::w_of(0)] - u[PlateFields::w_of(1)]
                 : u[PlateFields::bed_component(u.size())])
              - g;
            computed[q][0] = law.spring_pressure(w);
            computed[q][1] = std::max(-w, 0.0);
          }
      }

    private:
      const ContactLaw              &law;
      const std::vector<std::string> names;
      const bool                     between_layers;
    };


    /// The fields of a FieldDataOut with the plate placed at z = 0 in
    /// three dimensions, and two vectors added for ParaView (Glyph,
    /// WarpByVector): the rotation (psi_x, psi_y, 0) and the displacement
    /// (0, 0, w), w > 0 into the foundation. deal.II takes a vector of a 2d
    /// output to have two components, so (0, 0, w) needs the third
    /// dimension. The scalar fields stay as they are, so that old ParaView
    /// states keep working.
    class WarpableFields : public DataOutInterface<2, 3>
    {
    public:
      explicit WarpableFields(const FieldDataOut &plane)
          : names(plane.get_dataset_names())
          , ranges(plane.get_nonscalar_data_ranges())
      {
        const auto row = [&](const std::string &name) {
          const auto at = std::find(names.begin(), names.end(), name);
          Assert(at != names.end(), ExcInternalError());
          return static_cast<unsigned int>(at - names.begin());
        };
        const unsigned int n = names.size(), w = row("w"), psi_x = row("psi_x"),
                           psi_y = row("psi_y");
        for (const auto &flat : plane.get_patches())
          {
            DataOutBase::Patch<2, 3> patch;
            for (unsigned int v = 0; v < GeometryInfo<2>::vertices_per_cell;
                 ++v)
              patch.vertices[v] =
                Point<3>(flat.vertices[v][0], flat.vertices[v][1], 0.0);
            patch.neighbors            = flat.neighbors;
            patch.patch_index          = flat.patch_index;
            patch.n_subdivisions       = flat.n_subdivisions;
            patch.reference_cell       = flat.reference_cell;
            patch.points_are_available = flat.points_are_available;
            // The rows: the data sets, the two vectors, then (where the
            // mapping gave them) the coordinates of the points.
            const unsigned int n_points = flat.data.n_cols();
            patch.data.reinit(n + 6 + (flat.points_are_available ? 3 : 0),
                              n_points);
            for (unsigned int k = 0; k < n_points; ++k)
              {
                for (unsigned int r = 0; r < n; ++r)
                  patch.data(r, k) = flat.data(r, k);
                patch.data(n, k)     = flat.data(psi_x, k);
                patch.data(n + 1, k) = flat.data(psi_y, k);
                patch.data(n + 5, k) = flat.data(w, k);
                if (flat.points_are_available)
                  for (unsigned int d = 0; d < 2; ++d)
                    patch.data(n + 6 + d, k) = flat.data(n + d, k);
              }
            patches.push_back(std::move(patch));
          }
        for (const std::string vector : {"rotation", "displacement"})
          {
            ranges.emplace_back(
              names.size(),
              names.size() + 2,
              vector,
              DataComponentInterpretation::component_is_part_of_vector);
            names.insert(names.end(), 3, vector);
          }
      }

    protected:
      const std::vector<DataOutBase::Patch<2, 3>> &
      get_patches() const override
      {
        return patches;
      }

      std::vector<std::string>
      get_dataset_names() const override
      {
        return names;
      }

      std::vector<
        std::tuple<unsigned int,
                   unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>>
      get_nonscalar_data_ranges() const override
      {
        return ranges;
      }

    private:
      std::vector<DataOutBase::Patch<2, 3>> patches;
      std::vector<std::string>              names;
      std::vector<
        std::tuple<unsigned int,
                   unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>>
        ranges;
    };


    /// What each field is, for its unit and scale: the state's and the
    /// foundation's here, the moments' in StressResultants; rotation and
    /// displacement are WarpableFields' vectors.
    std::map<std::string, PhysicalUnits::Quantity>
    all_field_quantities()
    {
      using Quantity                             = PhysicalUnits::Quantity;
      std::map<std::string, Quantity> quantities = {
        {"w", Quantity::deflection},
        {"psi_x", Quantity::rotation},
        {"psi_y", Quantity::rotation},
        {"w_dot", Quantity::velocity},
        {"psi_x_dot", Quantity::angular_velocity},
        {"psi_y_dot", Quantity::angular_velocity},
        {"rotation", Quantity::rotation},
        {"displacement", Quantity::deflection},
        {"foundation_pressure", Quantity::pressure},
        {"uplift", Quantity::deflection},
        {"contact_status", Quantity::number},
        {"w_base", Quantity::deflection},
        {"psi_x_base", Quantity::rotation},
        {"psi_y_base", Quantity::rotation},
        {"w_base_dot", Quantity::velocity},
        {"psi_x_base_dot", Quantity::angular_velocity},
        {"psi_y_base_dot", Quantity::angular_velocity},
        {"interface_pressure", Quantity::pressure},
        {"interface_gap", Quantity::deflection},
        {"interface_contact_status", Quantity::number}};
      quantities.insert(StressResultants::quantities().begin(),
                        StressResultants::quantities().end());
      return quantities;
    }

    const std::map<std::string, PhysicalUnits::Quantity> field_quantities =
      all_field_quantities();


    /// Whether `filter` holds the data set `name`.
    bool
    filter_has(const DataOutBase::DataOutFilter &filter,
               const std::string                &name)
    {
      for (unsigned int i = 0; i < filter.n_data_sets(); ++i)
        if (filter.get_data_set_name(i) == name)
          return true;
      return false;
    }


    /// What the data sets of an HDF5 output do not say themselves, as
    /// attributes of the file `path`, for a reader of the .h5 alone (h5py):
    /// the time tau and the step on the file, the unit of each data set as
    /// its `units` (those of the VTU files), the scales the units are made
    /// of, and the moments' sign convention where they are written.
    void
    add_hdf5_metadata(const std::string                &path,
                      const DataOutBase::DataOutFilter &filter,
                      const PhysicalUnits              &units,
                      const double                      time,
                      const unsigned int                step)
    {
      using Quantity = PhysicalUnits::Quantity;
      HDF5::File file(path, HDF5::File::FileAccessMode::open);
      file.set_attribute("time", time);
      file.set_attribute("time_units", units.unit_symbol(Quantity::time));
      file.set_attribute("step", step);
      if (!units.is_physical())
        file.set_attribute("scales",
                           std::string(
                             "L the plate's length along x, F0 the "
                             "load scale, D the bending stiffness, "
                             "t0 = L^2 sqrt(rho H / D) (doc/model.md)"));
      file.set_attribute("liftoff", written_by);
      if (filter_has(filter, "M_xx"))
        file.set_attribute("moment_sign_convention",
                           StressResultants::sign_convention);
      file.open_dataset("nodes").set_attribute(
        "units", units.unit_symbol(Quantity::length));
      for (unsigned int i = 0; i < filter.n_data_sets(); ++i)
        {
          const auto q = field_quantities.find(filter.get_data_set_name(i));
          if (q != field_quantities.end())
            file.open_dataset(q->first).set_attribute(
              "units", units.unit_symbol(q->second));
        }
    }


    /// The entries of solution.xdmf for the outputs of `records` (after a
    /// resume), each with the sizes of its own .h5: an adaptive mesh has
    /// other sizes at every output. The fields are those of `filter`, the
    /// current output's. Outputs whose .h5 is gone are left out, rather
    /// than named with sizes nobody knows.
    std::vector<XDMFEntry>
    earlier_xdmf_entries(
      const std::string                                 &directory,
      const DataOutBase::DataOutFilter                  &filter,
      const std::vector<std::pair<double, std::string>> &records)
    {
      std::vector<XDMFEntry> entries;
      for (const auto &[time, master] : records)
        {
          const std::string name = master.substr(0, master.rfind('.')) + ".h5";
          if (!std::filesystem::exists(directory + "/" + name))
            continue;
          const HDF5::File file(directory + "/" + name,
                                HDF5::File::FileAccessMode::open);
          const auto       rows = [&](const std::string &data_set) {
            return file.open_dataset(data_set).get_dimensions();
          };
          XDMFEntry entry(
            name, name, time, rows("nodes")[0], rows("cells")[0], 2, 3);
          for (unsigned int i = 0; i < filter.n_data_sets(); ++i)
            entry.add_attribute(filter.get_data_set_name(i),
                                filter.get_data_set_dim(i));
          entries.push_back(entry);
        }
      return entries;
    }


    /// solution_NNNNN.h5 (`stem`.h5) from the patches of data_out, and its
    /// entry added to `xdmf_entries`, the entries of solution.xdmf; after a
    /// resume that is empty and is rebuilt first from the PVD `records` of
    /// the earlier outputs. The entries name the .h5 files without a folder,
    /// so readers look for them beside solution.xdmf. Collective.
    void
    write_hdf5(const std::string                                 &directory,
               const DataOutInterface<2, 3>                      &data_out,
               const PhysicalUnits                               &units,
               const MPI_Comm                                     comm,
               const double                                       time,
               const unsigned int                                 step,
               const std::string                                 &stem,
               const std::vector<std::pair<double, std::string>> &records,
               std::vector<XDMFEntry>                            &xdmf_entries)
    {
      // XDMF describes linear cells only: the subdivided patches are written
      // as bilinear quadrilaterals, whatever Field cells says.
      DataOutBase::DataOutFilter filter(
        DataOutBase::DataOutFilterFlags(false, true));
      data_out.write_filtered_data(filter);
      const std::string  name = stem + ".h5";
      const std::string  path = directory + "/" + name;
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      // write_hdf5_parallel is collective: every rank writes its part into
      // the same temporary file, which rank 0 completes and renames once all
      // are done.
      collective_attempt(comm, "Writing " + name + " failed", [&]() {
        data_out.write_hdf5_parallel(filter, path + ".tmp", comm);
      });
      collective_attempt(comm, "Writing " + name + " failed", [&]() {
        if (rank != 0)
          return;
        add_hdf5_metadata(path + ".tmp", filter, units, time, step);
        if (std::rename((path + ".tmp").c_str(), path.c_str()) != 0)
          throw std::runtime_error("cannot rename " + path + ".tmp");
        // After a resume rank 0, which alone writes solution.xdmf, first
        // rebuilds the entries of the earlier outputs.
        if (xdmf_entries.empty())
          xdmf_entries = earlier_xdmf_entries(directory, filter, records);
      });
      xdmf_entries.push_back(
        data_out.create_xdmf_entry(filter, name, time, comm));
    }


    /// solution.xdmf naming the HDF5 files of `entries`; rank 0 writes it.
    /// XDMF 3: the time series reader of Debian 12's meshio 5.0 refuses any
    /// other version ("Unknown XDMF version 2.0"); ParaView's XDMF readers
    /// read deal.II's entries either way.
    void
    write_xdmf(const std::string            &directory,
               const std::vector<XDMFEntry> &entries)
    {
      write_file_atomically(
        directory + "/solution.xdmf", [&](std::ostream &out) {
          out << "<?xml version=\"1.0\" ?>\n"
              << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
              << "<Xdmf Version=\"3.0\">\n"
              << "  <Domain>\n"
              << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
                 "CollectionType=\"Temporal\">\n";
          for (const auto &entry : entries)
            out << entry.get_xdmf_content(3, ReferenceCells::Quadrilateral);
          out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
        });
    }


  } // namespace


  void
  FieldOutput::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("VTU interval",
                      "10",
                      Patterns::Integer(0),
                      "Write fields every this many steps (and at the last "
                      "step); 0 writes none.");
    prm.declare_entry("Field cells",
                      "subdivided",
                      Patterns::Selection("subdivided|higher order"),
                      "How the VTU files draw a cell of the mesh: "
                      "`subdivided` into Subdivisions x Subdivisions "
                      "bilinear cells, or `higher order`: one Lagrange cell "
                      "of degree Subdivisions (VTK_LAGRANGE_QUADRILATERAL, "
                      "ParaView 5.5 or later; its Nonlinear Subdivision "
                      "Level sets how finely it is drawn).");
    prm.declare_entry("Subdivisions",
                      "0",
                      Patterns::Integer(0, 16),
                      "Subdivisions of each cell in the field files; 0 takes "
                      "the polynomial degree, which shows a Q2 field "
                      "exactly with higher-order cells.");
    prm.declare_entry("HDF5 output",
                      "false",
                      Patterns::Bool(),
                      "Also write every field output as "
                      "solution_NNNNN.h5 (one file for all ranks, MPI-IO; "
                      "tau and the units as HDF5 attributes) and the time "
                      "series solution.xdmf (XDMF 3), which ParaView "
                      "(Xdmf3ReaderT) and meshio (TimeSeriesReader) read: "
                      "doc/viewing.md.");
    prm.declare_entry(
      "Moment fields",
      "true",
      Patterns::Bool(),
      "Also write the moments M_xx, M_yy, M_xy (units F0), the shear "
      "forces Q_x, Q_y (F0/L, from the shear strain the element uses: the "
      "assumed strain with mitc), the principal moments M_1 >= M_2 and the "
      "angle of M_1 from x (degrees), and the bending stresses at the "
      "bed-side face sigma_xx, sigma_yy, sigma_xy = 6 M / Delta^2 and the "
      "largest tension on either face sigma_max (F0/L^2). A positive moment "
      "puts the bed-side face in tension (doc/model.md, \"Moments, shear "
      "forces and stresses\"). false leaves them out of the field files.");
    prm.declare_entry(
      "Face stress fields",
      "false",
      Patterns::Bool(),
      "With `Moment fields`, also write the largest principal stress at "
      "each face: sigma_1_top at the face away from the bed (top-down "
      "cracking) and sigma_1_bottom at the bed-side face (bottom-up), "
      "positive in tension (F0/L^2; Pa in an SI scene), each slab's with "
      "its own thickness and a temperature profile's stress of that face "
      "(doc/model.md, \"Stresses as design quantities\").");
  }


  void
  FieldOutput::parse_parameters(ParameterHandler &prm, const SceneView &scene)
  {
    plate          = scene.plate;
    dowels         = &scene.dowels;
    writes_moments = prm.get_bool("Moment fields");
    writes_faces   = prm.get_bool("Face stress fields");
    AssertThrow(writes_moments || !writes_faces,
                ExcMessage("Output/Face stress fields = true adds to the "
                           "moment fields: it needs Output/Moment fields = "
                           "true."));
    interval           = prm.get_integer("VTU interval");
    higher_order_cells = prm.get("Field cells") == "higher order";
    subdivisions       = prm.get_integer("Subdivisions");
    writes_hdf5        = prm.get_bool("HDF5 output");
  }


  bool
  FieldOutput::is_due(const unsigned int step, const bool is_last_step) const
  {
    return is_due_every(interval, step, is_last_step);
  }


  namespace
  {
    DataOutBase::VtkFlags
    vtk_flags(const double                              time,
              const unsigned int                        step,
              const bool                                higher_order_cells,
              const std::map<std::string, std::string> &units)
    {
      DataOutBase::VtkFlags flags;
      flags.time                     = time;
      flags.cycle                    = step;
      flags.write_higher_order_cells = higher_order_cells;
      flags.physical_units           = units;
      // zlib's fastest level: its best compression took 40 % of the field
      // output's time (Example 2 pulse, 100 files) for files 6 % smaller.
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      return flags;
    }


    /// The stem of the dowels' file of the output whose plate file is
    /// `master` (solution_NNNNN.pvtu): dowels_NNNNN.
    std::string
    dowel_file_of(const std::string &master)
    {
      const std::string plate = "solution_";
      return "dowels_"
             + master.substr(plate.size(),
                             master.size() - plate.size()
                               - std::string(".pvtu").size());
    }


    // Each cell's level above the uniform mesh of the scene (Mesh
    // refinement).
    Vector<float>
    refinement_levels(const Discretization &disc)
    {
      Vector<float> level(disc.triangulation.n_active_cells());
      for (const auto &cell : disc.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          level[cell->active_cell_index()] =
            static_cast<float>(cell->level()) - disc.initial_level();
      return level;
    }
  } // namespace


  void
  FieldOutput::build_patches(FieldDataOut          &plane,
                             const Discretization  &disc,
                             const Bed             &foundation,
                             const LA::MPI::Vector &solution,
                             const LA::MPI::Vector &velocity) const
  {
    plane.attach_dof_handler(disc.dof_handler);
    const unsigned int layers =
      PlateFields::n_layers(disc.dof_handler.get_fe());
    plane.add_data_vector(solution, PlateFields::names(layers));
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      scalar(PlateFields::n_components_of(layers),
             DataComponentInterpretation::component_is_scalar);
    plane.add_data_vector(velocity,
                          PlateFields::names(layers, "_dot"),
                          DataOut<2>::type_dof_data,
                          scalar);
    const FoundationPressure pressure(foundation.law(),
                                      {"foundation_pressure", "uplift"},
                                      false);
    plane.add_data_vector(solution, pressure);
    // A base the slab can lift off: its springs' pressure, the gap between
    // slab and base, and which cells of the interface are in contact.
    std::unique_ptr<FoundationPressure> on_base;
    Vector<float>                       base_contact;
    if (interface != nullptr)
      {
        on_base = std::make_unique<FoundationPressure>(
          interface->law(),
          std::vector<std::string>{"interface_pressure", "interface_gap"},
          true);
        plane.add_data_vector(solution, *on_base);
        base_contact = interface->diagnostics().contact_fraction_per_cell();
        plane.add_data_vector(base_contact, "interface_contact_status");
      }
    const StressResultants resultants(plate,
                                      disc.mapping(),
                                      disc.element().shear_integration(),
                                      solution,
                                      free_bending,
                                      writes_faces);
    if (writes_moments)
      plane.add_data_vector(solution, resultants);
    const Vector<float> contact =
      foundation.diagnostics().contact_fraction_per_cell();
    plane.add_data_vector(contact, "contact_status");
    Vector<float> subdomain(disc.triangulation.n_active_cells());
    subdomain = disc.triangulation.locally_owned_subdomain();
    plane.add_data_vector(subdomain, "subdomain");
    const Vector<float> level = refinement_levels(disc);
    plane.add_data_vector(level, "refinement_level");
    plane.build_patches(disc.mapping(),
                        subdivisions > 0 ? subdivisions
                                         : disc.element().degree());
    plane.sort_patches(disc.locally_owned_cells());
  }


  void
  FieldOutput::write(const std::string     &directory,
                     const Discretization  &disc,
                     const Bed             &foundation,
                     const LA::MPI::Vector &solution,
                     const LA::MPI::Vector &velocity,
                     const double           time,
                     const unsigned int     step)
  {
    FieldDataOut plane;
    build_patches(plane, disc, foundation, solution, velocity);
    std::map<std::string, std::string> symbols =
      plane.put_in_units_of(units, field_quantities);
    for (const std::string vector : {"rotation", "displacement"})
      symbols[vector] = units.unit_symbol(field_quantities.at(vector));
    WarpableFields data_out(plane);

    data_out.set_flags(vtk_flags(time, step, higher_order_cells, symbols));

    const MPI_Comm    comm = disc.mpi_communicator;
    const std::string stem = "solution_" + Utilities::int_to_string(step, 5);
    const std::string master =
      write_vtu_pieces(directory, data_out, comm, time, stem, writes_moments);
    if (!dowels->sites().empty())
      write_dowel_points(
        directory, *dowels, solution, units, comm, time, dowel_file_of(master));
    if (writes_hdf5)
      write_hdf5(directory,
                 data_out,
                 units,
                 comm,
                 time,
                 step,
                 stem,
                 records,
                 xdmf_entries);
    records.emplace_back(time, master);
    write_record(directory,
                 comm,
                 since_record_written.wall_time() >= rewrite_interval);
  }


  void
  FieldOutput::write_record(const std::string &directory,
                            const MPI_Comm     comm,
                            const bool         is_due)
  {
    if (records.empty())
      return;
    collective_attempt(comm, "", [&]() {
      if (!is_due || Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      write_file_atomically(directory + "/solution.pvd",
                            [&](std::ostream &out) {
                              DataOutBase::write_pvd_record(out, records);
                            });
      if (!dowels->sites().empty())
        {
          std::vector<std::pair<double, std::string>> dowel_records;
          for (const auto &[time, master] : records)
            dowel_records.emplace_back(time, dowel_file_of(master) + ".vtu");
          write_file_atomically(directory + "/dowels.pvd",
                                [&](std::ostream &out) {
                                  DataOutBase::write_pvd_record(out,
                                                                dowel_records);
                                });
        }
      // After a resume the entries wait for the next output (write_hdf5),
      // and the earlier run's file stays until then.
      if (writes_hdf5 && !xdmf_entries.empty())
        write_xdmf(directory, xdmf_entries);
    });
    if (is_due)
      since_record_written.restart();
  }


  void
  FieldOutput::write_in_units_of(const PhysicalUnits &scene_units)
  {
    units = scene_units;
  }


  void
  FieldOutput::setup(const SceneView &scene, const std::string &folder)
  {
    directory = folder;
    interface = scene.interface;
    mesh_changed(scene);
  }


  void
  FieldOutput::mesh_changed(const SceneView &scene)
  {
    const Discretization &disc = scene.discretization;
    discretization             = &disc;
    disc.reinit_ghosted_vector(ghosted_velocity);
  }


  void
  FieldOutput::execute(const StepData &step)
  {
    if (directory.empty()
        || !is_due(step.state.clock.step(), step.state.clock.is_at_end()))
      return;
    ghosted_velocity = step.state.v;
    free_bending     = step.resultants.free_bending();
    write(directory,
          *discretization,
          step.scene.bed,
          step.state.ghosted_u,
          ghosted_velocity,
          units.scale(PhysicalUnits::Quantity::time) * step.state.clock.tau(),
          step.state.clock.step());
  }


  void
  FieldOutput::flush()
  {
    if (!directory.empty())
      write_record(directory, discretization->mpi_communicator, true);
  }


  void
  FieldOutput::save(OutputArchive &archive) const
  {
    archive << records;
  }


  void
  FieldOutput::load(InputArchive &archive)
  {
    archive >> records;
  }
} // namespace liftoff
