// The batched stress update ConstitutiveModel::update_stresses(), which the
// residual calls once per cell, against the per-point update_stress() and
// against closed-form stresses:
//
// 1. LinearElastic (2D plane strain, 2D plane stress, 3D) overrides it with
//    sigma = sigma_old + lambda tr(d_eps) I + 2 mu d_eps. Reference: that
//    formula with lambda, mu computed here from E, nu (plane stress:
//    lambda' = 2 lambda mu / (lambda + 2 mu)), and update_stress(), which
//    contracts the full stiffness tensor.
// 2. CubicElastic (3D, points in five orientations) overrides it, reading
//    the rotated stiffness in place, and declares its state constant.
//    References: update_stress() point by point; for the unrotated
//    crystal sigma_xx = C11 eps_xx + C12 (eps_yy + eps_zz), sigma_xy =
//    2 C44 eps_xy.
// 3. Decohesion keeps the default (update_stress() point by point): the
//    stresses and the trial fields, which change as the points crack, equal
//    those of update_stress() exactly.
//
// 4. The batched tangents ConstitutiveModel::tangents(), which the tangent
//    assembler and the check for nodes without stiffness call once per
//    cell: LinearElastic's override against
//    C_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk) with the same
//    lambda, mu; the default (CubicElastic, one orientation per point)
//    equal to tangent() point by point.
//
// The points of a batch are read through PointStateBatch from property
// arrays laid out as the points' own (strain, stress, volume, material id,
// model fields), with committed stresses and strain increments that differ
// from point to point, so that a batch that mixed up points would fail.
// Tolerance 1e-13 relative to the largest stress: the overrides change the
// order of the floating-point operations only (measured <= 2e-16), while a
// wrong modulus or point is off by 1e-3 or more. The default
// implementation is compared for equality.
#include "tests.h"

#include <deal.II/base/tensor_function.h>
#include <qsmpm/base/rotation.h>
#include <qsmpm/materials/cubic_elastic.h>
#include <qsmpm/materials/decohesion.h>
#include <qsmpm/materials/linear_elastic.h>
#include <random>

using namespace qsmpm;

namespace
{
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> uniform(-1., 1.);

  template <int dim>
  SymmetricTensor<2, dim>
  random_symmetric(const double scale)
  {
    SymmetricTensor<2, dim> t;
    for (unsigned int i = 0; i < t.n_independent_components; ++i)
      t.access_raw_entry(i) = scale * uniform(rng);
    return t;
  }

  /// n random strain increments of size @p scale.
  template <int dim>
  std::vector<SymmetricTensor<2, dim>>
  random_increments(const unsigned int n, const double scale)
  {
    std::vector<SymmetricTensor<2, dim>> d_eps;
    for (unsigned int i = 0; i < n; ++i)
      d_eps.push_back(random_symmetric<dim>(scale));
    return d_eps;
  }

  /**
   * n points of a model in property arrays laid out like a
   * MaterialPointSet's: strain, stress, volume, material id, the model's
   * fields; random committed strains and stresses.
   */
  template <int dim>
  struct Points
  {
    static constexpr unsigned int n_sym =
      SymmetricTensor<2, dim>::n_independent_components;

    Points(const ConstitutiveModel<dim> &model,
           const unsigned int            n,
           const double                  stress_scale)
      : layout{0,
               n_sym,
               2 * n_sym,
               2 * n_sym + 1,
               2 * n_sym + 2,
               model.n_state_components()}
      , data(n, std::vector<double>(2 * n_sym + 2 + layout.n_state))
      , positions(n)
    {
      for (unsigned int i = 0; i < n; ++i)
        {
          for (unsigned int d = 0; d < dim; ++d)
            positions[i][d] = 0.5 + 0.4 * uniform(rng);
          const auto strain = random_symmetric<dim>(1e-4);
          const auto stress = random_symmetric<dim>(stress_scale);
          for (unsigned int c = 0; c < n_sym; ++c)
            {
              data[i][layout.strain + c] = strain.access_raw_entry(c);
              data[i][layout.stress + c] = stress.access_raw_entry(c);
            }
          data[i][layout.volume]      = 0.01;
          data[i][layout.material_id] = 0;
          model.initialize_state(
            positions[i],
            ArrayView<double>(data[i].data() + layout.state, layout.n_state));
          pointers.push_back(data[i].data());
        }
    }

    PointStateBatch<dim>
    batch() const
    {
      return {layout, pointers.data(), positions.data(), size()};
    }

    unsigned int
    size() const
    {
      return data.size();
    }

    typename PointStateBatch<dim>::Layout layout;
    std::vector<std::vector<double>>      data;
    std::vector<const double *>           pointers;
    std::vector<Point<dim>>               positions;
  };

  /// The stresses and trial fields of update_stresses() and update_stress().
  template <int dim>
  struct Results
  {
    std::vector<SymmetricTensor<2, dim>> batched, single;
    std::vector<double>                  batched_state, single_state;
  };

  template <int dim>
  Results<dim>
  update_both(const ConstitutiveModel<dim>               &model,
              const Points<dim>                          &points,
              const std::vector<SymmetricTensor<2, dim>> &d_eps)
  {
    const unsigned int n = points.size(), n_state = points.layout.n_state;
    Results<dim>       r;
    r.batched.resize(n);
    r.single.resize(n);
    r.batched_state.resize(n * n_state);
    r.single_state.resize(n * n_state);
    model.update_stresses(points.batch(),
                          make_array_view(d_eps),
                          make_array_view(r.batched),
                          make_array_view(r.batched_state));
    const auto batch = points.batch();
    for (unsigned int i = 0; i < n; ++i)
      model.update_stress(batch[i],
                          d_eps[i],
                          r.single[i],
                          ArrayView<double>(r.single_state.data() + i * n_state,
                                            n_state));
    return r;
  }

  /// max_i |a_i - b_i| / max_i |b_i| (stresses or tangents)
  template <typename TensorType>
  double
  relative_difference(const std::vector<TensorType> &a,
                      const std::vector<TensorType> &b)
  {
    double diff = 0., scale = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        diff  = std::max(diff, (a[i] - b[i]).norm());
        scale = std::max(scale, b[i].norm());
      }
    return diff / scale;
  }

  /// tangents() of the batch and tangent() of each point.
  template <int dim>
  std::pair<std::vector<SymmetricTensor<4, dim>>,
            std::vector<SymmetricTensor<4, dim>>>
  tangents_both(const ConstitutiveModel<dim> &model, const Points<dim> &points)
  {
    std::vector<SymmetricTensor<4, dim>> batched(points.size()), single;
    model.tangents(points.batch(), make_array_view(batched));
    const auto batch = points.batch();
    for (unsigned int i = 0; i < points.size(); ++i)
      single.push_back(model.tangent(batch[i]));
    return {batched, single};
  }

  template <int dim>
  void
  check_linear_elastic(const bool plane_stress)
  {
    const double E = 210e3, nu = 0.3;
    deallog << "LinearElastic, dim = " << dim
            << (plane_stress ? ", plane stress" : "") << std::endl;
    const LinearElastic<dim> model(E, nu, plane_stress);
    const Points<dim>        points(model, 7, 100.);
    const auto d_eps = random_increments<dim>(points.size(), 1e-3);
    const auto r     = update_both(model, points, d_eps);

    // Independent: the Lame constants of E and nu.
    const double mu     = E / (2. * (1. + nu));
    double       lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    if (plane_stress)
      lambda = 2. * lambda * mu / (lambda + 2. * mu);
    std::vector<SymmetricTensor<2, dim>> exact;
    for (unsigned int i = 0; i < points.size(); ++i)
      exact.push_back(points.batch().stress(i) +
                      lambda * trace(d_eps[i]) * unit_symmetric_tensor<dim>() +
                      2. * mu * d_eps[i]);
    check("  batched against lambda tr(d_eps) I + 2 mu d_eps",
          relative_difference(r.batched, exact),
          1e-13);
    check("  batched against update_stress()",
          relative_difference(r.batched, r.single),
          1e-13);

    std::vector<SymmetricTensor<4, dim>> exact_C(points.size());
    for (auto &C : exact_C)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              C[i][j][k][l] = lambda * (i == j) * (k == l) +
                              mu * ((i == k) * (j == l) + (i == l) * (j == k));
    check("  batched tangents against lambda, mu",
          relative_difference(tangents_both(model, points).first, exact_C),
          1e-13);
  }

  void
  check_cubic_elastic()
  {
    deallog << "CubicElastic, dim = 3" << std::endl;
    const double    C11 = 249., C12 = 155., C44 = 114.;
    CubicElastic<3> model(C11, C12, C44);
    check_that("  state_is_constant()", model.state_is_constant());

    // The unrotated crystal: closed-form stresses.
    {
      const Points<3> points(model, 5, 0.1);
      const auto      d_eps = random_increments<3>(points.size(), 1e-3);
      const auto      r     = update_both(model, points, d_eps);
      std::vector<SymmetricTensor<2, 3>> exact;
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          SymmetricTensor<2, 3> s = points.batch().stress(i);
          const auto           &e = d_eps[i];
          for (unsigned int a = 0; a < 3; ++a)
            s[a][a] += C11 * e[a][a] + C12 * (trace(e) - e[a][a]);
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = a + 1; b < 3; ++b)
              s[a][b] += 2. * C44 * e[a][b];
          exact.push_back(s);
        }
      check("  unrotated: batched against C11, C12, C44",
            relative_difference(r.batched, exact),
            1e-13);
    }

    // Five orientations, one per point.
    model.set_orientation([](const Point<3> &x) {
      return Rotation::from_bunge(7. * x[0] + 1.,
                                  3. * x[1] + 0.2,
                                  5. * x[2] + 2.);
    });
    const Points<3> points(model, 5, 0.1);
    const auto      d_eps = random_increments<3>(points.size(), 1e-3);
    const auto      r     = update_both(model, points, d_eps);
    check("  rotated: batched against update_stress()",
          relative_difference(r.batched, r.single),
          1e-13);
    const auto C = tangents_both(model, points);
    check_that("  rotated: tangents() (the default) equal tangent()'s, and "
               "they differ from point to point",
               relative_difference(C.first, C.second) == 0. &&
                 relative_difference(C.second,
                                     std::vector<SymmetricTensor<4, 3>>(
                                       C.second.size(), C.second[0])) > 1e-3);
  }

  void
  check_decohesion()
  {
    deallog << "Decohesion, dim = 2 (default update_stresses())" << std::endl;
    const double        E = 1000., tau = 1., G_f = 0.05, h = 0.1;
    const Decohesion<2> model(E, 0.2, true, tau, G_f, Tensor<1, 2>(), h);
    const Points<2>     points(model, 6, 0.);
    std::vector<SymmetricTensor<2, 2>> d_eps;
    // Uniaxial strains from elastic (0.5 tau / E) to beyond initiation
    // (3 tau / E): some points crack in this increment.
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        SymmetricTensor<2, 2> e;
        e[0][0] = (0.5 + 0.5 * i) * tau / E;
        d_eps.push_back(e);
      }
    const auto r = update_both(model, points, d_eps);
    check_that("  stresses equal update_stress()'s",
               relative_difference(r.batched, r.single) == 0.);
    check_that("  trial fields equal update_stress()'s",
               r.batched_state == r.single_state);
    std::vector<double> committed;
    for (unsigned int i = 0; i < points.size(); ++i)
      for (const double s : points.batch().state(i))
        committed.push_back(s);
    check_that("  the trial fields differ from the committed ones (some "
               "points crack)",
               !committed.empty() && r.batched_state != committed);
  }
} // namespace

int
main()
{
  initlog();
  check_linear_elastic<2>(false);
  check_linear_elastic<2>(true);
  check_linear_elastic<3>(false);
  check_cubic_elastic();
  check_decohesion();
}
