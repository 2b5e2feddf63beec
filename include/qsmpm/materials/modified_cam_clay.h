#ifndef qsmpm_materials_modified_cam_clay_h
#define qsmpm_materials_modified_cam_clay_h

#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/materials/isotropic_plasticity.h>

namespace qsmpm
{
  /**
   * Modified Cam Clay (Roscoe & Burland 1968): the critical-state model of
   * a clay, with a pressure-dependent elastic stiffness, small or finite
   * strain (see IsotropicPlasticity for the state fields, the 2D
   * plane-strain treatment and the finite-strain exponential map).
   *
   * Soil mechanics' signs inside: the mean effective pressure p = -tr(sigma)
   * / 3 and the volumetric strain v = -tr(eps) are positive in compression;
   * q = sqrt(3/2) |dev sigma| is the deviatoric stress. The stress of the
   * point is the effective stress (tension positive, as everywhere in
   * qsmpm).
   *
   * <h3>Elasticity: hyperelastic, stiffer with pressure</h3>
   * With the elastic strain eps_e, its volumetric part v_e = -tr(eps_e) and
   * deviator e_e,
   *
   *   p = p0 exp(v_e / kappa),     s = 2 G e_e,
   *
   * the derivative of the energy p0 kappa exp(v_e / kappa) + G |e_e|^2
   * (Houlsby 1985: a constant shear modulus with this bulk law is
   * conservative): the bulk modulus K = p / kappa grows with the pressure,
   * and the swelling lines are straight in (ln p, v). p0, the "Initial
   * pressure", is the pressure of the unstrained point: every point starts
   * in the isotropic state sigma = -p0 I (a body of this model needs
   * boundary tractions that balance it; see doc/example_triaxial.md),
   * unless `Material points/Initial stress` gives another (compressive,
   * inside the yield surface; the elastic law keeps p0 as its reference).
   * A layer whose stress grows with depth has a preconsolidation pressure
   * that grows with it: `Overconsolidation ratio` = OCR >= 1 puts each
   * point's yield surface through the stress it starts from, scaled by OCR
   * (1: normally consolidated), instead of the one `Preconsolidation
   * pressure` for all.
   *
   * <h3>Yield surface, flow, hardening</h3>
   *
   *   f = q^2 / M^2 + p (p - p_c) <= 0,
   *
   * an ellipse through the origin and p = p_c, with its top on the
   * critical-state line q = M p. Associative flow, d eps_p = d gamma df /
   * d sigma. The preconsolidation pressure hardens with the plastic
   * compaction alpha = -tr(eps_p) (the state's "equivalent_plastic_strain"):
   *
   *   p_c = p_c0 exp(alpha / (lambda - kappa)),
   *
   * so that an isotropic compression on the normal consolidation line
   * gives ln p = v / lambda. lambda and kappa are the slopes of the normal
   * compression and swelling lines in (ln p, v) with v the logarithmic
   * volumetric strain (lambda / (1 + e0) and kappa / (1 + e0) of the
   * (ln p, e) plot at the void ratio e0).
   *
   * <h3>Return mapping</h3>
   * Backward Euler (closest point in the metric of the elastic law, Borja
   * & Lee 1990): the deviator returns radially, q = q_tr / (1 + 6 G
   * d gamma / M^2), and the two unknowns ln p and d gamma solve
   *
   *   d alpha = d gamma (2 p - p_c),   f(p, q, p_c) = 0,
   *
   * where d alpha = v_tr - kappa ln(p / p0) is the plastic compaction of
   * the step and p_c = p_c,old exp(d alpha / (lambda - kappa)), by
   * Newton's method with backtracking on the scaled residual (to 1e-14). Since
   * the elastic law and the hardening are exact functions of the state, the
   * volumetric strain and p_c of a point on the surface are those of the
   * closed-form paths whatever the step size; only the plastic shear
   * strain carries the first-order error of backward Euler.
   *
   * <h3>Tangents</h3>
   * consistent_tangent() and the finite-strain kirchhoff_tangent() use the
   * algorithmic tangent of the return, exact (the implicit derivative of
   * the 2 x 2 system). The preconditioner's tangent at a committed state
   * (tangent(), the rule of IsotropicPlasticity) is the elastic one at the
   * committed pressure, K = p / kappa.
   *
   * Selected in a .prm file with `set Model = Modified Cam Clay`;
   * parameters in subsection "Modified Cam Clay": "Shear modulus",
   * "Swelling index", "Compression index", "Critical state slope",
   * "Initial pressure", "Preconsolidation pressure".
   */
  template <int dim>
  class ModifiedCamClay : public IsotropicPlasticity<dim>
  {
  public:
    using typename IsotropicPlasticity<dim>::Return;

    /// The subsection "Modified Cam Clay".
    struct Parameters : ParameterStruct<Parameters>
    {
      double shear_modulus             = 1e4;
      double swelling_index            = 0.01;
      double compression_index         = 0.05;
      double critical_state_slope      = 1.;
      double initial_pressure          = 100.;
      double preconsolidation_pressure = 100.;
      double overconsolidation_ratio   = 0.;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);

      /**
       * Throws, naming the entry, unless G > 0, 0 < kappa < lambda, M > 0,
       * 0 < p0 <= p_c0 (without OCR; with it 0 < p_c0) and OCR = 0 or
       * OCR >= 1.
       */
      void
      check() const;
    };

    explicit ModifiedCamClay(const Parameters &parameters);

    /// Construct from the subsection "Modified Cam Clay".
    explicit ModifiedCamClay(ParameterHandler &prm);

    static void
    declare_parameters(ParameterHandler &prm);

    std::string
    name() const override
    {
      return "Modified Cam Clay";
    }

    /// The parameters the model was made with.
    const Parameters &
    parameters() const;

    /// The preconsolidation pressure p_c(alpha).
    double
    preconsolidation_pressure(const double alpha) const;

    /**
     * IsotropicPlasticity::initial_stress(); with an `Overconsolidation
     * ratio` OCR > 0 the point's yield surface first goes through the
     * stress it starts from (@p sigma0, or -p0 I without it), scaled by
     * OCR: p_c = OCR (p + q^2 / (M^2 p)), the point's alpha set to
     * (lambda - kappa) ln(p_c / p_c0). Throws, naming `Initial stress`,
     * for a start with p <= 0.
     */
    SymmetricTensor<2, dim>
    initial_stress(const Point<dim>            &x,
                   const unsigned int           material_id,
                   const SymmetricTensor<2, 3> *sigma0,
                   ArrayView<double>            state) const override;

    /// p = p0 exp(v_e / kappa), s = 2 G e_e.
    SymmetricTensor<2, 3>
    elastic_stress(const SymmetricTensor<2, 3> &eps_e) const override;

    /// (p / kappa) 1 (x) 1 + 2 G (I - 1/3 1 (x) 1) at @p eps_e.
    SymmetricTensor<4, 3>
    elastic_tangent(const SymmetricTensor<2, 3> &eps_e) const override;

    /// The elastic strain whose stress is @p stress (elastic_stress()
    /// inverted; needs p > 0).
    SymmetricTensor<2, 3>
    elastic_strain_of(const SymmetricTensor<2, 3> &stress) const override;

    void
    return_map(const SymmetricTensor<2, 3> &trial_elastic_strain,
               const double                 alpha_old,
               const bool                   want_tangent,
               Return                      &r) const override;

    /// The algorithmic tangent of an infinitesimal plastic step past the
    /// surface at @p stress (on it).
    SymmetricTensor<4, 3>
    continuum_tangent(const SymmetricTensor<2, 3> &stress,
                      const double                 alpha) const override;

    /// f = q^2 / M^2 + p (p - p_c(alpha)) (a stress squared).
    double
    yield_function(const SymmetricTensor<2, 3> &stress,
                   const double                 alpha) const override;

  private:
    const Parameters param;
  };
} // namespace qsmpm

#endif
