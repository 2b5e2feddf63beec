#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <map>
#include <qsmpm/fracture/crack_tracking.h>
#include <tuple>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  namespace
  {
    /// A crack's path: the line through its path point normal to n, and
    /// the half-width of the band of cells it crosses.
    template <int dim>
    struct PathLine
    {
      Point<dim>     anchor;
      Tensor<1, dim> normal;
      double         half_width;

      /// The distance of @p c from the line.
      double
      offset(const Point<dim> &c) const
      {
        return std::abs((c - anchor) * normal);
      }
    };

    /// Path lines binned by their path points in boxes of the size r, so
    /// that those within r of a point are found in the 3^dim boxes around
    /// it.
    template <int dim>
    class PathBins
    {
    public:
      explicit PathBins(const double radius)
        : radius(radius)
      {
      }

      void
      add(const PathLine<dim> &line)
      {
        bins[key(line.anchor)].push_back(lines.size());
        lines.push_back(line);
      }

      bool
      empty() const
      {
        return lines.empty();
      }

      /// Call @p f(line) for each line whose path point lies within r of
      /// @p c.
      template <typename Function>
      void
      for_each_near(const Point<dim> &c, const Function &f) const
      {
        const std::array<long, dim> centre = key(c);
        std::array<long, dim>       k;
        for (unsigned int n = 0; n < std::pow(3, dim); ++n)
          {
            unsigned int m = n;
            for (unsigned int d = 0; d < dim; ++d, m /= 3)
              k[d] = centre[d] + long(m % 3) - 1;
            const auto bin = bins.find(k);
            if (bin == bins.end())
              continue;
            for (const unsigned int i : bin->second)
              if (lines[i].anchor.distance(c) <= radius)
                f(lines[i]);
          }
      }

    private:
      std::array<long, dim>
      key(const Point<dim> &x) const
      {
        std::array<long, dim> k;
        for (unsigned int d = 0; d < dim; ++d)
          k[d] = static_cast<long>(std::floor(x[d] / radius));
        return k;
      }

      const double                                           radius;
      std::vector<PathLine<dim>>                             lines;
      std::map<std::array<long, dim>, std::vector<unsigned>> bins;
    };

    /// A crack started in the step just committed, to be anchored.
    template <int dim>
    struct NewCrack
    {
      Point<dim>     centre;
      Point<dim>     location;
      Tensor<1, dim> normal;
      double         half_width;
      double         history;
      /// Its place in the gathered list.
      unsigned int index;
    };

    template <int dim>
    void
    append(std::vector<double> &buffer, const Tensor<1, dim> &x)
    {
      for (unsigned int d = 0; d < dim; ++d)
        buffer.push_back(x[d]);
    }

    template <int dim>
    Tensor<1, dim>
    read_tensor(const double *&data)
    {
      Tensor<1, dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = *data++;
      return x;
    }
  } // namespace



  template <int dim>
  CrackTracking<dim>::CrackTracking(const SmearedCracks<dim> &model)
    : model(model)
  {
  }



  template <int dim>
  unsigned long long
  CrackTracking<dim>::update(MaterialPointSet<dim> &points,
                             const MPI_Comm         communicator) const
  {
    using Model                = SmearedCracks<dim>;
    const unsigned int first   = points.get_offsets().state;
    const unsigned int n_state = points.n_state_components();
    // Indices into the model's state (SmearedCracks::state_fields()):
    // crack_allowed, crack_count, the first crack's separation history,
    // crack_anchor and crack_band_length.
    const unsigned int allowed     = 0;
    const unsigned int count       = 1;
    const unsigned int history     = 2 + 2 * dim * dim;
    const unsigned int anchor      = Model::anchor_index;
    const unsigned int band_length = Model::band_length_index;
    const double       radius      = model.tracking_radius();
    auto              &particles   = points.get_particle_handler();

    // Gather the paths of the cracks anchored in earlier steps and the
    // cracks started in the last one.
    std::vector<double>                           anchored, started;
    std::vector<double *>                         local_started;
    std::array<typename Model::CrackSummary, dim> cracks;
    // The largest energy a point's cracks have dissipated per unit crack
    // area (for `Crack tracking localization`).
    double largest = 0.;
    for (auto &particle : particles)
      {
        double            *state = particle.get_properties().data() + first;
        const unsigned int n_cracks =
          model.crack_summaries(ArrayView<const double>(state, n_state),
                                cracks);
        if (n_cracks == 0)
          continue;
        double dissipated = 0.;
        for (unsigned int k = 0; k < n_cracks; ++k)
          dissipated += cracks[k].dissipated;
        largest = std::max(largest, dissipated);
        // The band of a path is that of its own normal (the smearing
        // length may come from the mean normal of the band instead).
        const double half_width = 0.5 * model.smearing_length(cracks[0].normal);
        if (state[anchor] > 0.)
          {
            for (unsigned int d = 0; d < dim; ++d)
              anchored.push_back(state[anchor + 1 + d]);
            append(anchored, cracks[0].normal);
            anchored.push_back(half_width);
          }
        else
          {
            append(started,
                   Tensor<1, dim>(particle.get_surrounding_cell()->center()));
            append(started, Tensor<1, dim>(particle.get_location()));
            append(started, cracks[0].normal);
            started.push_back(half_width);
            started.push_back(state[history]);
            local_started.push_back(state);
          }
      }
    const auto all_anchored =
      Utilities::MPI::all_gather(communicator, anchored);
    const auto all_started = Utilities::MPI::all_gather(communicator, started);

    PathBins<dim> paths(radius);
    for (const auto &buffer : all_anchored)
      for (const double *data = buffer.data();
           data < buffer.data() + buffer.size();)
        {
          PathLine<dim> line;
          line.anchor     = Point<dim>(read_tensor<dim>(data));
          line.normal     = read_tensor<dim>(data);
          line.half_width = *data++;
          paths.add(line);
        }

    // Anchor the new cracks one after another, the same on every rank: the
    // most opened first, then by position.
    std::vector<NewCrack<dim>> new_cracks;
    unsigned int               first_local = 0;
    const unsigned int         this_rank =
      Utilities::MPI::this_mpi_process(communicator);
    for (unsigned int rank = 0; rank < all_started.size(); ++rank)
      {
        if (rank == this_rank)
          first_local = new_cracks.size();
        const auto &buffer = all_started[rank];
        for (const double *data = buffer.data();
             data < buffer.data() + buffer.size();)
          {
            NewCrack<dim> crack;
            crack.centre     = Point<dim>(read_tensor<dim>(data));
            crack.location   = Point<dim>(read_tensor<dim>(data));
            crack.normal     = read_tensor<dim>(data);
            crack.half_width = *data++;
            crack.history    = *data++;
            crack.index      = new_cracks.size();
            new_cracks.push_back(crack);
          }
      }
    const auto position_key = [](const NewCrack<dim> &c) {
      std::array<double, 2 * dim> key;
      for (unsigned int d = 0; d < dim; ++d)
        {
          key[d]       = c.centre[d];
          key[dim + d] = c.location[d];
        }
      return key;
    };
    std::vector<NewCrack<dim>> order = new_cracks;
    std::sort(order.begin(),
              order.end(),
              [&](const NewCrack<dim> &a, const NewCrack<dim> &b) {
                if (a.history != b.history)
                  return a.history > b.history;
                return position_key(a) < position_key(b);
              });
    std::vector<Point<dim>> anchors(new_cracks.size());
    std::vector<double>     band_lengths(new_cracks.size());
    for (const NewCrack<dim> &crack : order)
      {
        const PathLine<dim> *nearest = nullptr;
        paths.for_each_near(crack.centre, [&](const PathLine<dim> &line) {
          if (nearest == nullptr ||
              line.offset(crack.centre) < nearest->offset(crack.centre))
            nearest = &line;
        });
        Point<dim> a = crack.centre;
        if (nearest != nullptr)
          a -= ((crack.centre - nearest->anchor) * nearest->normal) *
               nearest->normal;
        anchors[crack.index] = a;
        // The band's direction: the mean of the normals of the paths whose
        // bands contain the cell, this crack's own included (each turned to
        // the side of this one).
        Tensor<1, dim> mean = crack.normal;
        paths.for_each_near(crack.centre, [&](const PathLine<dim> &line) {
          if (line.offset(crack.centre) <= line.half_width * (1. + 1e-9))
            mean += (line.normal * crack.normal < 0. ? -1. : 1.) * line.normal;
        });
        band_lengths[crack.index] = model.smearing_length(mean / mean.norm());
        paths.add({a, crack.normal, crack.half_width});
      }
    for (unsigned int i = 0; i < local_started.size(); ++i)
      {
        double *state = local_started[i];
        state[anchor] = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          state[anchor + 1 + d] = anchors[first_local + i][d];
        state[band_length] = band_lengths[first_local + i];
      }

    // Localized: a crack has dissipated `Crack tracking localization` of
    // G_f somewhere; new paths may then start only near existing ones.
    const bool localized =
      model.tracking_localization() > 0. &&
      Utilities::MPI::max(largest, communicator) >=
        model.tracking_localization() * model.fracture_energy();

    // The permissions for the next step. A small tolerance lets a path
    // that runs exactly through the corners of cells (at 45 degrees, from
    // a cell's centre) include the cells that touch it there.
    unsigned long long held_back = 0;
    for (auto &particle : particles)
      {
        double *state = particle.get_properties().data() + first;
        if (state[allowed] == 0. || state[count] > 0.)
          continue;
        const Point<dim> centre = particle.get_surrounding_cell()->center();
        bool             near = false, in_band = false;
        paths.for_each_near(centre, [&](const PathLine<dim> &line) {
          near = true;
          in_band =
            in_band || line.offset(centre) <= line.half_width * (1. + 1e-9);
        });
        state[allowed] = ((!near && !localized) || in_band) ? 1. : -1.;
        held_back += (state[allowed] < 0.);
      }
    return Utilities::MPI::sum(held_back, communicator);
  }



  template class CrackTracking<2>;
  template class CrackTracking<3>;
} // namespace qsmpm
