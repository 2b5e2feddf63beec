#ifndef qsmpm_assembly_quasi_static_residual_h
#define qsmpm_assembly_quasi_static_residual_h

#include <Epetra_Export.h>
#include <Epetra_Import.h>
#include <Epetra_Vector.h>
#include <array>
#include <deal.II/lac/trilinos_vector.h>
#include <limits>
#include <memory>
#include <qsmpm/assembly/iterate_kinematics.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <vector>

namespace qsmpm
{
  /**
   * The residual of one load step, paper eqs. (2.14)-(2.25):
   *
   *   R_i(du) = f_ext_i - f_int_i(du),
   *   f_int_i = sum_p Omega_p^{k+1} sigma_p^{k+1} . grad N_i(x_p^k),
   *
   * with f_ext the external force of set_external_force() (2.10-2.12):
   * the paper's R_i = f^int_i + f^ext_i (2.13-2.14), whose f^int
   * (2.9, 2.25) is defined with the minus sign: f^int_paper = -f_int. At
   * every point, d_eps_p = sym(sum_i grad N_i(x_p^k) (x) du_i) (2.18), the
   * trial stress from the constitutive model (2.20-2.21), and
   * Omega_p^{k+1} = (1 + tr d_eps_p) J_p^k Omega_p^0 (2.23-2.24).
   *
   * At finite strain (Kinematics::finite_strain) the same loop computes
   * Delta F_p = I + sum_i du_i (x) grad N_i, F_p = Delta F_p F_p^k, the
   * Kirchhoff stress tau_p from the model, and
   *
   *   f_int_i = sum_p Omega_p^0 tau_p Delta F_p^{-T} . grad N_i(x_p^k),
   *
   * which equals sum_p Omega_p^{k+1} sigma_p . grad_{k+1} N_i. commit()
   * stores F, J = det F, the volume J Omega^0, the Cauchy stress tau / J
   * and the logarithmic strain 1/2 ln(F F^T). An inverted point
   * (det Delta F <= 0) makes the residual non-finite, which Newton's line
   * search backs off from.
   *
   * With VolumetricTreatment::fbar the model sees, at every point, the
   * kinematics with the volume change replaced by the volume-weighted mean
   * over the points of its cell (F-bar, Coombs et al. 2018; at small strain
   * d eps_bar = d eps + (theta_bar - tr d eps)/dim I). At finite strain the
   * forces are integrated with the point's own Delta F (the original,
   * non-symmetric F-bar). At small strain they are the work of the stresses
   * on the virtual F-bar strain, f_int = sum_p Omega_p B_bar_p^T sigma_p
   * (B-bar, the mean dilatation): the volumetric part of the forces is that
   * of the cell's volume-weighted mean stress trace
   * (project_fbar_force_stresses()). The two agree while the pressure is
   * the same at all points of a cell (elasticity); a dilatant plastic flow
   * (Drucker-Prager) makes it differ between the points, and with the
   * standard gradients these differences acted on the points' own volume
   * changes, which the F-bar kinematics gives no stiffness: Newton stalled
   * on the c-phi footing (issue 31).
   *
   * The sums over i run over each point's stencil in the ShapeCache: the
   * 2^dim vertices of its cell (linear) or 3^dim nodes (GIMP). On affine
   * cells with linear shape functions both sums are done per cell in the
   * monomial form of AffineQ1Cell, from the points' positions. The
   * evaluations read the committed state from a packed copy of the fields
   * the model declares (ConstitutiveModel::batch_fields()).
   *
   * evaluate() is pure: it reads the committed point state, writes only
   * the residual, and returns what else it found (Evaluation). This is what
   * makes finite-difference Jacobian-vector products, line searches and
   * rejected steps safe; the types say so, as evaluate() is const and reads
   * the points through a read-only reference, and the ShapeCache hands out
   * writable point data only to the holder of the writable point set, which
   * only commit() uses: it evaluates the same formulas once more for the
   * converged increment and stores strain, stress, model state, J and
   * volume on the points.
   *
   * The residual includes the rows of constrained degrees of freedom: there,
   * -R_i = f_int_i - f_ext_i is the reaction force of the support (the
   * force it exerts on the body).
   */
  template <int dim>
  class QuasiStaticResidual
  {
  public:
    /**
     * What an evaluation finds besides the residual, on this rank's points.
     */
    struct Evaluation
    {
      /**
       * The smallest J = det F (finite strain) or J = (1 + tr d eps) J_old
       * (small strain) at the increment; +infinity on a rank without
       * points. A converged increment with J <= 0 somewhere has turned a
       * point inside out (possible at small strain, where the residual
       * stays finite) and must be rejected.
       */
      double minimum_volume_ratio = std::numeric_limits<double>::infinity();
      /**
       * The energy the points dissipate in the trial state
       * (ConstitutiveModel::dissipation() times the point volume at the
       * start of the step); 0 if the model computes none.
       */
      double dissipation = 0.;
    };

    /**
     * @p update_volumes = false keeps Omega_p = Omega_p^0 (a geometrically
     * linear model, used to compare with linear finite elements). The
     * residual keeps @p points; only commit() writes to them.
     */
    QuasiStaticResidual(const BackgroundGrid<dim> &grid,
                        MaterialPointSet<dim>     &points,
                        const ShapeCache<dim>     &cache,
                        const bool                 update_volumes = true);

    /// Size the internal vectors; call after the grid's dofs changed.
    void
    reinit();

    /// The external force of the step (see ExternalForceAssembler).
    void
    set_external_force(const TrilinosWrappers::MPI::Vector &f_ext);

    /**
     * The kinematics of the points at the increment @p du, as evaluate()
     * hands them to the constitutive model: at small strain the strain
     * increments (F-bar's mean volume change included), at finite strain
     * the deformation increments Delta F and, with F-bar, their cells'
     * mean volume changes (at small strain with a dilatant model each
     * point's share, share_plastic_volume_changes()); in axisymmetric
     * problems the hoop
     * strain increments as well. For the stiffness at a Newton
     * iterate (TangentAssembler), which leaves out the terms of the
     * share.
     */
    void
    iterate_kinematics(const TrilinosWrappers::MPI::Vector &du,
                       IterateKinematics<dim>              &kinematics) const;

    /// R = f_ext - f_int(du). Does not change any point.
    Evaluation
    evaluate(const TrilinosWrappers::MPI::Vector &du,
             TrilinosWrappers::MPI::Vector       &R) const;

    /**
     * Store the state of the converged increment on the points of the
     * constructor. @p du_ghosted holds the increment with the layout of
     * ghosted_layout() (the caller imports the ghost entries once and moves
     * the points with the same vector).
     */
    void
    commit(const TrilinosWrappers::MPI::Vector &du_ghosted);

    /**
     * Say that the committed fields of the points changed within the step
     * (PorePressureSolver writes the pressure iterate into them): the
     * residual's packed copy of them is made anew at the next evaluate().
     */
    void
    point_state_changed()
    {
      packed_generation = std::numeric_limits<unsigned long>::max();
    }

    /// A vector with the locally relevant layout (for ShapeCache::reinit).
    const TrilinosWrappers::MPI::Vector &
    ghosted_layout() const;

    /**
     * Copy @p du (the grid's owned layout) into @p ghosted (a copy of
     * ghosted_layout()) with its ghost entries, by the import that
     * evaluate() uses: without building the exchange anew, as the
     * assignment of the two vectors would.
     */
    void
    import_ghosts(const TrilinosWrappers::MPI::Vector &du,
                  TrilinosWrappers::MPI::Vector       &ghosted) const;

    /**
     * The l2 norm of a displacement of one (smallest) cell size at every
     * degree of freedom: the scale of finite-difference steps taken at
     * du = 0 (see JacobianFreeOperator).
     */
    double
    typical_increment_norm() const;

  private:
    /**
     * Scratch space for the points of a block of cells (see loop()): grad
     * du, the strain increments, the trial stresses and fields, the
     * volume-weighted stress measures of the forces, the monomials of
     * AffineQ1Cell, the volumes and, for F-bar at finite strain, the mean
     * volume change of each point's cell. Point p is entry p - block_first.
     */
    struct Scratch
    {
      std::vector<Tensor<2, dim>>                        grad_du;
      std::vector<SymmetricTensor<2, dim>>               strain_increment;
      std::vector<SymmetricTensor<2, dim>>               stress;
      std::vector<double>                                state;
      std::vector<Tensor<2, dim>>                        force_stress;
      std::vector<typename AffineQ1Cell<dim>::Monomials> monomials;
      std::vector<double>                                volume;
      std::vector<double>                                mean_volume_change;
      /// Axisymmetric: the points' shape-function values N_k(x_p) over
      /// their radius r_p, k over the point's stencil (the cell's vertices,
      /// or GIMP's up to 3 x 3 nodes), once for the hoop strain and its
      /// force; the hoop strain increments, the trial hoop stresses and the
      /// points' volume times hoop stress (the hoop force's measure).
      std::vector<std::array<double, ShapeCache<dim>::max_stencil_size>>
                          hoop_values;
      std::vector<double> hoop_increment;
      std::vector<double> hoop_stress;
      std::vector<double> hoop_force;
      /// F-bar with dilatant plastic flow (share_plastic_volume_changes()):
      /// per point the elastic volume change of the last pass, the slope
      /// d(elastic)/d(total) volume change and the last shift of its
      /// volume change.
      std::vector<double> elastic_volume_change;
      std::vector<double> elastic_volume_slope;
      std::vector<double> volume_shift;
      unsigned int        block_first = 0;

      /// Start the block of @p n_points points from @p first, with
      /// @p n_state state variables each; the arrays only grow.
      void
      start_block(const unsigned int first,
                  const unsigned int n_points,
                  const unsigned int n_state)
      {
        block_first = first;
        if (grad_du.size() < n_points)
          {
            grad_du.resize(n_points);
            strain_increment.resize(n_points);
            stress.resize(n_points);
            force_stress.resize(n_points);
            monomials.resize(n_points);
            volume.resize(n_points);
            mean_volume_change.resize(n_points);
            hoop_values.resize(n_points);
            hoop_increment.resize(n_points);
            hoop_stress.resize(n_points);
            hoop_force.resize(n_points);
            elastic_volume_change.resize(n_points);
            elastic_volume_slope.resize(n_points);
            volume_shift.resize(n_points);
            state.resize(n_points * n_state);
          }
      }
    };

    /// The cells of a block of loop() and iterate_kinematics() (blocks of
    /// 8 cells were the fastest; the figures are in doc/benchmarks.md).
    static constexpr unsigned int block_cells = 8;

    /// What the loop does, the same for all blocks of cells.
    struct LoopKind
    {
      bool finite_strain;
      bool fbar;
      /// Small strain without F-bar: sym(grad du) suffices.
      bool symmetric_small_strain;
      /// Axisymmetric (r, z): the hoop strain from the shape functions'
      /// values, and its force; the cells' stored or computed gradients
      /// instead of AffineQ1Cell's monomial form.
      bool axisymmetric;
      /// Linear shape functions: every point's stencil is the cell's
      /// vertices in their order, known at compile time.
      bool vertex_stencil;
    };

    LoopKind
    loop_kind() const;

    /**
     * The loop over cells and their points shared by evaluate() and
     * commit(), with du in the local storage @p du_values of a vector with
     * the layout of ghosted_layout(). evaluate() adds the forces into
     * @p force, the local storage of a vector of the same layout, and
     * records in @p result; commit() writes the state into the points.
     *
     * Per block of a few cells: block_kinematics(), block_stresses() and
     * (evaluate()) block_forces(), with the block's points in the scratch
     * arrays.
     */
    template <bool write_back>
    void
    loop(const double *du_values, double *force, Evaluation &result) const;

    /**
     * grad du (or, where it suffices, sym grad du) at all points of the
     * cells [@p c0, @p c1), and the strain increments (with F-bar the
     * cells' mean volume changes).
     */
    void
    block_kinematics(const LoopKind    &kind,
                     const unsigned int c0,
                     const unsigned int c1,
                     const double      *du_values) const;

    /// The committed states of the @p n_points points from @p first, as
    /// the model reads them.
    PointStateBatch<dim>
    committed_batch(const unsigned int first,
                    const unsigned int n_points) const;

    /**
     * The stresses of the block's @p n_points points from @p first (one
     * call of ConstitutiveModel::update_stresses() at small strain) and
     * with them the volume-weighted stress measures of the forces and,
     * for evaluate(), the dissipation; commit() writes the state.
     */
    template <bool write_back>
    void
    block_stresses(const LoopKind    &kind,
                   const unsigned int first,
                   const unsigned int n_points,
                   Evaluation        &result) const;

    /**
     * F-bar at small strain with a model whose plastic flow changes the
     * volume and that keeps its elastic strain apart
     * (ConstitutiveModel::elastic_volume_strains(); IsotropicPlasticity with
     * dilatancy: Drucker-Prager, Mohr-Coulomb, Modified Cam Clay; also as
     * a member of a MaterialMap or the skeleton of a PoroelasticModel;
     * a point of a model that does not split its strain counts its whole
     * volume change as elastic): block_stresses() for the cells
     * [@p c0, @p c1)
     * after the volume change of each point is split into the cell's
     * common elastic part and the point's own plastic part.
     *
     * Plain F-bar gives every point of a cell the cell's mean volume
     * change. Associated flow ties a point's plastic volume change to its
     * own plastic shear (tr d eps_p = sin psi gamma_p for Mohr-Coulomb), so
     * at collapse, where the elastic strains stop changing, every plastic
     * point of a cell would have to shear alike: a constraint per point
     * that a bilinear cell cannot meet, and the limit load keeps rising
     * (dilatancy locking; Sloan and Randolph 1982, de Borst and Vermeer
     * 1984). Here the volume change of point p is theta_bar + g_p - g_bar,
     * g_p its plastic volume change in the step and g_bar the cell's
     * volume-weighted mean: the cell as a whole still changes its volume
     * by theta_bar, every point changes its elastic volume (its pressure)
     * by the same amount, and only one constraint per cell remains, as in
     * the mixed Q1-P0 element. g_p depends on the return mapping at the
     * point's own volume change: the split is solved per cell by a Newton
     * iteration on the common elastic volume change with the points'
     * secant slopes, a few passes of the model over the block, to 1e-12
     * of the block's strain increments. Where no point of a cell changes
     * its plastic volume (elastic points, von Mises, psi = 0) g_p = 0 and
     * this is plain F-bar (one pass). Finite-strain and axisymmetric
     * problems keep plain F-bar.
     */
    template <bool write_back>
    void
    share_plastic_volume_changes(const LoopKind    &kind,
                                 const unsigned int c0,
                                 const unsigned int c1,
                                 Evaluation        &result) const;

    /**
     * One Newton update of share_plastic_volume_changes() on the cells
     * [@p c0, @p c1) from the elastic volume changes of the last pass;
     * false (and nothing changed) where they already agree within each
     * cell.
     */
    bool
    update_volume_shares(const unsigned int c0,
                         const unsigned int c1,
                         const bool         first_pass) const;

    /// The forces of the cells [@p c0, @p c1), added into @p force.
    void
    block_forces(const LoopKind    &kind,
                 const unsigned int c0,
                 const unsigned int c1,
                 double            *force) const;

    /**
     * grad du at the points of the cache's cell @p c into Scratch::grad_du,
     * from the cell's values @p du_cell, with the stored shape-function
     * gradients (GIMP, or a cell that is not affine). With
     * @p vertex_stencil (linear shape functions) every stencil is the
     * cell's vertices in their order, and the loops have fixed bounds.
     */
    template <bool vertex_stencil>
    void
    cell_gradients(const double *du_cell, const unsigned int c) const;

    /**
     * cell_gradients() on an affine cell with linear shape functions, from
     * the points' positions (see AffineQ1Cell), keeping the points'
     * monomials in Scratch::monomials for the forces. With @p symmetric
     * (small strain without F-bar) only sym(grad du), the strain
     * increments, straight into Scratch::strain_increment (from the
     * symmetric parts of the K_w), without grad du.
     */
    template <bool symmetric>
    void
    affine_cell_kinematics(
      const AffineQ1Cell<dim>                   &affine,
      const double                              *du_cell,
      const typename ShapeCache<dim>::CellRange &range) const;

    /**
     * The forces of affine_cell_kinematics<true>(): from the stresses in
     * Scratch::stress and the volumes in Scratch::volume of the points of
     * the cell @p range, summed over their symmetric entries.
     */
    void
    add_affine_symmetric_forces(
      const AffineQ1Cell<dim>                   &affine,
      const typename ShapeCache<dim>::CellRange &range,
      double                                    *f_cell) const;

    /// add_cell_forces() on an affine cell with linear shape functions.
    void
    add_affine_cell_forces(const AffineQ1Cell<dim>                   &affine,
                           const typename ShapeCache<dim>::CellRange &range,
                           double *f_cell) const;

    /**
     * Subtract the internal forces of the points of the cache's cell @p c,
     * from their stress measures in Scratch::force_stress, from the cell's
     * forces @p f_cell (stored gradients, as cell_gradients()).
     */
    template <bool vertex_stencil>
    void
    add_cell_forces(const unsigned int c, double *f_cell) const;

    /**
     * Axisymmetric: the hoop strain increments d u_r / r of the points of
     * the cache's cell @p c into Scratch::hoop_increment, and the values
     * N_k / r they come from into Scratch::hoop_values.
     */
    void
    cell_hoop_increments(const double *du_cell, const unsigned int c) const;

    /**
     * Axisymmetric: subtract the hoop forces, sum_p Omega_p sigma_thetatheta
     * N_i(x_p) / r_p in the radial direction, of the points of the cache's
     * cell @p c (from Scratch::hoop_force, with F-bar the projected
     * measure, and Scratch::hoop_values) from @p f_cell.
     */
    void
    add_hoop_forces(const unsigned int c, double *f_cell) const;

    /**
     * Axisymmetric finite strain: finite_strain_stresses() with the hoop
     * stretch 1 + d u_r / r_n of each point (with F-bar the cell's mean
     * volume change shared by the three directions), the hoop Kirchhoff
     * stress from ConstitutiveModel::update_kirchhoff_stress_axisymmetric()
     * and its force; commit() writes the logarithmic hoop strain ln(r / R)
     * and the hoop Cauchy stress.
     */
    template <bool write_back>
    void
    axisymmetric_finite_strain_stresses(const PointStateBatch<dim> &old,
                                        const unsigned int          first,
                                        Evaluation &result) const;

    /**
     * Axisymmetric small strain: the points' trial stresses one by one
     * (ConstitutiveModel::update_stress_axisymmetric()), J and the
     * volumes, as small_strain_stresses(); commit() also writes the hoop
     * strain and stress.
     */
    template <bool write_back>
    void
    axisymmetric_stresses(const PointStateBatch<dim> &old,
                          const unsigned int          first,
                          Evaluation                 &result) const;

    /**
     * Small strain: from the strain increments in Scratch::strain_increment
     * of the points @p first, ... of the block's batch @p old, their trial
     * stresses from one call of the model's batched update, and J and the
     * volume at the end of the step. evaluate() keeps the volumes in
     * Scratch::volume and volume times stress in Scratch::force_stress (the
     * latter not if every cell's forces come from
     * add_affine_symmetric_forces()); commit() writes strain, stress, J
     * and volume into the points.
     */
    template <bool write_back>
    void
    small_strain_stresses(const PointStateBatch<dim> &old,
                          const unsigned int          first,
                          Evaluation                 &result) const;

    /**
     * Finite strain: F = Delta F F_old and the Kirchhoff stress at each
     * point of the batch (with F-bar, the cell's mean volume change from
     * Scratch::mean_volume_change); evaluate() keeps Omega_0 P = Omega_0 tau
     * Delta F^{-T} in Scratch::force_stress (NaN at an inverted point);
     * commit() writes the logarithmic strain, Cauchy stress, F, J and the
     * volume.
     */
    template <bool write_back>
    void
    finite_strain_stresses(const PointStateBatch<dim> &old,
                           const unsigned int          first,
                           Evaluation                 &result) const;

    /**
     * F-bar: the volume-weighted mean over the points of the cell @p range
     * of the volume change of the step, Delta J (finite strain) or tr d eps
     * (small strain), from the gradients in Scratch::grad_du.
     */
    double
    cell_mean_volume_change(const typename ShapeCache<dim>::CellRange &range,
                            const bool finite_strain) const;

    /**
     * F-bar at small strain: replace the stress measures in
     * force_stress_scratch of the points of the cell @p range by those of
     * the forces B_bar^T sigma (the work on the virtual F-bar strain), whose
     * volumetric part is the cell's mean stress trace.
     */
    void
    project_fbar_force_stresses(
      const typename ShapeCache<dim>::CellRange &range) const;

    /**
     * The committed state of point @p p (in the cache's order) that the
     * evaluations read: its record in the packed copy, or its property
     * array if there is no packed copy. Offsets in it: state_layout and
     * own_offsets.
     */
    const double *
    committed(const unsigned int p) const
    {
      return packed_record > 0 ?
               packed.data() + std::size_t(p) * packed_record :
               cache.properties(p);
    }

    /// Gather the packed copy from the points, if the cache changed.
    void
    update_packed_state() const;

    const BackgroundGrid<dim>   &grid;
    const MaterialPointSet<dim> &points;
    /// The same points, for commit() only.
    MaterialPointSet<dim>        &writable_points;
    const ShapeCache<dim>        &cache;
    const ConstitutiveModel<dim> &model;
    const bool                    update_volumes;

    TrilinosWrappers::MPI::Vector f_ext;
    /// Scratch: du with ghost entries, and the force on the same layout.
    mutable TrilinosWrappers::MPI::Vector  du_ghosted;
    mutable std::unique_ptr<Epetra_Vector> local_force;
    /// Whether the model computes a dissipation (ConstitutiveModel::
    /// computes_dissipation()): if not, Evaluation::dissipation is 0 without
    /// asking it at every point.
    const bool track_dissipation;
    /// Where the model's batched update finds the point state (in the
    /// packed record, or in the property array without a packed copy).
    typename PointStateBatch<dim>::Layout state_layout;
    /**
     * Whether share_plastic_volume_changes() splits the points' volume
     * changes: F-bar at small strain (not axisymmetric), a batch that
     * carries the model state and a model whose plastic flow can change
     * the volume (ConstitutiveModel::plastic_flow_changes_volume()).
     */
    bool share_volume_changes = false;
    /// Where the residual's own fields are in the same data: J, the
    /// initial volume, the volume (F-bar) and F (finite strain).
    typename MaterialPointSet<dim>::Offsets own_offsets;
    /**
     * The committed state the evaluations of a load step read, packed:
     * per point, in the cache's order, the doubles of the property array at
     * packed_sources (the fields of ConstitutiveModel::batch_fields() and
     * the residual's own), packed_record of them. With a linear elastic
     * model in 2D five doubles instead of the twelve of the property
     * array: the residual streams 40 instead of 96 bytes of state per
     * point. Gathered again when the cache was reinitialized and after
     * commit(); without it (packed_record = 0: the record would be more
     * than half the array) the property arrays are read in place.
     */
    mutable std::vector<double> packed;
    std::vector<unsigned int>   packed_sources;
    unsigned int                packed_record = 0;
    /// The cache's generation() of the packed copy; none (the largest
    /// number) before the first gathering and after commit().
    mutable unsigned long packed_generation =
      std::numeric_limits<unsigned long>::max();
    mutable Scratch scratch;
    /// Communication plans owned -> relevant and back, built once: deal.II's
    /// vector assignment between layouts would rebuild one per evaluation.
    std::unique_ptr<Epetra_Import> importer;
    std::unique_ptr<Epetra_Export> exporter;
    /// Whether the ghosted layout is the owned one (one rank): evaluate()
    /// then needs neither.
    bool same_layout = false;
  };
} // namespace qsmpm

#endif
