#include <deal.II/base/mpi.h>
#include <iomanip>
#include <limits>
#include <qsmpm/base/utilities.h>
#include <qsmpm/io/probe_writer.h>

namespace qsmpm
{
  template <int dim>
  ProbeWriter<dim>::ProbeWriter(const std::vector<Point<dim>> &positions,
                                const std::string             &directory,
                                const MPI_Comm                 communicator)
    : positions(positions)
    , directory(directory)
    , communicator(communicator)
  {
  }



  template <int dim>
  bool
  ProbeWriter<dim>::empty() const
  {
    return positions.empty();
  }



  template <int dim>
  void
  ProbeWriter<dim>::select(const MaterialPointSet<dim> &points)
  {
    const unsigned int u = points.get_offsets().displacement;
    ids.assign(positions.size(), 0);
    for (unsigned int k = 0; k < positions.size(); ++k)
      {
        // The nearest point on this rank, then the nearest of all ranks
        // (ties: the smaller id, so that every rank count picks the same).
        std::pair<double, types::particle_index> nearest{
          std::numeric_limits<double>::max(), 0};
        for (const auto &particle : points.get_particle_handler())
          {
            const auto data = particle.get_properties();
            Point<dim> X    = particle.get_location();
            for (unsigned int d = 0; d < dim; ++d)
              X[d] -= data[u + d];
            const std::pair<double, types::particle_index> candidate{
              X.distance(positions[k]), particle.get_id()};
            nearest = std::min(nearest, candidate);
          }
        const double distance =
          dealii::Utilities::MPI::min(nearest.first, communicator);
        AssertThrow(distance < std::numeric_limits<double>::max(),
                    ExcMessage("Output/Probe points: there are no material "
                               "points to probe."));
        ids[k] = dealii::Utilities::MPI::min(
          nearest.first == distance ?
            nearest.second :
            std::numeric_limits<types::particle_index>::max(),
          communicator);
      }

    if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0 || file)
      return;
    file = std::make_unique<std::ofstream>(directory + "/probes.csv");
    AssertThrow(*file, ExcMessage("Cannot write " + directory + "/probes.csv"));
    static const char *const axes[3] = {"x", "y", "z"};
    *file << "step,load_factor";
    for (unsigned int k = 0; k < ids.size(); ++k)
      {
        const std::string probe = "probe" + std::to_string(k) + "_";
        for (unsigned int d = 0; d < dim; ++d)
          *file << ',' << probe << axes[d];
        for (unsigned int d = 0; d < dim; ++d)
          *file << ',' << probe << "u_" << axes[d];
        for (unsigned int c = 0; c < Utils::n_symmetric_components<dim>; ++c)
          {
            const auto ij =
              SymmetricTensor<2, dim>::unrolled_to_component_indices(c);
            *file << ',' << probe << "stress_" << axes[ij[0]] << axes[ij[1]];
          }
        for (const auto &name : points.output_layout().component_names(dim))
          *file << ',' << probe << name;
      }
    *file << '\n';
  }



  template <int dim>
  void
  ProbeWriter<dim>::write(const MaterialPointSet<dim> &points,
                          const unsigned int           step,
                          const double                 load_factor)
  {
    // Each probe's values on the rank that owns its point, zeros
    // elsewhere: one sum over the ranks gathers them.
    // Position, displacement, stress and the model's output fields.
    constexpr unsigned int n_kinematic =
      2 * dim + Utils::n_symmetric_components<dim>;
    const unsigned int  n_values = n_kinematic + points.output_layout().size();
    std::vector<double> values(ids.size() * n_values, 0.);
    const auto         &offsets = points.get_offsets();
    for (const auto &particle : points.get_particle_handler())
      for (unsigned int k = 0; k < ids.size(); ++k)
        if (particle.get_id() == ids[k])
          {
            const auto data = particle.get_properties();
            double    *out  = values.data() + k * n_values;
            const auto x    = particle.get_location();
            for (unsigned int d = 0; d < dim; ++d)
              {
                out[d]       = x[d];
                out[dim + d] = data[offsets.displacement + d];
              }
            for (unsigned int c = 0; c < Utils::n_symmetric_components<dim>;
                 ++c)
              out[2 * dim + c] = data[offsets.stress + c];
            points.compute_output_fields(
              particle,
              ArrayView<double>(out + n_kinematic, n_values - n_kinematic));
          }
    dealii::Utilities::MPI::sum(values, communicator, values);
    if (!file)
      return;
    *file << step << ',' << std::setprecision(12) << load_factor;
    for (const double value : values)
      *file << ',' << value;
    *file << std::endl;
  }



  template class ProbeWriter<2>;
  template class ProbeWriter<3>;
} // namespace qsmpm
