#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <limits>
#include <qsmpm/base/utilities.h>
#include <qsmpm/loading/opening_gauge.h>
#include <sstream>
#include <utility>
#include <vector>

namespace qsmpm
{
  template <int dim>
  OpeningGauge<dim>::OpeningGauge(const std::string &text)
  {
    const auto positions = Utils::split(text, ';');
    AssertThrow(positions.size() == 2,
                ExcMessage("Load stepping: <Opening gauge> = <" + text +
                           "> must be two positions x_a; x_b separated by "
                           "';'."));
    x_a = Utils::parse_point<dim>(positions[0], "Opening gauge");
    x_b = Utils::parse_point<dim>(positions[1], "Opening gauge");
    const double length = x_a.distance(x_b);
    AssertThrow(std::isfinite(length) && length > 0.,
                ExcMessage("Load stepping: the two positions of <Opening "
                           "gauge> = <" +
                           text + "> must differ."));
    e = (x_b - x_a) / length;
  }



  template <int dim>
  unsigned int
  OpeningGauge<dim>::find_point(const ShapeCache<dim> &cache,
                                const unsigned int     displacement,
                                const Point<dim>      &x,
                                const double           max_distance,
                                const MPI_Comm         communicator) const
  {
    // A point's initial position.
    const auto initial_position = [&](const unsigned int p) {
      Point<dim>    X   = cache.position(p);
      const double *u_p = cache.properties(p) + displacement;
      for (unsigned int d = 0; d < dim; ++d)
        X[d] -= u_p[d];
      return X;
    };
    const auto before = [](const Point<dim> &X, const Point<dim> &Y) {
      return std::lexicographical_compare(&X[0],
                                          &X[0] + dim,
                                          &Y[0],
                                          &Y[0] + dim);
    };
    double nearest = std::numeric_limits<double>::infinity();
    for (unsigned int p = 0; p < cache.n_points(); ++p)
      nearest = std::min(nearest, initial_position(p).distance(x));
    nearest = dealii::Utilities::MPI::min(nearest, communicator);
    if (!(nearest <= max_distance))
      {
        std::ostringstream message;
        message << "Load stepping: the <Opening gauge> position " << x
                << " has no material point within " << max_distance
                << " (one cell); the nearest is "
                << (std::isfinite(nearest) ? std::to_string(nearest) :
                                             std::string("none"))
                << " away. Place the gauge's ends inside the body.";
        AssertThrow(false, ExcMessage(message.str()));
      }

    // Points as near as the nearest up to round-off (X is x - u, which
    // changes in the last digits from step to step) are ties; of those, the
    // one with the lexicographically smallest X, the same on every rank and
    // in every step.
    const double tie  = 1e-9 * x_a.distance(x_b);
    unsigned int best = numbers::invalid_unsigned_int;
    Point<dim>   best_X;
    for (unsigned int p = 0; p < cache.n_points(); ++p)
      {
        const Point<dim> X = initial_position(p);
        if (X.distance(x) <= nearest + tie &&
            (best == numbers::invalid_unsigned_int || before(X, best_X)))
          {
            best   = p;
            best_X = X;
          }
      }
    std::vector<Point<dim>> candidates;
    if (best != numbers::invalid_unsigned_int)
      candidates.push_back(best_X);
    Point<dim> winner;
    bool       found = false;
    for (const auto &rank_candidates :
         dealii::Utilities::MPI::all_gather(communicator, candidates))
      for (const auto &X : rank_candidates)
        if (!found || before(X, winner))
          {
            winner = X;
            found  = true;
          }
    return !candidates.empty() && candidates[0] == winner ?
             best :
             numbers::invalid_unsigned_int;
  }



  template <int dim>
  void
  OpeningGauge<dim>::make_vector(const ShapeCache<dim>         &cache,
                                 const unsigned int             displacement,
                                 const double                   max_distance,
                                 const MPI_Comm                 communicator,
                                 TrilinosWrappers::MPI::Vector &w) const
  {
    // (global dof, coefficient) of both points on the ranks that own them;
    // all ranks receive them and add those of their own dofs.
    std::vector<std::pair<types::global_dof_index, double>> entries;
    const std::pair<Point<dim>, double> ends[2] = {{x_a, -1.}, {x_b, 1.}};
    for (const auto &[x, sign] : ends)
      {
        const unsigned int p =
          find_point(cache, displacement, x, max_distance, communicator);
        if (p == numbers::invalid_unsigned_int)
          continue;
        unsigned int c = 0;
        while (p >= cache.cell(c).end_point)
          ++c;
        const types::global_dof_index        *dofs  = cache.global_dofs(c);
        const unsigned short                 *nodes = cache.nodes(p);
        typename ShapeCache<dim>::ValueBuffer buffer;
        const double                         *N = cache.values(c, p, buffer);
        for (unsigned int k = 0; k < cache.stencil_size(p); ++k)
          for (unsigned int d = 0; d < dim; ++d)
            if (N[k] * e[d] != 0.)
              entries.emplace_back(dofs[nodes[k] * dim + d],
                                   sign * N[k] * e[d]);
      }

    w = 0.;
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    const IndexSet                      &owned = w.locally_owned_elements();
    for (const auto &rank_entries :
         dealii::Utilities::MPI::all_gather(communicator, entries))
      for (const auto &[index, value] : rank_entries)
        if (owned.is_element(index))
          {
            indices.push_back(index);
            values.push_back(value);
          }
    w.add(indices, values);
    w.compress(VectorOperation::add);
  }



  template class OpeningGauge<2>;
  template class OpeningGauge<3>;
} // namespace qsmpm
