// The residual's kernel for affine cells (AffineQ1Cell) and its packed copy
// of the committed point state:
//
// 1. AffineQ1Cell against deal.II's FEValues, in 2D and 3D, on cells that
//    are parallelograms (parallelepipeds) with sheared, stretched and
//    rotated edges: at points inside the cell, with their reference
//    locations from deal.II's MappingQ1 (as the ShapeCache keeps deal.II's),
//    - grad u = sum_w K_w m_w(xi) of random nodal values u against
//      sum_v u_v (x) grad N_v(x) from FEValues (FE_Q(1), MappingQ1 at the
//      reference location);
//    - sym grad u from the symmetric parts of the K_w against sym() of the
//      same;
//    - the nodal forces of random non-symmetric stress measures S_p,
//      add_nodal_forces() of H_w = sum_p m_w S_p, against
//      f_v = sum_p S_p grad N_v(x_p) from FEValues, and of symmetric ones
//      through unfold_symmetric_terms().
//    - the shape functions N_v and grad N_v of shape_functions() (which
//      the ShapeCache computes instead of storing on affine cells) against
//      FEValues' shape values and gradients;
//    Tolerance 1e-12 relative: the two differ by round-off only (measured
//    below 1e-14), while a wrong sign, monomial or transposed J^{-1} is
//    off by O(1).
//
// 2. The residual's packed copy of the committed state (a LinearElastic
//    model declares that its batched update reads the stress only, so the
//    residual gathers 5 of the 12 doubles of a 2D point) against the same
//    model declaring every field (read in place from the property arrays):
//    R(du) equal to 1e-13 of |R| for a random du, again after commit() of
//    that du on both point sets (the copy must follow the commit without a
//    reinit() of the cache), and a PointStateBatch without strains must
//    return NaN strains from operator[] instead of plausible values.
#include "tests.h"

#include <algorithm>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/particles/affine_q1_cell.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <random>

namespace
{
  using namespace qsmpm;

  template <int dim>
  void
  test_kernel(std::mt19937 &random)
  {
    std::uniform_real_distribution<double> uniform(-1., 1.);
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    constexpr unsigned int n_terms    = AffineQ1Cell<dim>::n_terms;
    constexpr unsigned int n_sym      = AffineQ1Cell<dim>::n_sym;

    // A unit cell mapped by x = origin + A xi, A = a stretch, shear and
    // rotation (det A > 0).
    Tensor<2, dim> A;
    for (unsigned int d = 0; d < dim; ++d)
      for (unsigned int e = 0; e < dim; ++e)
        A[d][e] = (d == e ? 1.5 + 0.5 * d : 0.) + 0.3 * uniform(random);
    AssertThrow(determinant(A) > 0., ExcInternalError());
    Point<dim> origin;
    for (unsigned int d = 0; d < dim; ++d)
      origin[d] = 2. * uniform(random);
    Triangulation<dim> tria;
    GridGenerator::hyper_cube(tria, 0., 1.);
    GridTools::transform(
      [&](const Point<dim> &xi) { return Point<dim>(origin + A * xi); }, tria);
    const auto cell = tria.begin_active();

    Tensor<2, dim> J;
    AssertThrow(BackgroundGrid<dim>::affine_map(cell, J), ExcInternalError());
    const AffineQ1Cell<dim> affine{invert(J)};

    // Points, nodal values, stress measures.
    const unsigned int          n_points = 7;
    std::vector<Point<dim>>     xi_true(n_points), x(n_points);
    std::vector<Tensor<2, dim>> S(n_points);
    for (unsigned int p = 0; p < n_points; ++p)
      {
        for (unsigned int d = 0; d < dim; ++d)
          xi_true[p][d] = 0.5 + 0.45 * uniform(random);
        x[p] = origin + A * xi_true[p];
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            S[p][a][b] = uniform(random);
      }
    double u[n_vertices * dim];
    for (auto &value : u)
      value = uniform(random);

    const MappingQ1<dim> mapping;
    const FE_Q<dim>      fe(1);
    double grad_error = 0., grad_scale = 0., sym_error = 0., force_error = 0.,
           force_scale = 0., sym_force_error = 0., shape_error = 0.,
           shape_scale = 0.;
    double K[n_terms][dim * dim], K_sym[n_terms][n_sym];
    affine.gradient_terms(u, K);
    AffineQ1Cell<dim>::symmetrize_terms(K, K_sym);
    double H[n_terms][dim * dim]       = {};
    double H_sym_sums[n_terms][n_sym]  = {};
    double f[n_vertices * dim]         = {};
    double f_sym[n_vertices * dim]     = {};
    double f_ref[n_vertices * dim]     = {};
    double f_sym_ref[n_vertices * dim] = {};
    for (unsigned int p = 0; p < n_points; ++p)
      {
        const Point<dim> xi = mapping.transform_real_to_unit_cell(cell, x[p]);
        typename AffineQ1Cell<dim>::Monomials m;
        AffineQ1Cell<dim>::monomials(xi, m);

        // deal.II's shape gradients at the point.
        FEValues<dim> fe_values(mapping,
                                fe,
                                Quadrature<dim>(std::vector<Point<dim>>{xi}),
                                update_values | update_gradients);
        fe_values.reinit(cell);
        double         N[n_vertices];
        Tensor<1, dim> grad_N[n_vertices];
        affine.shape_functions(xi, N, grad_N);
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            shape_error =
              std::max({shape_error,
                        std::abs(N[v] - fe_values.shape_value(v, 0)),
                        (grad_N[v] - fe_values.shape_grad(v, 0)).norm()});
            shape_scale =
              std::max({shape_scale, 1., fe_values.shape_grad(v, 0).norm()});
          }
        // FE_Q(1)'s shape function v belongs to vertex v.
        Tensor<2, dim> grad_ref;
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int a = 0; a < dim; ++a)
            grad_ref[a] += u[v * dim + a] * fe_values.shape_grad(v, 0);
        const Tensor<2, dim> grad = AffineQ1Cell<dim>::gradient(K, m);
        grad_error = std::max(grad_error, (grad - grad_ref).norm());
        grad_scale = std::max(grad_scale, grad_ref.norm());
        sym_error  = std::max(sym_error,
                             (AffineQ1Cell<dim>::symmetric_gradient(K_sym, m) -
                              symmetrize(grad_ref))
                               .norm());

        // Forces of S_p and of its symmetric part.
        AffineQ1Cell<dim>::add_force_terms(S[p], m, H);
        const SymmetricTensor<2, dim> S_sym = symmetrize(S[p]);
        for (unsigned int w = 0; w < n_terms; ++w)
          for (unsigned int k = 0; k < n_sym; ++k)
            H_sym_sums[w][k] += m[w] * S_sym.access_raw_entry(k);
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            const Tensor<1, dim> f_v = S[p] * fe_values.shape_grad(v, 0);
            const Tensor<1, dim> f_sym_v =
              Tensor<2, dim>(S_sym) * fe_values.shape_grad(v, 0);
            for (unsigned int a = 0; a < dim; ++a)
              {
                f_ref[v * dim + a] += f_v[a];
                f_sym_ref[v * dim + a] += f_sym_v[a];
              }
          }
      }
    affine.add_nodal_forces(H, 1., f);
    double H_unfolded[n_terms][dim * dim];
    AffineQ1Cell<dim>::unfold_symmetric_terms(H_sym_sums, H_unfolded);
    affine.add_nodal_forces(H_unfolded, 1., f_sym);
    for (unsigned int i = 0; i < n_vertices * dim; ++i)
      {
        force_error = std::max(force_error, std::abs(f[i] - f_ref[i]));
        sym_force_error =
          std::max(sym_force_error, std::abs(f_sym[i] - f_sym_ref[i]));
        force_scale = std::max(force_scale, std::abs(f_ref[i]));
      }

    const double tolerance = 1e-12;
    deallog << "dim = " << dim << std::endl;
    deallog << "  N and grad N against FEValues <= 1e-12 relative: "
            << (shape_error <= tolerance * shape_scale ? "PASS" : "FAIL")
            << std::endl;
    deallog << "  grad u against FEValues <= 1e-12 relative: "
            << (grad_error <= tolerance * grad_scale ? "PASS" : "FAIL")
            << std::endl;
    deallog << "  sym grad u against FEValues <= 1e-12 relative: "
            << (sym_error <= tolerance * grad_scale ? "PASS" : "FAIL")
            << std::endl;
    deallog << "  forces against FEValues <= 1e-12 relative: "
            << (force_error <= tolerance * force_scale ? "PASS" : "FAIL")
            << std::endl;
    deallog << "  forces of symmetric stresses <= 1e-12 relative: "
            << (sym_force_error <= tolerance * force_scale ? "PASS" : "FAIL")
            << std::endl;
  }



  /// LinearElastic declaring that it reads every field: no packed copy.
  template <int dim>
  class ReadsEverything : public LinearElastic<dim>
  {
  public:
    using LinearElastic<dim>::LinearElastic;

    typename PointStateBatch<dim>::Fields
    batch_fields() const override
    {
      return {};
    }
  };



  void
  test_packed_state()
  {
    constexpr int       dim = 2;
    BackgroundGrid<dim> grid(MPI_COMM_WORLD);
    grid.make_box(Point<dim>(0., 0.), Point<dim>(1., 0.5), {{6, 3}});

    const LinearElastic<dim>   packed_model(100., 0.3);
    const ReadsEverything<dim> full_model(100., 0.3);
    MaterialPointSet<dim>      packed_points(grid, packed_model);
    MaterialPointSet<dim>      full_points(grid, full_model);
    ShapeCache<dim>            packed_cache, full_cache;
    for (auto *points : {&packed_points, &full_points})
      points->fill([](const Point<dim> &) { return true; },
                   2,
                   MaterialPointSet<dim>::Placement::regular);
    QuasiStaticResidual<dim> packed(grid, packed_points, packed_cache);
    QuasiStaticResidual<dim> full(grid, full_points, full_cache);
    packed_cache.reinit(grid, packed_points, packed.ghosted_layout());
    full_cache.reinit(grid, full_points, full.ghosted_layout());

    TrilinosWrappers::MPI::Vector f_ext(grid.locally_owned_dofs(),
                                        MPI_COMM_WORLD);
    packed.set_external_force(f_ext);
    full.set_external_force(f_ext);
    TrilinosWrappers::MPI::Vector du(f_ext), R_packed(f_ext), R_full(f_ext);
    const auto                    compare = [&](const std::string &what) {
      packed.evaluate(du, R_packed);
      full.evaluate(du, R_full);
      const double scale = R_full.l2_norm();
      R_full -= R_packed;
      deallog << "  " << what << ": R packed against in place <= 1e-13 |R|: "
              << (scale > 0. && R_full.l2_norm() <= 1e-13 * scale ? "PASS" :
                                                                                       "FAIL")
              << std::endl;
    };

    for (const auto i : grid.locally_owned_dofs())
      du(i) = 1e-3 * std::sin(1. + 1.7 * i);
    du.compress(VectorOperation::insert);
    deallog << "packed committed state, dim = 2" << std::endl;
    compare("first step");

    // Commit du on both (stresses change), then a new du, same cache.
    TrilinosWrappers::MPI::Vector du_ghosted(packed.ghosted_layout());
    du_ghosted = du;
    packed.commit(du_ghosted);
    full.commit(du_ghosted);
    for (const auto i : grid.locally_owned_dofs())
      du(i) = 1e-3 * std::cos(0.4 + 2.3 * i);
    du.compress(VectorOperation::insert);
    compare("after commit()");

    // A batch without strains.
    const double                          data[3] = {1., 2., 3.};
    const Point<dim>                      position;
    typename PointStateBatch<dim>::Layout layout{numbers::invalid_unsigned_int,
                                                 0,
                                                 numbers::invalid_unsigned_int,
                                                 numbers::invalid_unsigned_int,
                                                 numbers::invalid_unsigned_int,
                                                 0};
    const PointStateBatch<dim>            batch(layout, data, 3, &position, 1);
    const PointState<dim>                 state = batch[0];
    deallog << "  batch without strains: stress read, strain NaN: "
            << (state.stress[0][0] == 1. && state.stress[1][1] == 2. &&
                    state.stress[0][1] == 3. &&
                    std::isnan(state.strain[0][0]) && std::isnan(state.volume) ?
                  "PASS" :
                  "FAIL")
            << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::mt19937 random(7);
  test_kernel<2>(random);
  test_kernel<3>(random);
  test_packed_state();
}
