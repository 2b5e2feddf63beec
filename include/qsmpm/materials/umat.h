#ifndef qsmpm_materials_umat_h
#define qsmpm_materials_umat_h

#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/materials/umat_library.h>

namespace qsmpm
{
  /**
   * A constitutive model given as an Abaqus/Standard UMAT subroutine in a
   * shared library: a user's Fortran or C model runs unchanged at the
   * material points (doc/user_models.md, section "Abaqus UMAT").
   *
   * <h3>What the UMAT receives</h3>
   * - NDI = 3 direct and NSHR = 1 (2D plane strain: xx, yy, zz, xy) or 3
   *   (3D: xx, yy, zz, xy, xz, yz) shear components, Abaqus's order, with
   *   engineering shear strains (gamma_xy = 2 eps_xy); DDSDDE(NTENS,NTENS)
   *   = d(Delta sigma)/d(Delta eps) in that order. In 2D, DSTRAN(3) = 0
   *   and the out-of-plane stress STRESS(3) is kept between steps.
   * - STRESS, STATEV, STRAN, SSE/SPD/SCD of the point's committed state at
   *   the start of the load step (every residual evaluation of the
   *   Jacobian-free Newton-Krylov solver calls the UMAT again from that
   *   state with the current trial increment, as Abaqus does in its
   *   iterations; only the converged result is kept).
   * - PROPS, NPROPS from "Properties"; NSTATV from "Number of state
   *   variables", STATEV initially "Initial state variables"; CMNAME
   *   "Material name" (blank-padded to 80 characters).
   * - COORDS the point's position at the start of the step (z = 0 in 2D);
   *   CELENT = volume^(1/dim) (the side of the square or cube of the
   *   point's volume); NOEL = the point's id + 1, NPT = 1; LAYER = KSPT =
   *   KSTEP = KINC = 1.
   * - TIME = (0, 0), DTIME = 1: quasi-static load steps have no time, so a
   *   rate-dependent UMAT sees one unit of time per step. TEMP = DTEMP = 0,
   *   no predefined fields.
   * - Small strain: DROT, DFGRD0 and DFGRD1 the identity.
   *
   * <h3>Finite strain</h3>
   * Abaqus's co-rotational convention (Kinematics = finite strain): with
   * the polar decomposition of the step's increment Delta F = Delta R
   * Delta U = Delta V Delta R, the UMAT gets DROT = Delta R, the committed
   * STRESS and STRAN rotated by it (Delta R sigma Delta R^T), the
   * logarithmic strain increment DSTRAN = ln(Delta V), DFGRD0 = F_old and
   * DFGRD1 = F. The Cauchy stress it returns gives the Kirchhoff stress
   * tau = det(F) sigma of the qsmpm interface. A pure rotation therefore
   * rotates the stress exactly (objectivity); the rate is the one of the
   * Green-Naghdi/ Jaumann family that Abaqus uses for an increment whose
   * rotation is applied at once. The tangent handed to the preconditioner
   * is the one Abaqus assembles from DDSDDE (Jaumann rate of Kirchhoff
   * stress, here d tau = c : d l):
   *
   *   c_ijkl = J D_ijkl + tau_ij delta_kl
   *          + J/2 (delta_ik sigma_lj - delta_il sigma_kj
   *                 - sigma_ik delta_jl + sigma_il delta_jk),
   *
   * D the DDSDDE as a fourth-order tensor; Newton's Jacobian is the
   * exact one of the residual regardless (Jacobian-free).
   *
   * <h3>Failures</h3>
   * PNEWDT < 1 (the UMAT asks for a smaller increment) and a stress that
   * is not a finite number both make the trial stress NaN: the Newton
   * iteration reports a residual that is not a finite number and the load
   * step is cut back, as Abaqus does; if the cut-backs do not help, the run
   * stops. A stress that is not finite is reported once per run on the
   * rank where it happened, with the material name, the point and its
   * position.
   *
   * <h3>Checks when the model is created</h3>
   * Two probe calls at the initial state, a zero strain increment and a
   * shear strain of 5 % (beyond the elastic range of soils, concrete and
   * metals, so that a plastic model takes its plastic branch), with PROPS
   * followed by NaN and STATEV by zeros: a UMAT that changes a value
   * beyond NSTATV ("Number of state variables" too small) or returns a
   * stress or DDSDDE that is not finite for the zero increment (it read a
   * property beyond NPROPS: "Properties" too short) stops the run with a
   * message naming the entry. What the probes cannot see (a UMAT that
   * writes beyond NSTATV only in states it does not reach from the
   * initial one) they do not claim to.
   *
   * Selected in a .prm file with `set Model = umat`, or per material id
   * in a material map.
   */
  template <int dim>
  class Umat : public ConstitutiveModel<dim>
  {
  public:
    /// The subsection "umat".
    struct Parameters : ParameterStruct<Parameters>
    {
      std::string         library;
      std::string         symbol        = "umat_";
      std::string         material_name = "UMAT";
      std::vector<double> properties;
      unsigned int        n_state_variables = 0;
      std::vector<double> initial_state_variables;
      /// 1-based index of STATEV's first component of the elastic strain
      /// (0: the UMAT does not say where it keeps one).
      unsigned int elastic_strain_state_variable = 0;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    /// Load the UMAT and check it with the probe calls.
    explicit Umat(const Parameters &parameters);

    /// Construct from the subsection "umat".
    explicit Umat(ParameterHandler &prm);

    static void
    declare_parameters(ParameterHandler &prm);

    std::string
    name() const override;

    /**
     * "umat_statev" (NSTATV), "umat_strain" (STRAN, NTENS components),
     * "umat_stress_zz" (2D only: the out-of-plane stress), "umat_energy"
     * (SSE, SPD, SCD) and "umat_noel" (NOEL).
     */
    std::vector<StateField>
    state_fields() const override;

    void
    initialize_point_state(const Point<dim>           &x,
                           const unsigned int          material_id,
                           const types::particle_index id,
                           ArrayView<double>           state) const override;

    void
    initialize_state(const Point<dim> &x,
                     ArrayView<double> state) const override;

    /// True: the stress is the committed one plus an increment.
    bool
    incremental_stress() const override
    {
      return true;
    }

    void
    update_stress(const PointState<dim>         &old,
                  const SymmetricTensor<2, dim> &strain_increment,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double>              new_state) const override;

    /// DDSDDE for a zero increment from the committed state.
    SymmetricTensor<4, dim>
    tangent(const PointState<dim> &old) const override;

    /// DDSDDE for the increment @p strain_increment.
    SymmetricTensor<4, dim>
    consistent_tangent(
      const PointState<dim>         &old,
      const SymmetricTensor<2, dim> &strain_increment) const override;

    /**
     * With "Elastic strain state variable" = k: the traces of the elastic
     * strain the UMAT keeps in STATEV(k), STATEV(k+1), STATEV(k+2) (the
     * direct components, Abaqus's order) at the committed and the trial
     * state, for F-bar's split of the volume change. Without the entry
     * nothing: the point's whole volume change counts as elastic.
     */
    std::optional<std::array<double, 2>>
    elastic_volume_strains(const PointState<dim>  &old,
                           ArrayView<const double> new_state) const override;

    /// True with "Elastic strain state variable".
    bool
    plastic_flow_changes_volume() const override;

    bool
    supports_finite_strain() const override;

    void
    update_kirchhoff_stress(const PointState<dim>             &old,
                            const FiniteStrainKinematics<dim> &kinematics,
                            SymmetricTensor<2, dim>           &tau,
                            ArrayView<double> new_state) const override;

    Tensor<4, dim>
    kirchhoff_tangent(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;

  private:
    /// NTENS: 4 in 2D (plane strain), 6 in 3D.
    static constexpr unsigned int n_tensor = (dim == 2 ? 4 : 6);

    /// The arguments of one UMAT call that change from point to point.
    struct Call
    {
      double stress[6];
      double ddsdde[36];
      double energy[3];
      double stran[6];
      double dstran[6];
      double drot[9];
      double dfgrd0[9];
      double dfgrd1[9];
      double coords[3];
      double celent;
      double pnewdt;
      int    noel;
    };

    /**
     * Fill @p call from the committed state @p old (stress, STRAN,
     * energies, COORDS, CELENT, NOEL) with rotation @p rotation applied
     * to the stress and strain, and copy the committed STATEV to
     * @p statev.
     */
    void
    prepare(const PointState<dim> &old,
            const Tensor<2, 3>    &rotation,
            Call                  &call,
            double                *statev) const;

    /// prepare() without rotation, DSTRAN from @p strain_increment, DROT,
    /// DFGRD0 and DFGRD1 the identity.
    void
    prepare_small_strain(const PointState<dim>         &old,
                         const SymmetricTensor<2, dim> &strain_increment,
                         Call                          &call,
                         double                        *statev) const;

    /// prepare() for the finite-strain step @p kinematics (see the class
    /// documentation); false if det F or det Delta F is not positive.
    bool
    prepare_finite_strain(const PointState<dim>             &old,
                          const FiniteStrainKinematics<dim> &kinematics,
                          Call                              &call,
                          double                            *statev) const;

    /// Call the UMAT with the properties @p props.
    void
    raw_call(Call &call, double *statev, double *props) const;

    /// Call the UMAT; false if it asked for a smaller increment or
    /// returned a stress that is not finite (reported once).
    bool
    invoke(Call &call, double *statev, const PointState<dim> &old) const;

    /// Write the result of @p call into the model's fields @p new_state
    /// (STRAN, the out-of-plane stress, the energies and NOEL; STATEV the
    /// UMAT wrote there in place, from prepare()'s copy).
    void
    store(const Call &call, ArrayView<double> new_state) const;

    /// DDSDDE as a 3D fourth-order tensor.
    SymmetricTensor<4, 3>
    ddsdde_tensor(const Call &call) const;

    /// The probe calls (see the class documentation).
    void
    probe() const;

    Parameters   parameters;
    UmatFunction umat;
    /// CMNAME, blank-padded to 80 characters.
    mutable char cmname[80];
    /// Offsets of the fields in the state.
    unsigned int strain_offset, stress_zz_offset, energy_offset, noel_offset;
    /// Whether a stress that is not finite has been reported.
    mutable bool reported = false;
  };
} // namespace qsmpm

#endif
