#ifndef qsmpm_porous_pore_pressure_solver_h
#define qsmpm_porous_pore_pressure_solver_h

#include <Epetra_Import.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <map>
#include <memory>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/surface_tractions.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <qsmpm/porous/poroelastic_model.h>
#include <vector>

namespace qsmpm
{
  /**
   * The pore pressure of a saturated porous body (Biot consolidation) on
   * the background grid, coupled to the displacement by the fixed-stress
   * split (update()) or as one block of the monolithic problem
   * (CoupledStepOperator).
   *
   * <h3>Equations</h3>
   * Mass balance of the pore fluid, with Darcy's law q = -kappa grad p
   * (kappa = k / mu_f, the hydraulic conductivity over the unit weight of
   * the fluid), in the implicit Euler form of a load step of length dt
   * (the load factor is the time):
   *
   *   b d(eps_v) + (p - p_n) / M + dt div q = 0,
   *
   * b the Biot coefficient, M the Biot modulus (1/M = 0: incompressible
   * grains and fluid), d(eps_v) the volume change of the step over the
   * volume at its start. Its weak form is integrated with the material
   * points as quadrature points, with the grid's shape functions N_i (Q1,
   * or the GIMP weights of the points, as for the displacement) for the
   * pressure: row i,
   *
   *   sum_p Omega_p [ N_i (b d(eps_v) + (p - p_n) / M)
   *                  + dt kappa grad N_i . grad p
   *                  + beta_p grad N_i . (grad p - grad p_n) ] = 0,
   *
   * where the last term is the stabilization of the equal-order (Q1-Q1)
   * pair of Rodrigo, Gaspar, Hu and Zikatanov (2016), beta_p = f h^2 / M_c
   * with M_c the constrained modulus of the point's skeleton (lambda + 2 mu
   * for isotropic elasticity) and f the entry "Stabilization factor" (1/4
   * by default: on Terzaghi's column it removes the overshoot of 32 % after
   * a sudden load, test terzaghi_consolidation). The point
   * carries p_n and grad p_n (PoroelasticModel). The nodes on the "Drained
   * boundaries" of the grid have the prescribed pressure. The points on
   * the body's own "Drained surface region" (set_drained_surface()) add
   * the flux dt gamma A_p N_i(x_f) (p(x_f) - p_b) through their faces
   * (centre x_f, current area A_p, both moving with the point; x_f and
   * N_i(x_f) are those SurfaceTractions finds for a load there), gamma =
   * f kappa_p / h, a penalty. Nodes whose support holds no point have
   * p = 0, but no point couples them to the body: the body's other
   * surfaces, on the grid's boundary or inside the grid, are impermeable.
   * On a multi-field grid (Contact between bodies) the bodies share the
   * one pressure field: a point's volume change comes from its own body's
   * displacement field, and the fluid flows between bodies whose points
   * reach the same nodes.
   *
   * <h3>Finite strain</h3>
   * With `Kinematics = finite strain` the grid moves with the body within
   * a step, as for the displacement: the equation is integrated over the
   * configuration at the start of the step (the points' volumes Omega_p
   * and shape function gradients there), the volume change of the step is
   * d(eps_v) = det(I + grad du) - 1, exact for any step, and kappa_p =
   * kappa f(J_p) with J_p = det F at the start of the step ("Mobility
   * factor"). Taking the geometry and the mobility at the start of the step
   * is an error of first order in the step, like implicit Euler's. The
   * skeleton's Kirchhoff stress carries the pressure as tau' - J b p I
   * (PoroelasticModel). Verified against the large-strain consolidation
   * of a column (Gibson, England and Hussey 1967; test
   * large_strain_consolidation).
   *
   * <h3>Fixed-stress split</h3>
   * Within a load step the mechanical problem (with p as data) and the
   * flow problem are solved in turn (Kim, Tchelepi and Juanes 2011;
   * Mikelic and Wheeler 2013): the flow problem of iteration k + 1 takes
   * the volume change from the displacement of iteration k and adds
   * L_p (p^{k+1} - p^k) to the storage term, L_p = b^2 / K_p with K_p the
   * drained bulk modulus of the point's skeleton (its tangent, 2D: plane
   * strain). The iteration converges for any such L; the flow matrix is
   * the same for all iterations of a step and is assembled, with its AMG,
   * once per step.
   */
  template <int dim>
  class PorePressureSolver
  {
  public:
    /// The subsection "Pore fluid".
    struct Parameters : ParameterStruct<Parameters>
    {
      bool   enabled          = false;
      double biot_coefficient = 1.;
      double biot_modulus     = 0.;
      double mobility         = 1.;
      /// Mobilities of particular material ids (others: mobility).
      std::map<unsigned int, double> mobility_by_material_id;
      std::string                    mobility_factor  = "1";
      double                         initial_pressure = 0.;
      std::vector<unsigned int>      drained_boundaries;
      std::string                    boundary_pressure = "0";
      /// Expression in x, y (z) non-zero on the drained part of the body's
      /// initial surface (empty: none).
      std::string               drained_surface_region;
      double                    drained_surface_penalty = 100.;
      std::vector<unsigned int> flux_boundaries;
      std::string               boundary_flux           = "0";
      double                    stabilization_factor    = 0.25;
      double                    fixed_stress_factor     = 1.;
      double                    coupling_tolerance      = 1e-5;
      unsigned int              max_coupling_iterations = 100;
      /// "fixed-stress" or "monolithic" (CoupledStepOperator).
      std::string coupling = "fixed-stress";

      /// 1 / M, 0 for an incompressible fluid and grains (M = 0).
      double
      inverse_biot_modulus() const
      {
        return biot_modulus > 0. ? 1. / biot_modulus : 0.;
      }

      /// Whether the step solves both fields at once.
      bool
      monolithic() const
      {
        return coupling == "monolithic";
      }

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);

      /// Stop with a message naming the entry if a value is impossible.
      void
      check() const;
    };

    PorePressureSolver(const Parameters &parameters, const MPI_Comm comm);

    /**
     * Set up the flow problem of a load step of length @p dt on the points
     * of @p cache: constraints, the matrix and its AMG. The points' pressure
     * iterate starts from their committed pressure.
     */
    void
    begin_step(const BackgroundGrid<dim>   &grid,
               const ShapeCache<dim>       &cache,
               MaterialPointSet<dim>       &points,
               const PoroelasticModel<dim> &model,
               const double                 t_old,
               const double                 t_new);

    /**
     * One flow solve of the fixed-stress iteration with the displacement
     * increment @p du_ghosted (ghosted layout of the grid): writes the new
     * pressure iterate and its gradient into the points, and returns the
     * largest change of a nodal pressure over the larger of the largest
     * nodal pressure and the largest stress component of the points at the
     * start of the step (0 if all are 0).
     */
    double
    update(const ShapeCache<dim>               &cache,
           MaterialPointSet<dim>               &points,
           const TrilinosWrappers::MPI::Vector &du_ghosted);

    /**
     * @name The monolithic coupling (Pore fluid/Coupling = monolithic)
     *
     * The flow problem as one block of the coupled residual [R_u, R_p]
     * that NewtonKrylov solves for [du, p] at once (CoupledStepOperator),
     * and the pieces of its block-triangular preconditioner. Each needs
     * begin_step() of the step.
     */
    /// @{

    /**
     * Make @p p (owned layout, the constraints of the step satisfied) the
     * points' pressure iterate: its value and gradient at each point.
     */
    void
    set_pressure(const ShapeCache<dim>               &cache,
                 MaterialPointSet<dim>               &points,
                 const TrilinosWrappers::MPI::Vector &p);

    /**
     * The residual of the flow equation, @p R = A p - f(du) (the rows of
     * the constrained pressures zero), for the displacement increment
     * @p du_ghosted and the pressure @p p that set_pressure() last gave
     * the points. A is the step's matrix without the fixed-stress term
     * (which the iterate's L_p p(x_p) on the right-hand side cancels).
     */
    void
    flow_residual(const ShapeCache<dim>               &cache,
                  const TrilinosWrappers::MPI::Vector &du_ghosted,
                  const TrilinosWrappers::MPI::Vector &p,
                  TrilinosWrappers::MPI::Vector       &R) const;

    /**
     * The derivative of the flow residual with respect to the
     * displacement applied to @p du_ghosted, linearized at du = 0:
     * sum_p Omega_p b N_i tr(grad du).
     */
    void
    coupling_product(const ShapeCache<dim>               &cache,
                     const TrilinosWrappers::MPI::Vector &du_ghosted,
                     TrilinosWrappers::MPI::Vector       &dst) const;

    /**
     * One AMG cycle of the step's matrix, A plus the fixed-stress term
     * L_p N_i N_j: the fixed-stress approximation of the Schur complement
     * of the displacement block (White, Castelletto and Tchelepi 2016).
     * The constrained rows of @p dst are zero.
     */
    void
    precondition_schur(TrilinosWrappers::MPI::Vector       &dst,
                       const TrilinosWrappers::MPI::Vector &src) const;

    /**
     * The largest constrained modulus M_c of the points' skeletons over
     * the smallest cell size h. A pressure p balances the strain p / M_c,
     * a displacement of p h / M_c across a cell; a volume of fluid V is
     * the volume change of a force V M_c / h. The coupled system scales
     * its pressure unknowns and flow residuals by this number, so that
     * both blocks are displacements and forces of similar size.
     */
    double
    pressure_scale() const
    {
      return modulus_scale;
    }

    /// Zero the rows of the constrained pressures of @p v.
    void
    set_constrained_to_zero(TrilinosWrappers::MPI::Vector &v) const
    {
      constraints.set_zero(v);
    }

    /// The pressure dofs this rank owns (the step's).
    const IndexSet &
    locally_owned_dofs() const
    {
      return owned;
    }

    /// @}

    /// The nodal pressures of the last update() (owned layout).
    const TrilinosWrappers::MPI::Vector &
    owned_pressure() const
    {
      return p_owned;
    }

    /// The nodal pressures of the last update() or set_pressure() (ghosted).
    const TrilinosWrappers::MPI::Vector &
    pressure() const
    {
      return p_ghosted;
    }

    /**
     * Drain the surface of condition @p index of @p tractions (a condition
     * without load that marks the faces of "Drained surface region", added
     * to the problem's BoundaryDescriptor before the points are made): its
     * points and the Q1 values at their faces' centres, which @p tractions
     * finds in each step before begin_step(). @p tractions must outlive
     * this object.
     */
    void
    set_drained_surface(const unsigned int           index,
                        const SurfaceTractions<dim> &tractions)
    {
      drained_surface   = index;
      surface_tractions = &tractions;
    }

    /// The pressure's degrees of freedom.
    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /**
     * The size of the nodal forces in the body at the start of the step:
     * the largest stress component or pore pressure of the points times
     * the area of a cell face, at every degree of freedom of the grid,
     * h^(dim-1) sqrt(n_dofs) max |sigma| (0 before any load). The
     * displacement solves of the fixed-stress iteration stop relative to
     * it.
     */
    double
    force_scale() const
    {
      return forces;
    }

    /// CG iterations of the last update().
    unsigned int
    last_linear_iterations() const
    {
      return linear_iterations;
    }

  private:
    /**
     * The right-hand side of the flow problem for the displacement
     * increment @p du_ghosted and the points' pressure iterate into
     * @p vector (owned layout); with @p coupling_only just its volume
     * change term, with the sign of the residual and linearized at du = 0:
     * sum_p Omega_p b N_i tr(grad du).
     */
    void
    assemble_rhs(const ShapeCache<dim>               &cache,
                 const TrilinosWrappers::MPI::Vector &du_ghosted,
                 const bool                           coupling_only,
                 TrilinosWrappers::MPI::Vector       &vector) const;

    /// Interpolate the nodal pressures of p_ghosted to the points' iterate.
    void
    interpolate_to_points(const ShapeCache<dim> &cache,
                          MaterialPointSet<dim> &points);

    /// Find the pressure dofs of the nodes of each group of @p cache.
    void
    collect_group_dofs(const BackgroundGrid<dim> &grid,
                       const ShapeCache<dim>     &cache);

    /// The matrix of the flow problem on group @p c of the cache.
    void
    group_matrix(const ShapeCache<dim> &cache,
                 const unsigned int     c,
                 FullMatrix<double>    &matrix) const;

    /**
     * Add the penalty dt gamma A_p N_i(x_f) (p(x_f) - p_b) of the drained
     * surface's points to the matrix and boundary_rhs (not compressed).
     */
    void
    add_drained_surface(const ShapeCache<dim>       &cache,
                        const MaterialPointSet<dim> &points);

    /// Add -dt int N_i q.n over the faces of @p cell on the flux boundaries.
    void
    add_boundary_flux(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      FEFaceValues<dim>                                    &face_values,
      Vector<double>                                       &cell_rhs) const;

    const Parameters parameters;
    /// The pressure on the drained boundaries and the outward flux on the
    /// flux boundaries, functions of x and t.
    FunctionParser<dim> boundary_pressure, boundary_flux;
    /// The factor of the mobility, a function of J.
    FunctionParser<1> mobility_factor;
    /// Whether the points' kinematics is finite strain.
    bool finite_strain = false;
    /// Whether the kinematics is axisymmetric (r, z): the points' volumes
    /// are per radian, r dA, and the volume change has the hoop strain.
    bool axisymmetric = false;
    /// set_drained_surface() (invalid: none).
    unsigned int drained_surface = numbers::invalid_unsigned_int;
    const SurfaceTractions<dim> *surface_tractions = nullptr;
    /// The smallest cell size of the grid.
    double cell_size = 0.;
    /**
     * The pressure dof of each node, indexed by its first displacement
     * dof's position in the grid's locally relevant dofs (the step's).
     */
    std::vector<types::global_dof_index> pressure_at;
    /// The grid's locally relevant (displacement) dofs of the step.
    IndexSet relevant_displacement;
    /// The length of the step (the load factor is the time).
    double                            dt = 0.;
    MPI_Comm                          communicator;
    FE_Q<dim>                         fe;
    DoFHandler<dim>                   dof_handler;
    IndexSet                          owned, relevant;
    AffineConstraints<double>         constraints;
    TrilinosWrappers::SparseMatrix    matrix;
    TrilinosWrappers::PreconditionAMG amg;
    TrilinosWrappers::MPI::Vector     p_owned, p_ghosted, rhs;
    /// The exchange of the owned pressures into p_ghosted (set_pressure()).
    std::unique_ptr<Epetra_Import> ghost_import;
    /// The part of the right-hand side that is the same for all iterations
    /// of a step: the fluxes and the prescribed pressures.
    TrilinosWrappers::MPI::Vector boundary_rhs;
    /// The pressure dofs of the nodes of the cache's groups (the cell's
    /// 2^dim vertices with linear shape functions, the nodes its points
    /// reach with GIMP): those of group c are [group_offsets[c],
    /// group_offsets[c + 1]).
    std::vector<types::global_dof_index> group_dofs;
    std::vector<unsigned int>            group_offsets;
    /// The position of each entry of group_dofs in the relevant set, which
    /// is also its position in p_ghosted's local array.
    std::vector<unsigned int> group_relevant_entry;
    /// Per relevant dof: its position in an owned vector's local array
    /// (-1: owned by another rank).
    std::vector<int> relevant_owned_entry;
    /// The relevant dofs owned by other ranks: their positions in the
    /// relevant set and their global indices.
    std::vector<unsigned int>            ghost_entries;
    std::vector<types::global_dof_index> ghost_dofs;
    /// Scratch of assemble_rhs(): the sums per relevant dof, and those of
    /// the ghost dofs.
    mutable std::vector<double> relevant_sums, ghost_sums;
    /// The part of the flow's right-hand side that does not change within
    /// a step (the committed pressure's storage and the stabilization
    /// with the committed pressure gradient), per relevant dof: found once
    /// in begin_step(), the start of assemble_rhs()'s sums.
    std::vector<double> step_sums;
    /// Per point of the cache: Omega_p, kappa_p, L_p and beta_p of the step.
    std::vector<double> volume, mobility, fixed_stress, stabilization;
    unsigned int        state_offset = 0;
    /// Offset of the points' initial total stress in their properties.
    unsigned int initial_stress_offset = 0;
    double       b                     = 1.;
    unsigned int linear_iterations     = 0;
    /// The largest stress component of the points at the start of the step.
    double stress_scale = 0.;
    /// force_scale().
    double forces = 0.;
    /// pressure_scale().
    double modulus_scale = 0.;
  };
} // namespace qsmpm

#endif
