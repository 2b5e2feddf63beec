#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/particles/data_out.h>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <qsmpm/base/utilities.h>
#include <qsmpm/io/checkpoint.h>
#include <qsmpm/io/output_writer.h>

namespace qsmpm
{
  template <int dim>
  void
  OutputWriter<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    {
      prm.add_parameter("Directory",
                        directory,
                        "Where all output goes (created if needed; relative "
                        "to the working directory).",
                        Patterns::Anything());
      prm.add_parameter("Interval",
                        interval,
                        "Write point and grid fields every this many steps "
                        "(and after the last); 0 writes none. reactions.csv "
                        "is written every step.",
                        Patterns::Integer(0));
      prm.add_parameter("Write increment",
                        write_increment,
                        "Also write the grid displacement increment.",
                        Patterns::Bool());
      prm.add_parameter(
        "Checkpoint interval",
        checkpoint_interval,
        "K > 0: every K accepted load steps, write a checkpoint (the grid, "
        "all material points with all their properties, the load stepping "
        "state) into <Directory>/checkpoint-<step>; the newest two are "
        "kept. A checkpoint is written into <Directory>/checkpoint.tmp and "
        "renamed only when complete, so a crash never damages the last "
        "one. Resume with 'qsmpm --resume file.prm' (also on another number "
        "of MPI ranks); the rows of reactions.csv after the checkpoint are "
        "then replaced. 0: no checkpoints.",
        Patterns::Integer(0));
      prm.add_parameter(
        "Probe points",
        probe_points,
        "Positions in the initial configuration, separated by semicolons "
        "(\"10,0.5; 5,1\"): after every step, probes.csv gets the "
        "current position, the displacement, the stress (stress_xx, "
        "...) and the model's output fields (e.g. pore_pressure) of the "
        "material point nearest to each. Empty: no probes.",
        Patterns::Anything());
    }
    prm.leave_subsection();
  }



  template <int dim>
  std::vector<Point<dim>>
  OutputWriter<dim>::Parameters::probe_positions() const
  {
    std::vector<Point<dim>> positions;
    for (const auto &text :
         dealii::Utilities::split_string_list(probe_points, ';'))
      if (!text.empty())
        positions.push_back(
          Utils::parse_point<dim>(text, "Output/Probe points"));
    return positions;
  }



  template <int dim>
  OutputWriter<dim>::OutputWriter(const Parameters &parameters,
                                  const MPI_Comm    communicator)
    : parameters(parameters)
    , communicator(communicator)
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(parameters.directory, error);
        AssertThrow(!error,
                    ExcMessage("Cannot create the output directory <" +
                               parameters.directory + ">: " + error.message()));
      }
    MPI_Barrier(communicator);
  }



  template <int dim>
  bool
  OutputWriter<dim>::fields_due(const unsigned int step) const
  {
    return parameters.interval > 0 && step % parameters.interval == 0;
  }



  namespace
  {
    /**
     * deal.II's particle output with the model's output fields appended:
     * the stored properties of each point as Particles::DataOut writes
     * them, then the values of ConstitutiveModel::output_fields(), which
     * are computed here from the committed state and never stored.
     */
    template <int dim>
    class PointDataOut : public Particles::DataOut<dim>
    {
    public:
      explicit PointDataOut(const MaterialPointSet<dim> &points)
      {
        const auto &handler = points.get_particle_handler();
        this->build_patches(handler,
                            points.get_layout().component_names(dim),
                            points.get_layout().component_interpretations());
        patches = Particles::DataOut<dim>::get_patches();
        names   = Particles::DataOut<dim>::get_dataset_names();

        const PropertyLayout output_layout = points.output_layout();
        const unsigned int   n_output      = output_layout.size();
        if (n_output == 0)
          return;
        for (const auto &name : output_layout.component_names(dim))
          names.push_back(name);

        // The patches are in the order of the particles in the handler.
        std::vector<double> values(n_output);
        unsigned int        i = 0;
        for (const auto &particle : handler)
          {
            points.compute_output_fields(particle, ArrayView<double>(values));
            auto              &data = patches[i++].data;
            const unsigned int n    = data.n_rows();
            Table<2, float>    extended(n + n_output, 1);
            for (unsigned int c = 0; c < n; ++c)
              extended(c, 0) = data(c, 0);
            for (unsigned int c = 0; c < n_output; ++c)
              extended(n + c, 0) = values[c];
            data.swap(extended);
          }
        AssertThrow(i == patches.size(), ExcInternalError());
      }

    protected:
      const std::vector<DataOutBase::Patch<0, dim>> &
      get_patches() const override
      {
        return patches;
      }

      std::vector<std::string>
      get_dataset_names() const override
      {
        return names;
      }

    private:
      std::vector<DataOutBase::Patch<0, dim>> patches;
      std::vector<std::string>                names;
    };
  } // namespace



  template <int dim>
  void
  OutputWriter<dim>::write_points(const MaterialPointSet<dim> &points,
                                  const unsigned int           step,
                                  const double                 load_factor)
  {
    PointDataOut<dim> data_out(points);
    const std::string name = data_out.write_vtu_with_pvtu_record(
      parameters.directory + "/", "points", step, communicator, 5);
    point_records.emplace_back(load_factor, name);
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ofstream pvd(parameters.directory + "/points.pvd");
        DataOutBase::write_pvd_record(pvd, point_records);
      }
  }



  template <int dim>
  void
  OutputWriter<dim>::write_increment(const BackgroundGrid<dim>           &grid,
                                     const TrilinosWrappers::MPI::Vector &du,
                                     const unsigned int                   step,
                                     const double load_factor)
  {
    if (!parameters.write_increment)
      return;
    TrilinosWrappers::MPI::Vector ghosted(grid.locally_owned_dofs(),
                                          grid.locally_relevant_dofs(),
                                          communicator);
    ghosted = du;
    DataOut<dim> data_out;
    data_out.attach_dof_handler(grid.get_dof_handler());
    // One vector per body on a multi-field grid.
    std::vector<std::string> names;
    for (unsigned int b = 0; b < grid.n_bodies(); ++b)
      names.insert(names.end(),
                   dim,
                   grid.n_bodies() == 1 ?
                     std::string("displacement_increment") :
                     "displacement_increment_body_" + std::to_string(b));
    data_out.add_data_vector(
      ghosted,
      names,
      DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        grid.n_node_dofs(),
        DataComponentInterpretation::component_is_part_of_vector));
    data_out.build_patches();
    const std::string name = data_out.write_vtu_with_pvtu_record(
      parameters.directory + "/", "increment", step, communicator, 5);
    increment_records.emplace_back(load_factor, name);
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ofstream pvd(parameters.directory + "/increment.pvd");
        DataOutBase::write_pvd_record(pvd, increment_records);
      }
  }



  template <int dim>
  void
  OutputWriter<dim>::write_reactions(
    const unsigned int                 step,
    const double                       load_factor,
    const std::vector<std::string>    &names,
    const std::vector<Tensor<1, dim>> &forces,
    const std::vector<std::string>    &column_names,
    const std::vector<double>         &columns,
    const double                       imbalance)
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    static const char *const components[3] = {"x", "y", "z"};
    if (!reactions_file)
      {
        reactions_file = std::make_unique<std::ofstream>(parameters.directory +
                                                         "/reactions.csv");
        AssertThrow(*reactions_file,
                    ExcMessage("Cannot write " + parameters.directory +
                               "/reactions.csv"));
        *reactions_file << "step,load_factor";
        for (const auto &name : names)
          for (unsigned int d = 0; d < dim; ++d)
            *reactions_file << ',' << name << "_F" << components[d];
        for (const auto &name : column_names)
          *reactions_file << ',' << name;
        *reactions_file << ",imbalance\n";
      }
    *reactions_file << step << ',' << std::setprecision(12) << load_factor;
    for (const auto &force : forces)
      for (unsigned int d = 0; d < dim; ++d)
        *reactions_file << ',' << force[d];
    for (const double u : columns)
      *reactions_file << ',' << u;
    *reactions_file << ',' << imbalance << std::endl;
  }



  template <int dim>
  const typename OutputWriter<dim>::Parameters &
  OutputWriter<dim>::get_parameters() const
  {
    return parameters;
  }



  // One line per record, "points|increment load_factor file name"; the
  // file name is the rest of the line.
  template <int dim>
  void
  OutputWriter<dim>::save(std::ostream &out) const
  {
    out << std::setprecision(std::numeric_limits<double>::max_digits10)
        << point_records.size() + increment_records.size() << '\n';
    for (const auto &[t, name] : point_records)
      out << "points " << t << ' ' << name << '\n';
    for (const auto &[t, name] : increment_records)
      out << "increment " << t << ' ' << name << '\n';
  }



  template <int dim>
  void
  OutputWriter<dim>::resume(std::istream &in, const unsigned int step)
  {
    point_records.clear();
    increment_records.clear();
    std::size_t n = 0;
    in >> n;
    for (std::size_t i = 0; i < n; ++i)
      {
        std::string kind, name;
        double      t = 0.;
        in >> kind >> t;
        std::getline(in >> std::ws, name);
        AssertThrow(in && (kind == "points" || kind == "increment"),
                    ExcMessage("Cannot read the output records of the "
                               "checkpoint."));
        (kind == "points" ? point_records : increment_records)
          .emplace_back(t, name);
      }
    if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
      return;

    // The PVD files may name steps after the checkpoint: write them anew.
    if (!point_records.empty())
      {
        std::ofstream pvd(parameters.directory + "/points.pvd");
        DataOutBase::write_pvd_record(pvd, point_records);
      }
    if (!increment_records.empty())
      {
        std::ofstream pvd(parameters.directory + "/increment.pvd");
        DataOutBase::write_pvd_record(pvd, increment_records);
      }

    // Rows of later steps go; the next ones are appended after the header.
    const std::string csv = parameters.directory + "/reactions.csv";
    if (std::filesystem::exists(csv))
      {
        Checkpoint<dim>::truncate_csv(csv, step);
        reactions_file =
          std::make_unique<std::ofstream>(csv, std::ios::out | std::ios::app);
        AssertThrow(*reactions_file, ExcMessage("Cannot write " + csv));
      }
  }



  template class OutputWriter<2>;
  template class OutputWriter<3>;
} // namespace qsmpm
