#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <iomanip>
#include <limits>
#include <qsmpm/loading/constraint_checks.h>
#include <sstream>

namespace qsmpm
{
  namespace ConstraintChecks
  {
    namespace
    {
      /// The rigid-body modes: dim translations, then the rotations (one in
      /// 2D, about z; three in 3D, about x, y, z).
      template <int dim>
      constexpr unsigned int n_modes = (dim == 2 ? 3 : 6);

      /// Component @p c of mode @p m at the (centred, scaled) position x.
      template <int dim>
      double
      mode_value(const unsigned int m,
                 const unsigned int c,
                 const Point<dim>  &x)
      {
        if (m < dim)
          return m == c ? 1. : 0.;
        if constexpr (dim == 2) // rotation about z: (-y, x)
          return c == 0 ? -x[1] : x[0];
        else
          {
            // Rotation about axis a: (e_a x x)_c.
            const unsigned int a = m - dim;
            const unsigned int b = (a + 1) % 3, d = (a + 2) % 3;
            if (c == a)
              return 0.;
            return c == d ? x[b] : -x[d];
          }
      }

      template <int dim>
      std::string
      mode_name(const unsigned int m)
      {
        const char *axis = "xyz";
        if (m < dim)
          return std::string("translation in ") + axis[m];
        return std::string("rotation about ") +
               (dim == 2 ? 'z' : axis[m - dim]);
      }
    } // namespace



    template <int dim>
    std::vector<std::string>
    free_rigid_body_motions(
      const std::vector<std::pair<Point<dim>, unsigned int>> &held,
      const Point<dim>                                       &centre,
      const double                                            length,
      const MPI_Comm                                          communicator)
    {
      constexpr unsigned int M = n_modes<dim>;
      std::vector<double>    gram(M * M, 0.);
      for (const auto &[x, c] : held)
        {
          const Point<dim> y((x - centre) / length);
          double           r[M];
          for (unsigned int m = 0; m < M; ++m)
            r[m] = mode_value<dim>(m, c, y);
          for (unsigned int m = 0; m < M; ++m)
            for (unsigned int n = 0; n < M; ++n)
              gram[m * M + n] += r[m] * r[n];
        }
      Utilities::MPI::sum(gram, communicator, gram);

      LAPACKFullMatrix<double> G(M, M);
      double                   trace = 0.;
      for (unsigned int m = 0; m < M; ++m)
        {
          trace += gram[m * M + m];
          for (unsigned int n = 0; n < M; ++n)
            G(m, n) = gram[m * M + n];
        }
      Vector<double>     eigenvalues;
      FullMatrix<double> eigenvectors;
      G.compute_eigenvalues_symmetric(
        -1., 2. * trace + 1., 0., eigenvalues, eigenvectors);

      // Eigenvalues come in ascending order; a free motion has (up to
      // round-off) a zero one.
      std::vector<std::string> free;
      for (unsigned int k = 0; k < eigenvalues.size(); ++k)
        if (eigenvalues[k] <= 1e-10 * std::max(trace, 1.))
          {
            unsigned int dominant = 0;
            for (unsigned int m = 1; m < M; ++m)
              if (std::abs(eigenvectors(m, k)) >
                  std::abs(eigenvectors(dominant, k)))
                dominant = m;
            if (std::abs(eigenvectors(dominant, k)) > 0.999)
              free.push_back(mode_name<dim>(dominant));
            else
              {
                std::ostringstream combination;
                combination << "a combination of";
                for (unsigned int m = 0; m < M; ++m)
                  if (std::abs(eigenvectors(m, k)) > 1e-3)
                    combination << " " << mode_name<dim>(m) << " ("
                                << std::setprecision(2) << eigenvectors(m, k)
                                << ")";
                free.push_back(combination.str());
              }
          }
      return free;
    }



    template <int dim>
    void
    assert_no_rigid_body_motion(
      const std::vector<std::pair<Point<dim>, unsigned int>> &held,
      const Point<dim>                                       &centre,
      const double                                            length,
      const MPI_Comm                                          communicator,
      const bool                                              axisymmetric)
    {
      std::vector<std::string> free;
      if (axisymmetric)
        {
          unsigned int axial = 0;
          for (const auto &entry : held)
            axial += (entry.second == 1 ? 1 : 0);
          if (Utilities::MPI::sum(axial, communicator) == 0)
            free.push_back(mode_name<dim>(1) + " (along the axis)");
        }
      else
        free = free_rigid_body_motions<dim>(held, centre, length, communicator);
      if (free.empty())
        return;
      std::string list;
      for (const auto &motion : free)
        list += (list.empty() ? "" : ", ") + motion;
      AssertThrow(false,
                  ExcMessage("The body is not held against rigid-body motion: "
                             "no displacement condition on nodes that carry "
                             "material prevents " +
                             list +
                             ". Tractions, body forces and point loads "
                             "cannot; add a displacement condition (e.g. "
                             "fix that component on a boundary or a node)."));
    }



    void
    assert_condition_acts(const std::string &name,
                          const unsigned int n_active_nodes,
                          const double       largest_increment,
                          const double       t_old,
                          const double       t_new,
                          const MPI_Comm     communicator)
    {
      if (Utilities::MPI::sum(n_active_nodes, communicator) > 0 ||
          Utilities::MPI::max(largest_increment, communicator) == 0.)
        return;
      std::ostringstream message;
      message << "Load step from load factor " << t_old << " to " << t_new
              << ": the displacement condition <" << name
              << "> prescribes a non-zero increment, but none of its nodes "
                 "has a material point in its support any more; the body has "
                 "left it, so it would no longer act on the body. Use a "
                 "smaller total displacement or a condition that follows the "
                 "body.";
      AssertThrow(false, ExcMessage(message.str()));
    }



    template std::vector<std::string>
    free_rigid_body_motions<2>(
      const std::vector<std::pair<Point<2>, unsigned int>> &,
      const Point<2> &,
      const double,
      const MPI_Comm);
    template std::vector<std::string>
    free_rigid_body_motions<3>(
      const std::vector<std::pair<Point<3>, unsigned int>> &,
      const Point<3> &,
      const double,
      const MPI_Comm);
    template void
    assert_no_rigid_body_motion<2>(
      const std::vector<std::pair<Point<2>, unsigned int>> &,
      const Point<2> &,
      const double,
      const MPI_Comm,
      const bool);
    template void
    assert_no_rigid_body_motion<3>(
      const std::vector<std::pair<Point<3>, unsigned int>> &,
      const Point<3> &,
      const double,
      const MPI_Comm,
      const bool);
  } // namespace ConstraintChecks
} // namespace qsmpm
