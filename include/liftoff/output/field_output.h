#pragma once

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <liftoff/base/archive_types.h>
#include <liftoff/base/physical_units.h>
#include <liftoff/contact/bed.h>
#include <liftoff/contact/joint_dowels.h>
#include <liftoff/fem/discretization.h>
#include <liftoff/fem/mindlin_plate.h>
#include <liftoff/loads/free_bending.h>
#include <liftoff/output/output.h>
#include <liftoff/output/vtu_pieces.h>

#include <string>
#include <utility>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * Fields for ParaView: w, psi_x, psi_y, their velocities, the foundation
   * pressure and the contact status (fraction of each cell's Gauss points in
   * contact), the moments, shear forces and stresses (StressResultants,
   * unless `Moment fields = false`), as VTU (plus PVTU under MPI) every k steps
   * and a PVD record naming them; with dowels (Slabs/Dowels) their forces
   * as points beside each (dowels_NNNNN.vtu, dowels.pvd). The record is
   * replaced at most once a second of wall time and at flush(), as history.csv
   * is: rewriting it after every file made the output quadratic in the number
   * of files (2 001 outputs of Example 2: 34 % of the run's `perf` samples in
   * the record) and cost a file creation per output.
   */
  class FieldOutput : public Output
  {
  public:
    /// Entries of the `Output` subsection.
    static void
    declare_parameters(ParameterHandler &prm);
    /// The moment fields need the scene's plate (its section); the
    /// dowels' files its dowels (none: no dowel files).
    void
    parse_parameters(ParameterHandler &prm, const SceneView &scene) override;

    /// Whether step `step` is written (the last step always is, unless the
    /// interval is 0).
    bool
    is_due(const unsigned int step, const bool is_last_step) const;

    /// The fields of the state, in the scene's units (write_in_units_of())
    /// at `time`, given in them.
    void
    write(const std::string     &directory,
          const Discretization  &discretization,
          const Bed             &foundation,
          const LA::MPI::Vector &ghosted_solution,
          const LA::MPI::Vector &ghosted_velocity,
          const double           time,
          const unsigned int     step);

    /// Write the PVD file with the records so far (none: no file), and
    /// solution.xdmf with HDF5 output, if `is_due` on rank 0. Collective, as
    /// is write().
    void
    write_record(const std::string &directory,
                 const MPI_Comm     comm,
                 const bool         is_due);

    /// An SI scene's files hold SI values, coordinates in metres and
    /// times in seconds, each field with its unit (VTU `units`, HDF5
    /// attributes).
    void
    write_in_units_of(const PhysicalUnits &scene_units) override;

    void
    setup(const SceneView &scene, const std::string &directory) override;
    void
    mesh_changed(const SceneView &scene) override;
    /// write() when the step is due and the run writes files.
    void
    execute(const StepData &step) override;
    /// write_record() now.
    void
    flush() override;
    /// The records of the PVD file; after load(), flush() rewrites it
    /// with them.
    void
    save(OutputArchive &archive) const override;
    void
    load(InputArchive &archive) override;

  private:
    /// The springs between the slab and a base it can lift off (none:
    /// nullptr), whose pressure, gap and contact the files add.
    const Bed *interface = nullptr;
    /// The fields of the state, the foundation, the moments and the cells
    /// in `plane`, with its patches built (the postprocessors and cell
    /// vectors it reads live here until then).
    void
    build_patches(FieldDataOut          &plane,
                  const Discretization  &disc,
                  const Bed             &foundation,
                  const LA::MPI::Vector &solution,
                  const LA::MPI::Vector &velocity) const;

    unsigned int interval           = 10;
    bool         higher_order_cells = false;
    unsigned int subdivisions       = 0;
    bool         writes_hdf5        = false;
    bool         writes_moments     = true;
    /// Output/Face stress fields: sigma_1_top and sigma_1_bottom too.
    bool                                        writes_faces = false;
    MindlinPlate                                plate;
    PhysicalUnits                               units;
    std::vector<std::pair<double, std::string>> records;
    const JointDowels                          *dowels = nullptr;
    std::string                                 directory;
    const Discretization                       *discretization = nullptr;
    /// The velocity with ghosts, filled only for the steps written.
    LA::MPI::Vector ghosted_velocity;
    /// The step's temperature loads, for the moments and stresses.
    FreeBendingField free_bending;
    /// The entries of solution.xdmf (HDF5 output); rebuilt from `records`
    /// and the sizes of their .h5 files after a resume.
    std::vector<XDMFEntry> xdmf_entries;
    /// Since the PVD file was last written; rank 0's clock decides.
    Timer since_record_written;
  };
} // namespace liftoff
