#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <liftoff/field_output.h>
#include <liftoff/output_files.h>

#include <fstream>

namespace liftoff
{
  namespace
  {
    /// Pressure of the springs on the plate, Gamma w^+ (Gamma w when
    /// bilateral): what the foundation carries, positive in compression.
    class FoundationPressure : public DataPostprocessorScalar<2>
    {
    public:
      explicit FoundationPressure(const TensionlessWinklerFoundation &f)
          : DataPostprocessorScalar<2>("foundation_pressure", update_values)
          , foundation(f)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &input,
        std::vector<Vector<double>>              &computed) const override
      {
        using Model = TensionlessWinklerFoundation::Model;
        for (unsigned int q = 0; q < input.solution_values.size(); ++q)
          {
            const double w = input.solution_values[q][0];
            computed[q][0] = (foundation.model == Model::none
                                ? 0.0
                                : foundation.stiffness
                                    * (foundation.model == Model::bilateral
                                         ? w
                                         : std::max(w, 0.0)));
          }
      }

    private:
      const TensionlessWinklerFoundation &foundation;
    };
  } // namespace


  void
  FieldOutput::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("VTU interval",
                      "10",
                      Patterns::Integer(0),
                      "Write fields every this many steps (and at the last "
                      "step); 0 writes none.");
  }


  void
  FieldOutput::parse_parameters(ParameterHandler &prm)
  {
    interval = prm.get_integer("VTU interval");
  }


  bool
  FieldOutput::is_due(const unsigned int step, const bool is_last_step) const
  {
    return is_due_every(interval, step, is_last_step);
  }


  void
  FieldOutput::write(const std::string                  &directory,
                     const Discretization               &disc,
                     const TensionlessWinklerFoundation &foundation,
                     const LA::MPI::Vector              &solution,
                     const LA::MPI::Vector              &velocity,
                     const double                        time,
                     const unsigned int                  step)
  {
    DataOut<2> data_out;
    data_out.attach_dof_handler(disc.dof_handler);
    data_out.add_data_vector(solution,
                             std::vector<std::string>{"w", "psi_x", "psi_y"});
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      scalar(3, DataComponentInterpretation::component_is_scalar);
    data_out.add_data_vector(velocity,
                             std::vector<std::string>{"w_dot",
                                                      "psi_x_dot",
                                                      "psi_y_dot"},
                             DataOut<2>::type_dof_data,
                             scalar);
    const FoundationPressure pressure(foundation);
    data_out.add_data_vector(solution, pressure);
    const Vector<float> contact = foundation.contact_fraction_per_cell();
    data_out.add_data_vector(contact, "contact_status");
    Vector<float> subdomain(disc.triangulation.n_active_cells());
    subdomain = disc.triangulation.locally_owned_subdomain();
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(disc.mapping, disc.degree());

    DataOutBase::VtkFlags flags;
    flags.time  = time;
    flags.cycle = step;
    data_out.set_flags(flags);

    // Every file goes to a temporary name first and is renamed when
    // complete, and the record naming the pieces is written only after every
    // rank has renamed its piece: a viewer never finds a half-written file.
    const MPI_Comm     comm    = disc.mpi_communicator;
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const std::string  stem  = "solution_" + Utilities::int_to_string(step, 5);
    const auto         piece = [&](const unsigned int r) {
      return stem + "." + Utilities::int_to_string(r, 4) + ".vtu";
    };
    // A failure on one rank stops all of them here (this is also the
    // barrier before the record), not in a later collective call.
    const std::string what = "Writing " + stem + " failed";
    collective_attempt(comm, what, [&]() {
      write_file_atomically(directory + "/" + piece(rank),
                            [&](std::ostream &out) {
                              data_out.write_vtu(out);
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
        data_out.write_pvtu_record(out, pieces);
      });
    });
    records.emplace_back(time, master);
    write_record(directory, comm);
  }


  void
  FieldOutput::write_record(const std::string &directory,
                            const MPI_Comm     comm) const
  {
    if (records.empty())
      return;
    collective_attempt(comm, "", [&]() {
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        write_file_atomically(directory + "/solution.pvd",
                              [&](std::ostream &out) {
                                DataOutBase::write_pvd_record(out, records);
                              });
    });
  }


  void
  FieldOutput::setup(const Discretization &disc, const std::string &folder)
  {
    discretization = &disc;
    directory      = folder;
    disc.reinit_ghosted_vector(ghosted_velocity);
  }


  void
  FieldOutput::execute(const StepData &step)
  {
    if (directory.empty() || !is_due(step.state.step, step.is_last_step))
      return;
    ghosted_velocity = step.state.v;
    write(directory,
          *discretization,
          step.foundation,
          step.state.ghosted_u,
          ghosted_velocity,
          step.state.tau,
          step.state.step);
  }


  void
  FieldOutput::flush()
  {
    if (!directory.empty())
      write_record(directory, discretization->mpi_communicator);
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
