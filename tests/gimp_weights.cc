// GIMP weights of the ShapeCache against the closed-form one-dimensional
// GIMP function of Bardenhagen & Kober (2004), for l <= h/2,
//
//   S(d) = 1 - (d^2 + l^2) / (2 h l)        |d| < l
//        = 1 - |d| / h                      l <= |d| < h - l
//        = (h + l - |d|)^2 / (4 h l)        h - l <= |d| < h + l
//        = 0                                otherwise,
//
// (d = x_p - X_i), whose tensor product is the weight of node i: an
// independent formula, not the antiderivative the library uses. The grid is
// periodic in x (2D) or x and z (3D), and every point's domain is widened to
// l_x = 0.45 h, so that domains cross cell faces and the periodic faces:
// the nodes reached across them must be found (on other ranks too), or the
// partition of unity fails. Checks at every point: every stencil weight and
// gradient against the closed form (node positions taken from the dofs'
// support points, distances wrapped by the period), sum_k S_k = 1,
// sum_k grad S_k = 0, and no stencil node missing (the number of nodes with
// |d_x| < h + l_x in each direction). Tolerance 1e-13: round-off only.
#include "tests.h"

#include <algorithm>
#include <deal.II/dofs/dof_tools.h>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>

namespace
{
  double
  s1d(const double d, const double l, const double h)
  {
    const double a = std::abs(d);
    if (a < l)
      return 1. - (d * d + l * l) / (2. * h * l);
    if (a < h - l)
      return 1. - a / h;
    if (a < h + l)
      return (h + l - a) * (h + l - a) / (4. * h * l);
    return 0.;
  }

  double
  ds1d(const double d, const double l, const double h)
  {
    const double a = std::abs(d), sign = d < 0 ? -1. : 1.;
    if (a < l)
      return -d / (h * l);
    if (a < h - l)
      return -sign / h;
    if (a < h + l)
      return -sign * (h + l - a) / (2. * h * l);
    return 0.;
  }

  template <int dim>
  void
  test()
  {
    using namespace qsmpm;
    BackgroundGrid<dim>           grid(MPI_COMM_WORLD);
    Point<dim>                    upper;
    std::array<unsigned int, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n[d]     = (d == 1 ? 3 : 4);
        upper[d] = n[d];
      }
    grid.make_box(Point<dim>(), upper, n);
    std::vector<unsigned int> periodic = {0};
    if (dim == 3)
      periodic.push_back(2);
    grid.make_periodic(periodic);

    const LinearElastic<dim> model(1., 0.3);
    Formulation              formulation;
    formulation.shape_functions = ShapeFunctions::ugimp;
    MaterialPointSet<dim> points(grid, model, formulation);
    points.fill([](const Point<dim> &) { return true; },
                2,
                MaterialPointSet<dim>::Placement::regular);
    const auto &o = points.get_offsets();
    for (auto &particle : points.get_particle_handler())
      particle.get_properties()[o.initial_half_length] = 0.45;

    ShapeCache<dim>          cache;
    QuasiStaticResidual<dim> residual(grid, points, cache, true);
    cache.reinit(grid, points, residual.ghosted_layout());

    std::map<types::global_dof_index, Point<dim>> support;
    DoFTools::map_dofs_to_support_points(grid.get_mapping(),
                                         grid.get_dof_handler(),
                                         support);
    // The material volume in each node's support, sum_p Omega_p S_i(x_p),
    // from the closed form (per dof, all components alike).
    std::vector<double> nodal_volume(grid.get_dof_handler().n_dofs(), 0.);
    double              value_error = 0, gradient_error = 0, unity_error = 0,
           gradient_sum_error = 0;
    unsigned int missing = 0, n_points = 0;
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      for (unsigned int p = cache.cell(c).first_point;
           p < cache.cell(c).end_point;
           ++p)
        {
          const Point<dim> &x = cache.position(p);
          Tensor<1, dim>    l;
          for (unsigned int d = 0; d < dim; ++d)
            l[d] = cache.properties(p)[o.initial_half_length + d];
          double                                   sum = 0;
          Tensor<1, dim>                           gradient_sum;
          const unsigned short                    *nodes = cache.nodes(p);
          typename ShapeCache<dim>::ValueBuffer    value_buffer;
          typename ShapeCache<dim>::GradientBuffer gradient_buffer;
          const double         *N      = cache.values(c, p, value_buffer);
          const Tensor<1, dim> *grad_N = cache.gradients(c, p, gradient_buffer);
          for (unsigned int k = 0; k < cache.stencil_size(p); ++k)
            {
              const Point<dim> &X =
                support.at(cache.global_dofs(c)[nodes[k] * dim]);
              double         S = 1.;
              Tensor<1, dim> G;
              for (unsigned int e = 0; e < dim; ++e)
                G[e] = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  double dist = x[d] - X[d];
                  if (d != 1) // periodic: the nearest image
                    dist -= upper[d] * std::round(dist / upper[d]);
                  S *= s1d(dist, l[d], 1.);
                  for (unsigned int e = 0; e < dim; ++e)
                    G[e] *=
                      (e == d) ? ds1d(dist, l[d], 1.) : s1d(dist, l[d], 1.);
                }
              value_error    = std::max(value_error, std::abs(S - N[k]));
              gradient_error = std::max(gradient_error, (G - grad_N[k]).norm());
              for (unsigned int d = 0; d < dim; ++d)
                nodal_volume[cache.global_dofs(c)[nodes[k] * dim + d]] +=
                  cache.properties(p)[o.volume] * S;
              sum += N[k];
              gradient_sum += grad_N[k];
            }
          unity_error = std::max(unity_error, std::abs(sum - 1.));
          gradient_sum_error =
            std::max(gradient_sum_error, gradient_sum.norm());
          // Nodes with a non-zero weight: per direction those within h + l.
          unsigned int expected = 1;
          for (unsigned int d = 0; d < dim; ++d)
            {
              unsigned int count = 0;
              for (int i = -2; i <= static_cast<int>(upper[d]) + 2; ++i)
                {
                  const double dist = std::abs(x[d] - i);
                  const bool   exists =
                    d != 1 || (i >= 0 && i <= static_cast<int>(upper[d]));
                  // Periodic directions: images i and i + L are one node.
                  const bool duplicate =
                    d != 1 && (i < 0 || i >= upper[d]) &&
                    std::abs(x[d] - (i - upper[d] * std::floor(i / upper[d]))) <
                      1. + l[d];
                  if (exists && !duplicate && dist < 1. + l[d] - 1e-12)
                    ++count;
                }
              expected *= count;
            }
          missing += (cache.stencil_size(p) != expected);
          ++n_points;
        }
    const MPI_Comm comm = MPI_COMM_WORLD;
    const auto     max  = [comm](const double v) {
      return Utilities::MPI::max(v, comm);
    };
    const double tol = 1e-13;
    deallog << dim << "D, " << Utilities::MPI::sum(n_points, comm)
            << " points, l_x = 0.45 h, periodic in x"
            << (dim == 3 ? " and z" : "") << std::endl;
    deallog << "  weights = closed form: "
            << (max(value_error) <= tol ? "PASS" : "FAIL") << std::endl;
    deallog << "  gradients = closed form: "
            << (max(gradient_error) <= tol ? "PASS" : "FAIL") << std::endl;
    deallog << "  sum of weights = 1: "
            << (max(unity_error) <= tol ? "PASS" : "FAIL") << std::endl;
    deallog << "  sum of gradients = 0: "
            << (max(gradient_sum_error) <= tol ? "PASS" : "FAIL") << std::endl;
    deallog << "  no node missing from a stencil: "
            << (Utilities::MPI::sum(missing, comm) == 0 ? "PASS" : "FAIL")
            << std::endl;

    // "Minimum nodal volume": with a threshold halfway between the smallest
    // and the largest nodal volume, exactly the nodes at or below it are
    // inactive: those on the walls y = 0, y = 3 (half the material of an
    // interior node) and those on the periodic faces, where each of the two
    // images holds its share (2D: 14 of the 20 nodes, 3D: 82 of 100).
    Utilities::MPI::sum(nodal_volume, comm, nodal_volume);
    const auto [smallest, largest] =
      std::minmax_element(nodal_volume.begin(), nodal_volume.end());
    const double   threshold = 0.5 * (*smallest + *largest);
    const IndexSet inactive =
      cache.dofs_without_points(grid, o.volume, threshold);
    unsigned int wrong = 0, n_inactive = 0;
    for (const auto dof : grid.locally_owned_dofs())
      {
        wrong += (inactive.is_element(dof) != (nodal_volume[dof] <= threshold));
        n_inactive += inactive.is_element(dof);
      }
    n_inactive = Utilities::MPI::sum(n_inactive, comm);
    deallog << "  nodes below a minimum nodal volume inactive: "
            << n_inactive / dim << " nodes, "
            << (Utilities::MPI::sum(wrong, comm) == 0 && n_inactive > 0 ?
                  "PASS" :
                  "FAIL")
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;
  test<2>();
  test<3>();
}
