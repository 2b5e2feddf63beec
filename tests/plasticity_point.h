// A single material point of an IsotropicPlasticity model driven through
// its 3D return mapping, for the tests of strain paths at one point.
#ifndef qsmpm_tests_plasticity_point_h
#define qsmpm_tests_plasticity_point_h

#include <deal.II/base/symmetric_tensor.h>
#include <qsmpm/materials/isotropic_plasticity.h>

namespace qsmpm_tests
{
  /// The committed state of the point: elastic strain and alpha.
  struct PointHistory
  {
    dealii::SymmetricTensor<2, 3> elastic_strain;
    double                        alpha = 0.;
  };

  /// One strain-driven step of @p model; returns the return mapping's
  /// result (with its tangent) and, if @p commit, commits it to @p point.
  template <typename Model>
  typename Model::Return
  step(const Model                         &model,
       PointHistory                        &point,
       const dealii::SymmetricTensor<2, 3> &d_eps,
       const bool                           commit = true)
  {
    typename Model::Return r;
    model.return_map(point.elastic_strain + d_eps, point.alpha, true, r);
    if (commit)
      {
        point.elastic_strain = r.elastic_strain;
        point.alpha          = r.alpha;
      }
    return r;
  }

  /// diag(a, b, d).
  inline dealii::SymmetricTensor<2, 3>
  diagonal(const double a, const double b, const double d)
  {
    dealii::SymmetricTensor<2, 3> t;
    t[0][0] = a;
    t[1][1] = b;
    t[2][2] = d;
    return t;
  }
} // namespace qsmpm_tests

#endif
