#ifndef qsmpm_particles_affine_q1_cell_h
#define qsmpm_particles_affine_q1_cell_h

#include <array>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

// Every loop below has bounds known at compile time (dim, 2^dim) and is
// unrolled completely (#pragma GCC unroll), so that the conditions on bits
// fold away; without it the residual's kernel is markedly slower (figures in
// doc/benchmarks.md).

namespace qsmpm
{
  using namespace dealii;

  /**
   * The gradients of the Q1 (bi/trilinear) interpolant on an affine cell
   * x = origin + J xi, and the transposed operation, the nodal forces of
   * stress measures at points, computed without the shape-function
   * gradients of the points.
   *
   * In the monomials m_w(xi) = prod_{d in w} xi_d (w a subset of the
   * directions, written as a bit mask as deal.II numbers the vertices), the
   * interpolant of nodal values u_v is u(xi) = sum_w c_w m_w(xi), where the
   * coefficients c are the finite differences of the u_v over the bits of
   * v (the Moebius transform: for each direction d, c_v -= c_{v - 2^d} for
   * every v with bit d). Its gradient in x is then
   *
   *   grad u(xi) = sum_{w != all} K_w m_w(xi),
   *   K_w[a][b]  = sum_{d not in w} c_{w + 2^d}[a] J^{-1}[d][b],
   *
   * 2^dim - 1 tensors per cell; in 2D grad u = K_0 + K_1 xi_0 + K_2 xi_1.
   * The forces f_v = sum_p S_p grad N_v(x_p) are the transpose: the cell
   * sums H_w = sum_p m_w(xi_p) S_p, and the nodal forces follow from the
   * H_w once per cell.
   *
   * A point then needs its reference location (kept by the ShapeCache for
   * the load step) instead of 2^dim gradient vectors, and the work per point
   * falls from 2 (2^dim) dim^2 to 2 (2^dim - 1) dim^2 multiply-adds: a quarter
   * less in 2D, and the memory traffic of the gradients (64 bytes a point in
   * 2D, 192 in 3D) is gone. On a cell that is not affine the gradients of the
   * ShapeCache are used instead.
   */
  template <int dim>
  struct AffineQ1Cell
  {
    static constexpr unsigned int n_vertices =
      GeometryInfo<dim>::vertices_per_cell;
    /// The monomials of a gradient: every subset of the directions but all.
    static constexpr unsigned int n_terms = n_vertices - 1;
    static constexpr unsigned int n_sym =
      SymmetricTensor<2, dim>::n_independent_components;
    /// Row and column of the entries of a symmetric tensor in deal.II's
    /// unrolled order, as a table made at compile time (called in the
    /// loops, SymmetricTensor::unrolled_to_component_indices() is not
    /// folded away).
    static constexpr std::array<std::array<unsigned int, 2>, n_sym>
      unrolled_indices = [] {
        std::array<std::array<unsigned int, 2>, n_sym> table{};
        for (unsigned int k = 0; k < n_sym; ++k)
          {
            const auto ij =
              SymmetricTensor<2, dim>::unrolled_to_component_indices(k);
            table[k] = {{static_cast<unsigned int>(ij[0]),
                         static_cast<unsigned int>(ij[1])}};
          }
        return table;
      }();
    /// The values m_w(xi) of the monomials at a point.
    using Monomials = std::array<double, n_terms>;

    /// J^{-1}, J with the columns vertex(2^d) - vertex(0).
    Tensor<2, dim> inverse_jacobian;

    /**
     * The Q1 shape functions at reference location @p xi: N_v(xi) =
     * prod_d (xi_d if bit d of v is set, else 1 - xi_d), vertex v in
     * deal.II's order, into @p N, and their gradients in x, J^{-T}
     * grad_xi N_v, into @p grad_N (either may be null). The values of
     * deal.II's FE_Q(1) to round-off.
     */
    void
    shape_functions(const Point<dim> &xi,
                    double           *N,
                    Tensor<1, dim>   *grad_N) const
    {
#pragma GCC unroll 64
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          double         value = 1.;
          Tensor<1, dim> reference_gradient;
#pragma GCC unroll 64
          for (unsigned int e = 0; e < dim; ++e)
            reference_gradient[e] = 1.;
#pragma GCC unroll 64
          for (unsigned int d = 0; d < dim; ++d)
            {
              const bool   bit   = (v >> d) & 1U;
              const double f     = bit ? xi[d] : 1. - xi[d];
              const double slope = bit ? 1. : -1.;
              value *= f;
#pragma GCC unroll 64
              for (unsigned int e = 0; e < dim; ++e)
                reference_gradient[e] *= (e == d) ? slope : f;
            }
          if (N != nullptr)
            N[v] = value;
          if (grad_N != nullptr)
            {
              Tensor<1, dim> g;
#pragma GCC unroll 64
              for (unsigned int b = 0; b < dim; ++b)
#pragma GCC unroll 64
                for (unsigned int d = 0; d < dim; ++d)
                  g[b] += inverse_jacobian[d][b] * reference_gradient[d];
              grad_N[v] = g;
            }
        }
    }

    /// m_w(xi) for w = 0..n_terms-1.
    static void
    monomials(const Point<dim> &xi, Monomials &m)
    {
      m[0] = 1.;
#pragma GCC unroll 64
      for (unsigned int d = 0; d < dim; ++d)
#pragma GCC unroll 64
        for (unsigned int w = 0; w < (1U << d); ++w)
          if ((w | (1U << d)) < n_terms)
            m[w | (1U << d)] = m[w] * xi[d];
    }

    /**
     * The K_w of the nodal values @p u (vertex by vertex, u[v * dim + a]),
     * as dim x dim arrays K[w][a * dim + b].
     */
    void
    gradient_terms(const double *u, double (&K)[n_terms][dim * dim]) const
    {
      double c[n_vertices][dim];
#pragma GCC unroll 64
      for (unsigned int v = 0; v < n_vertices; ++v)
#pragma GCC unroll 64
        for (unsigned int a = 0; a < dim; ++a)
          c[v][a] = u[v * dim + a];
      moebius<false>(c);
#pragma GCC unroll 64
      for (unsigned int w = 0; w < n_terms; ++w)
        {
#pragma GCC unroll 64
          for (unsigned int ab = 0; ab < dim * dim; ++ab)
            K[w][ab] = 0.;
#pragma GCC unroll 64
          for (unsigned int d = 0; d < dim; ++d)
            if (!((w >> d) & 1U))
#pragma GCC unroll 64
              for (unsigned int a = 0; a < dim; ++a)
#pragma GCC unroll 64
                for (unsigned int b = 0; b < dim; ++b)
                  K[w][a * dim + b] +=
                    c[w | (1U << d)][a] * inverse_jacobian[d][b];
        }
    }

    /// The symmetric parts of the K_w, in deal.II's unrolled order.
    static void
    symmetrize_terms(
      const double (&K)[n_terms][dim * dim],
      double (
        &K_sym)[n_terms][SymmetricTensor<2, dim>::n_independent_components])
    {
#pragma GCC unroll 64
      for (unsigned int w = 0; w < n_terms; ++w)
#pragma GCC unroll 64
        for (unsigned int k = 0; k < n_sym; ++k)
          {
            const auto &ab = unrolled_indices[k];
            K_sym[w][k] =
              0.5 * (K[w][ab[0] * dim + ab[1]] + K[w][ab[1] * dim + ab[0]]);
          }
    }

    /// sym(grad u) at a point with monomials @p m, from the symmetric parts.
    static SymmetricTensor<2, dim>
    symmetric_gradient(
      const double (
        &K_sym)[n_terms][SymmetricTensor<2, dim>::n_independent_components],
      const Monomials &m)
    {
      SymmetricTensor<2, dim> E;
#pragma GCC unroll 64
      for (unsigned int k = 0; k < n_sym; ++k)
        {
          double sum = K_sym[0][k];
#pragma GCC unroll 64
          for (unsigned int w = 1; w < n_terms; ++w)
            sum += K_sym[w][k] * m[w];
          E.access_raw_entry(k) = sum;
        }
      return E;
    }

    /**
     * The full H_w (see add_nodal_forces()) of sums of symmetric stress
     * measures @p H_sym, in deal.II's unrolled order.
     */
    static void
    unfold_symmetric_terms(
      const double (
        &H_sym)[n_terms][SymmetricTensor<2, dim>::n_independent_components],
      double (&H)[n_terms][dim * dim])
    {
#pragma GCC unroll 64
      for (unsigned int w = 0; w < n_terms; ++w)
#pragma GCC unroll 64
        for (unsigned int k = 0; k < n_sym; ++k)
          {
            const auto &ab            = unrolled_indices[k];
            H[w][ab[0] * dim + ab[1]] = H[w][ab[1] * dim + ab[0]] = H_sym[w][k];
          }
    }

    /// grad u at a point with monomials @p m, from the K_w.
    static Tensor<2, dim>
    gradient(const double (&K)[n_terms][dim * dim], const Monomials &m)
    {
      Tensor<2, dim> G;
#pragma GCC unroll 64
      for (unsigned int a = 0; a < dim; ++a)
#pragma GCC unroll 64
        for (unsigned int b = 0; b < dim; ++b)
          {
            double sum = K[0][a * dim + b];
#pragma GCC unroll 64
            for (unsigned int w = 1; w < n_terms; ++w)
              sum += K[w][a * dim + b] * m[w];
            G[a][b] = sum;
          }
      return G;
    }

    /// H_w += m_w S for the stress measure @p S of a point.
    static void
    add_force_terms(const Tensor<2, dim> &S,
                    const Monomials      &m,
                    double (&H)[n_terms][dim * dim])
    {
#pragma GCC unroll 64
      for (unsigned int w = 0; w < n_terms; ++w)
#pragma GCC unroll 64
        for (unsigned int a = 0; a < dim; ++a)
#pragma GCC unroll 64
          for (unsigned int b = 0; b < dim; ++b)
            H[w][a * dim + b] += m[w] * S[a][b];
    }

    /**
     * The nodal forces sum_p S_p grad N_v(x_p) of the sums @p H, added to
     * @p f (vertex by vertex, f[v * dim + a]) with the factor @p sign.
     */
    void
    add_nodal_forces(const double (&H)[n_terms][dim * dim],
                     const double sign,
                     double      *f) const
    {
      // g_v = sum_{d in v} H_{v - 2^d} J^{-T} e_d: the forces on the
      // coefficients c; then the transposed Moebius transform.
      double g[n_vertices][dim] = {};
#pragma GCC unroll 64
      for (unsigned int v = 1; v < n_vertices; ++v)
#pragma GCC unroll 64
        for (unsigned int d = 0; d < dim; ++d)
          if ((v >> d) & 1U)
#pragma GCC unroll 64
            for (unsigned int a = 0; a < dim; ++a)
#pragma GCC unroll 64
              for (unsigned int b = 0; b < dim; ++b)
                g[v][a] +=
                  H[v ^ (1U << d)][a * dim + b] * inverse_jacobian[d][b];
      moebius<true>(g);
#pragma GCC unroll 64
      for (unsigned int v = 0; v < n_vertices; ++v)
#pragma GCC unroll 64
        for (unsigned int a = 0; a < dim; ++a)
          f[v * dim + a] += sign * g[v][a];
    }

  private:
    /**
     * The Moebius transform of vertex values (finite differences over the
     * bits of v: for each direction d, c_v -= c_{v - 2^d} for every v with
     * bit d), nodal values to monomial coefficients; with @p transposed
     * its transpose (c_{v - 2^d} -= c_v), coefficient forces to nodal
     * forces. The steps of different directions commute.
     */
    template <bool transposed>
    static void
    moebius(double (&c)[n_vertices][dim])
    {
#pragma GCC unroll 64
      for (unsigned int d = 0; d < dim; ++d)
#pragma GCC unroll 64
        for (unsigned int v = 0; v < n_vertices; ++v)
          if ((v >> d) & 1U)
#pragma GCC unroll 64
            for (unsigned int a = 0; a < dim; ++a)
              {
                if (transposed)
                  c[v ^ (1U << d)][a] -= c[v][a];
                else
                  c[v][a] -= c[v ^ (1U << d)][a];
              }
    }
  };
} // namespace qsmpm

#endif
