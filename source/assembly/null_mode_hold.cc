#include <cmath>
#include <deal.II/base/mpi.h>
#include <qsmpm/assembly/null_mode_hold.h>

namespace qsmpm
{
  template <int dim>
  bool
  NullModeHold<dim>::points_on_a_face(const ShapeCache<dim> &cache,
                                      const double           delta)
  {
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const auto &range = cache.cell(c);
        if (range.first_point == range.end_point)
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          for (const double side : {0., 1.})
            {
              bool all = true;
              for (unsigned int p = range.first_point;
                   all && p < range.end_point;
                   ++p)
                all = std::abs(cache.reference_location(p)[d] - side) <= delta;
              if (all)
                return true;
            }
      }
    return false;
  }



  template <int dim>
  void
  NullModeHold<dim>::reinit(
    const BackgroundGrid<dim>                            &grid,
    const MaterialPointSet<dim>                          &points,
    const ShapeCache<dim>                                &cache,
    const AffineConstraints<double>                      &constraints,
    const GhostPenalty<dim>                              *ghost_penalty,
    const typename TangentAssembler<dim>::AdditionalTerm &additional_term,
    const double                                          fraction,
    const double                                          mean_stiffness)
  {
    clear();
    const MPI_Comm communicator = grid.get_communicator();
    const bool     look         = fraction > 0. && mean_stiffness > 0. &&
                      !points.get_formulation().gimp() &&
                      points_on_a_face(cache, std::sqrt(fraction));
    if (dealii::Utilities::MPI::max(look ? 1 : 0, communicator) == 0)
      {
        build(grid.locally_owned_dofs(),
              grid.locally_relevant_dofs(),
              communicator);
        return;
      }

    TangentAssembler<dim> tangent;
    tangent.reinit(grid);
    tangent.assemble(
      grid, points, cache, constraints, ghost_penalty, additional_term);
    const TrilinosWrappers::SparseMatrix &K = tangent.matrix();
    TrilinosWrappers::MPI::Vector         diagonal(grid.locally_owned_dofs(),
                                           communicator);
    for (const auto i : grid.locally_owned_dofs())
      diagonal(i) = K.diag_element(i);
    diagonal.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector ghosted(grid.locally_owned_dofs(),
                                          grid.locally_relevant_dofs(),
                                          communicator);
    ghosted = diagonal;

    // Each pair once, from the row of its smaller dof (on that dof's rank).
    const double                         threshold = fraction * mean_stiffness;
    std::vector<types::global_dof_index> pair(2);
    FullMatrix<double>                   spring(2, 2);
    for (const auto i : grid.locally_owned_dofs())
      {
        if (constraints.is_constrained(i))
          continue;
        const double a = ghosted(i);
        for (auto entry = K.begin(i); entry != K.end(i); ++entry)
          {
            const types::global_dof_index j = entry->column();
            if (j <= i || constraints.is_constrained(j))
              continue;
            const double b = ghosted(j), c = entry->value();
            // The smaller eigenvalue of [[a, c], [c, b]] and its vector.
            const double mean   = 0.5 * (a + b);
            const double root   = std::hypot(0.5 * (a - b), c);
            const double lambda = mean - root;
            if (!(std::abs(lambda) <= threshold) || root == 0.)
              continue;
            // (c, lambda - a) and (lambda - b, c) are both eigenvectors;
            // the longer one is the accurate one.
            double v0 = c, v1 = lambda - a;
            if (std::hypot(lambda - b, c) > std::hypot(v0, v1))
              {
                v0 = lambda - b;
                v1 = c;
              }
            const double norm = std::hypot(v0, v1);
            v0 /= norm;
            v1 /= norm;
            pair[0]      = i;
            pair[1]      = j;
            spring(0, 0) = mean_stiffness * v0 * v0;
            spring(0, 1) = spring(1, 0) = mean_stiffness * v0 * v1;
            spring(1, 1)                = mean_stiffness * v1 * v1;
            add(pair, spring);
          }
      }
    build(grid.locally_owned_dofs(),
          grid.locally_relevant_dofs(),
          communicator);
  }



  template class NullModeHold<2>;
  template class NullModeHold<3>;
} // namespace qsmpm
