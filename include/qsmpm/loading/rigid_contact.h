#ifndef qsmpm_loading_rigid_contact_h
#define qsmpm_loading_rigid_contact_h

#include <array>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/loading/preconditioner_correction.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * Contact of the material points with the rigid bodies of a
   * BoundaryDescriptor (add_rigid_body()), enforced by a penalty on the
   * points' surfaces.
   *
   * <h3>Where a point touches</h3>
   * A point stands for a box of material (half-lengths l_d: the initial
   * GIMP domain, or (Omega_p^0)^(1/dim) / 2 in every direction with linear
   * shape functions), deformed with the point: its edges are F l_d e_d (at
   * small strain F = I + eps). Towards a body with outward normal n it
   * touches at
   *
   *   x_c = x_p + a,   a = -sum_d (n . F e_d / |F e_d|) l_d F e_d,
   *
   * the centre of its face when n is along an edge (a box facing a plate
   * touches with its face, r = -n . a = l), and the support point of the
   * inscribed ellipse in between (a vertex would put the force on one side
   * of the point and bend the surface layer). In a step with increment du
   * the contact point moves by the grid's interpolation at x_c,
   *
   *   u_c(du) = sum_i N_i(x_c) du_i,
   *
   * with the Q1 functions of the cell that holds x_c: with linear shape
   * functions the point's own cell (extrapolated if x_c lies beyond it),
   * whose nodes are the point's stencil; with GIMP the cell among the
   * point's cell and those that touch it that contains x_c, if the points
   * of the point's cell reach all of its nodes (which are then in the
   * point's group and so in the stiffness's pattern); otherwise the
   * point's cell, extrapolated: at the grid's edge, and for a point whose
   * box is sheared far beyond its GIMP domain (an axis-parallel box at
   * most a cell wide), as beside a cone's face (test
   * contact_sheared_point). A GIMP point near the surface
   * whose centre has crossed into the next cell still has its contact
   * point in the cell it came from, and that cell's field is the one
   * that moves its surface: extrapolated from the new cell instead, the
   * contact point drifted from the surface the next step finds, and a
   * rigid footing pushed into the soil lost half of its contact points,
   * and 70 % of its force, when their row crossed a grid line.
   *
   * A point that was near a body in the last step (a candidate, within 2 h
   * of it) keeps the contact point the grid moved: the next step starts
   * at x_c + u_c(du), not at the support point of the box deformed with
   * the point's F (MaterialPointSet::Offsets::contact_point), as long as
   * the body's outward normal h / 100 behind it (far more than a contact
   * point's penetration under the penalty) has not turned by more than 60
   * degrees from the last step's; that normal, not the centre's, is then
   * the one the box's area is taken along, and on a flat face of a box or
   * a polygon the point meets the face with the share of its own face
   * that lies over it (as points that do not move, below), until none
   * does. At large strain the box's support point is not where the grid
   * carries the point's surface: under a rigid footing pushed in by a
   * quarter of its width the boxes recomputed at the start of a step
   * implied up to five times the footing's force (the flattened, sheared
   * points at its edge), and the pressure fell by 12-18 % in single
   * steps. Followed, the contact force at the start of a step is within
   * 1 % of the last step's; with the contact point's normal a flattened
   * point whose centre lies inside the base's new position is not measured
   * against the side, and with the share a point whose face slides over
   * the base's edge leaves it gradually. Where the point's face reaches
   * past the end of the body's face at a vertex at which the surface turns
   * by more than 60 degrees (a footing's edge; not on the axis of an
   * axisymmetric problem), the point is measured at the middle of that
   * share, and a second candidate of the same point presses the rest of
   * its face against the vertex (in 3D the edge; at a corner of the base,
   * where the face reaches past edges along both of its directions, the
   * rest is not pressed); measured at its face's middle, a
   * point half under the base was let go at once with 12 % of a footing's
   * force. The largest fall of the footing's pressure in one step is 0.6 %
   * (doc/example_footing.md). The normal behind the contact point lets a
   * point of the soil heaving beside the footing, whose contact point the
   * grid carried into the footing above its base, meet the side.
   *
   * The same N_i(x_c) carry the contact force to the nodes,
   * as a traction on the body's surface: with cpGIMP domains, which tile
   * the body, a uniform stress is then in equilibrium with a uniform
   * contact pressure (test contact_rigid_bodies: a plate compacting a
   * column, every point's stress within 0.27 % of the exact at small
   * strain, 0.13 % at 5 % compaction at finite strain). With linear shape
   * functions the points of the cell under the plate stand for material
   * that partly lies in the cell below, and that cell's stress is off by
   * about u / h (5 % at u = h / 12 in the same test).
   *
   * <h3>Points that do not move, against a frictionless body</h3>
   * With Formulation::move_points false the points keep their places on
   * the grid and the strain is small. Against a frictionless body the
   * contact is then that of small displacements: the contact point and
   * the normal are those of the point's place on the grid (the body at
   * its position of the step's end), and the point's displacement, u_p of
   * the steps before plus u_c(du), enters the gap by its component along
   * that normal only: g = g(x_c^place) + n . (u_p + u_c). Measured where
   * the displacement puts the point, the soil flowing out from under a
   * smooth rigid footing (u_x = 0.9 s at its edge) slid the points at the
   * edge over the footing's corner one after the other, and the footing's
   * plateau fell by 4.2 % after a settlement of a third of a cell (a/h =
   * 8; 2.2 % at a/h = 16; test contact_footing_small_displacement).
   *
   * Such a point meets a box or a polygon at one of its flat faces
   * (RigidBody::faces()) with its own face of half-widths w_k (the
   * projection of its box on the face's tangents t_k): n is the face's
   * normal, the gap the contact point's distance from the face's plane,
   * and only the share of the point's face that lies over the face is
   * pressed,
   *
   *   share = prod_k |I_k meet [lower_k, upper_k]| / (2 w_k),
   *   I_k = [x_c . t_k - w_k, x_c . t_k + w_k].
   *
   * The face is chosen at the start of each step: the one that pressed
   * the point in the step before (its stored traction, which without
   * friction lies along the normal) while the point's face still overlaps
   * it, otherwise the face nearest to the point's place (a point nearest
   * to an edge or a vertex touches that, with the signed distance). At
   * its place a point under a sinking footing lies below the base by the
   * settlement, and near the base's edge it comes nearer to the side
   * face: chosen anew each step by the signed distance, it went over to
   * the side face and was pushed sideways, and the plateau fell by 4.9 %
   * after s = 0.3 h (a/h = 8). With friction (whose tangential traction
   * does not tell the face) and with points that move, a point first meets
   * a body at the surface point nearest to its centre where its
   * displacement puts it (the signed distance, below), then where its
   * contact point goes (above); the rough footing's base holds the soil
   * under it, which does not slide over its edge.
   *
   * <h3>The traction</h3>
   * With the gap g (the body's signed distance at the load factor of the
   * step's end, RigidBody::signed_distance(), but for the faces above)
   * and the contact stiffness per area
   *
   *   epsilon = gamma kbar / h^(dim-1)
   *
   * (RigidBody::penalty_factor gamma, kbar the mean stiffness of the
   * step's degrees of freedom, h the smallest cell size), a point with
   * g < 0 gets the contact pressure p_N = -epsilon share g along n (share
   * = 1 but on a face, above), and with
   * friction the tangential traction of a return map: trial
   * tau = P (t_old - share epsilon_T s), s the slip of the contact point
   * relative to the body in the step, epsilon_T = epsilon / 10 (with the
   * full epsilon a point goes from stick to slip within a thousandth of a
   * step's motion and Newton cycles), P = I - n (x) n, t_old the point's
   * contact traction
   * of the last step (stored on the point, contact_<name>); Coulomb
   * friction limits |tau| to mu p_N (slip), below it the point sticks;
   * rough contact never slips. A tied body (RigidBody::Friction::tied)
   * holds the candidates whose contact point is within r of its surface or
   * inside it, in every direction and whatever the sign of g: traction
   * t = t_old - epsilon (u_c - u_b), u_b the body's motion in the step
   * (a penalty displacement condition; the preconditioner gets epsilon A
   * N_i N_j I). The force on the material,
   * f = A (p_N n + tau) with the point's area A = Omega_p / (2 r)
   * (contact_area(): bounded by twice the box's projection), goes to
   * the nodes with the weights N_i(x_c); minus its sum over the points is
   * the force on the body. Everything depends on the increment, so it is part
   * of the step's residual and Newton sees the exact (piecewise smooth)
   * Jacobian through its finite differences; the preconditioner gets
   * epsilon A N_i N_j (n (x) n, plus epsilon_T / epsilon P for points that
   * stick: rough contact, and Coulomb contact unless the point's traction
   * of the last step was at the Coulomb limit) of the points that touch or
   * penetrate the body at du = 0. Coulomb friction turns Newton's
   * line search on (QuasiStaticProblem::advance()).
   *
   * The candidates of a step are the points within two cell sizes of a
   * body at the step's end (with du = 0): a point that moves further
   * towards a body in one step than that is missed.
   *
   * <h3>A body driven by a force</h3>
   * A body with a load direction d (RigidBody::load_driven()) moves along
   * d by an unknown amount s in each step, beyond its converged position
   * of the last step: for every increment du, s is the root of
   *
   *   f(s) = sum_c A_c t_c(du, s) . d - F(t_new),
   *
   * the contact force of the material along d balancing the body's load F
   * (Newton's method on s in a bracket, one sum over the ranks per
   * iteration; f is monotone in s, piecewise linear for flat faces, so
   * Newton ends on the exact root in a few iterations once the points in
   * contact stay the same). The body's motion is thus condensed out of the
   * step's unknowns: the residual stays a function of du alone, and
   * Jacobian-free Newton sees ds/du through its finite differences. Where
   * no s balances F (the body finds no material to push against within
   * two cells), check_loads() stops the run with a message naming the
   * body.
   *
   * <h3>The preconditioner of a body driven by a force</h3>
   * The preconditioner's matrix K_A holds the contact stiffness K_c of
   * each body as if the body were held (add_to()). A body driven by a
   * force is free: with b = K_c e_d (e_d: the direction d at every node)
   * and beta = e_d^T K_c e_d, ds/du = b^T / beta, and the Jacobian of the
   * condensed residual is -(K_A - sum_k b_k b_k^T / beta_k), a rank-one
   * change per body. precondition() applies its inverse by the
   * Sherman-Morrison-Woodbury formula,
   *
   *   (K_A - B Beta^{-1} B^T)^{-1} = K_A^{-1} + m G^{-1} m^T,
   *   m = K_A^{-1} B,  G = Beta - B^T m,
   *
   * with K_A^{-1} the preconditioner and m solved for to 1e-10 by GMRES
   * (preconditioned by it) whenever the preconditioner is built
   * (setup_preconditioner()); b and beta are those of the contact
   * stiffness add_to() gave K_A. Without it AMG sees the body held by the
   * penalty springs, and GMRES has to find the body's motion itself.
   */
  template <int dim>
  class RigidContact
    : public PreconditionerCorrection<TrilinosWrappers::MPI::Vector>
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /// The rigid bodies of @p boundary, which must outlive this object.
    explicit RigidContact(const BoundaryDescriptor<dim> &boundary);

    /// Whether there are rigid bodies at all.
    bool
    empty() const;

    /**
     * The data of the step t_old -> t_new: the candidate points of
     * @p cache, their contact points and weights, and the contact stiffness
     * from
     * @p stiffness_scale (kbar). @p ghosted_layout is a vector with the
     * layout the cache's local dof indices refer to. @p load_displacements
     * holds, per body, the motion along its load direction at t_old of
     * the bodies driven by a force (empty: none has moved). Collective.
     */
    void
    reinit_step(const BackgroundGrid<dim>   &grid,
                const ShapeCache<dim>       &cache,
                const MaterialPointSet<dim> &points,
                const VectorType            &ghosted_layout,
                const double                 t_old,
                const double                 t_new,
                const double                 stiffness_scale,
                const std::vector<double>   &load_displacements = {});

    /// R += the contact forces on the material at the increment @p du
    /// (owned entries); @p R compressed.
    void
    add_contact_forces(const VectorType &du, VectorType &R) const;

    /// The largest motion of a body in the step, |u_b(t_new) - u_b(t_old)|,
    /// times the square root of the number of entries of @p layout's
    /// vector space: the size of a displacement of that motion at every
    /// degree of freedom.
    double
    motion_scale(const VectorType &layout) const;

    /// The force of the material on one body at an increment.
    struct BodyLoad
    {
      Tensor<1, dim> force;
      /// Points in contact, and the deepest penetration -g (0 if none).
      unsigned int n_points    = 0;
      double       penetration = 0.;
    };

    /// The load on each body at the increment @p du (all ranks).
    /// Collective.
    std::vector<BodyLoad>
    body_loads(const VectorType &du) const;

    /**
     * Why the converged increment @p du leaves a contact the step did not
     * resolve, or an empty string. A penalty step sees only its candidates
     * (the points within two cells of a body at its start) and, for each,
     * the side of the body its contact point starts on. Three things it
     * cannot see are reported, for the first body (in the order of the
     * bodies) where they happen, so that the step is cut back like one
     * that did not converge:
     * - a candidate's contact point went through the body: its path
     *   entered the body deeper than half the point's box radius |F l| and
     *   the normal at its end points against the one at its start (a thin
     *   body crossed, or a point pushed out on the far side);
     * - a point in contact lies deeper in the body than its box's radius
     *   |F l| (all of its box inside: an unresolved contact, or a penalty
     *   factor too small for the pressure);
     * - a point that was not a candidate and started clear of the body
     *   reached it (its centre's path came within its box's radius of
     *   it). Collective.
     */
    std::string
    unresolved_contact(const VectorType &du) const;

    /// Throw with a message naming the first body driven by a force whose
    /// load the material does not balance, @p loads being body_loads() of
    /// the step's solution (to 1e-6 of the load or of @p force_scale).
    void
    check_loads(const std::vector<BodyLoad> &loads,
                const double                 force_scale) const;

    /// K += the contact stiffness of the points that touch or penetrate a
    /// body at du = 0 (the couplings of their cells' nodes are in K's
    /// pattern already).
    /// If @p preconditioner_matrix, K is the matrix of the step's
    /// preconditioner, and b and beta of the bodies driven by a force are
    /// kept for setup_preconditioner() (collective then).
    void
    add_to(const AffineConstraints<double> &constraints,
           TrilinosWrappers::SparseMatrix  &K,
           const bool                       preconditioner_matrix = true) const;

    /**
     * m = K_A^{-1} B and G^{-1} of the bodies driven by a force (see the
     * class description), from @p K_A, the matrix add_to() added to, and
     * its preconditioner @p M, if @p new_preconditioner; otherwise those
     * of the last call serve. Collective.
     */
    void
    setup_preconditioner(const TrilinosWrappers::SparseMatrix &K_A,
                         const Preconditioning                &M,
                         const bool new_preconditioner);

    /// Whether precondition() has a correction to apply.
    bool
    has_preconditioner() const override;

    /// dst = M(src) with the bodies' rank-one corrections (the class
    /// description). Collective.
    void
    precondition(const Preconditioning &M,
                 VectorType            &dst,
                 const VectorType      &src) const override;

    /// Store each candidate's contact traction at the converged increment
    /// @p du_ghosted (the layout of reinit_step()) on its point, and
    /// return, per body, its motion along its load direction so far (the
    /// bodies driven by a force; 0 for the others). Collective.
    std::vector<double>
    commit(MaterialPointSet<dim> &points, const VectorType &du_ghosted) const;

    /**
     * The contact area of a point of volume @p volume whose box has the
     * half-edges F e_d l_d (@p F, l_d = @p half[d]) and the extent @p r
     * along the body's outward normal @p n (r = -n . a, the class
     * description): Omega_p / (2 r), bounded by twice the area of the
     * box's projection on the plane normal to n (2D: a length), times
     * @p radius (the point's radius in axisymmetric problems, where
     * Omega_p is per radian; 1 otherwise). The bound is a safeguard, not
     * a model: Omega_p / (2 r) of a box of ordinary shape stays well
     * below it, and grows without bound for a box drawn out along the
     * surface (a needle within a small angle of it: r, quadratic in that
     * angle, goes to zero while the projection stays its length). The
     * cone of examples/contact at 3.7 R had a point stretched 23 times
     * along the cone's face with Omega_p / (2 r) = 4671 against a
     * projection of about 2.4 per radian; its penalty force made the
     * step's first residual 80 times that of the steps beside it.
     */
    static double
    contact_area(const Tensor<2, dim> &F,
                 const Tensor<1, dim> &half,
                 const Tensor<1, dim> &n,
                 double                r,
                 double                volume,
                 double                radius);

  private:
    /// One candidate: a point of the cache near one body.
    struct Candidate
    {
      unsigned int point;
      unsigned int body;
      /// The first of the dofs of the cell that holds its contact point in
      /// dof_global etc.
      unsigned int first;
      /// The contact point x_p + a at the start of the step, relative to
      /// the body's reference point moved to the step's end
      /// (RigidBody::signed_distance_from_point()).
      Tensor<1, dim> relative;
      /// The point's contact area A.
      double area;
      /// The radius |F l| of the point's box at the step's start.
      double reach;
      /// Whether the corner touches or is inside the body at du = 0 (every
      /// candidate of a tied body).
      bool penetrates;
      /// The body's outward normal at the contact point's place at du = 0
      /// for a point of small displacements (the class description), whose
      /// contact point then moves along it only; zero otherwise.
      Tensor<1, dim> normal;
      /// Whether the point meets a flat face of a box or a polygon (points
      /// of small displacements), which @p face then
      /// describes, and the half-widths of the point's box along the
      /// face's tangents.
      bool                          flat = false;
      typename RigidBody<dim>::Face face;
      std::array<double, dim - 1>   half_width;
    };

    /// Where candidate @p c's contact point is, relative to the body as
    /// Candidate::relative, when it has moved by @p motion in the step
    /// (contact_motion()): for a point of small displacements by the part
    /// of @p motion along Candidate::normal (the class description).
    Tensor<1, dim>
    contact_position(const Candidate &c, const Tensor<1, dim> &motion) const;

    /**
     * The gap of candidate @p c's contact point at @p y (relative to the
     * body, as Candidate::relative), the body's outward normal @p n there,
     * and in @p share the part of the point's contact face that lies over
     * the body's surface. On a flat face (Candidate::flat) the gap is the
     * distance from the face's plane and @p share the overlap of the
     * point's face (centred at y, Candidate::half_width along each
     * tangent) with the face's extent; elsewhere the body's signed
     * distance and 1 (the class description).
     */
    double
    contact_gap(const Candidate      &c,
                const Tensor<1, dim> &y,
                Tensor<1, dim>       &n,
                double               &share) const;

    /// The displacement of candidate @p c's contact point in the step at
    /// the increment whose local entries @p du_local holds (ghosted
    /// layout), sum_i N_i(x_c) du_i, less the body's motion by a force in
    /// the step: Candidate::relative plus it is the contact point at the
    /// step's end relative to the body.
    Tensor<1, dim>
    contact_motion(const Candidate &c, const double *du_local) const;

    /// Where point @p p of the material is at the step's start: its place
    /// on the grid, plus its displacement u_p if the points do not move
    /// (Formulation::move_points).
    Point<dim>
    material_position(const unsigned int p) const;

    /// The box of point @p p of the cache at the step's start: its
    /// half-lengths @p half and its deformation @p F (the class
    /// description).
    void
    point_box(const unsigned int p,
              Tensor<1, dim>    &half,
              Tensor<2, dim>    &F) const;

    /**
     * The contact traction on candidate @p c (per unit of its area A) at
     * the increment whose local entries @p du_local holds (ghosted
     * layout), with the body's normal @p n there, the gap @p gap and the
     * share of the point's face over the body's surface @p share
     * (contact_gap()); @p active: whether the point is in contact (g < 0
     * with a share > 0, or tied).
     */
    Tensor<1, dim>
    traction(const Candidate &c,
             const double    *du_local,
             Tensor<1, dim>  &n,
             double          &gap,
             double          &share,
             bool            &active) const;

    /// The motion s along its load direction of each body driven by a
    /// force that balances its load at the increment whose local entries
    /// @p du_local holds (shift). Collective.
    void
    solve_shifts(const double *du_local) const;

    /// Call @p action(candidate, traction, gap) for every candidate in
    /// contact at the increment @p du (owned entries).
    template <typename Action>
    void
    for_each_contact(const VectorType &du, const Action &action) const;

    /// Whether candidate @p c slipped in the last step: its stored
    /// traction at the Coulomb limit (@p n: the body's normal).
    bool
    slipped(const Candidate &c, const Tensor<1, dim> &n) const;

    const BoundaryDescriptor<dim> &boundary;

    /// The step's data.
    const ShapeCache<dim> *cache          = nullptr;
    unsigned int           contact_offset = 0;
    /// The points' fields and kinematics point_box() reads.
    typename MaterialPointSet<dim>::Offsets offsets;
    bool                                    gimp         = false;
    bool                                    finite       = false;
    bool                                    axisymmetric = false;
    bool                                    move_points  = true;
    std::vector<double>                     penalty;
    /// Each body's displacement at the step's end, and in the step.
    std::vector<Tensor<1, dim>> body_displacement;
    std::vector<Tensor<1, dim>> body_increment;
    /// Per body driven by a force: its load direction (unit; zero for the
    /// others), its load at the step's end, its motion along the
    /// direction at the step's start, and the motion s in the step that
    /// the last solve_shifts() found (the next one starts from it).
    std::vector<Tensor<1, dim>> load_unit;
    std::vector<double>         load_force;
    std::vector<double>         load_start;
    mutable std::vector<double> shift;
    double                      cell_size = 0.;
    std::vector<Candidate>      candidates;
    /// The dofs of a candidate: those of one body's field in a cell.
    unsigned int dofs_per_cell = 0;
    /// Per candidate, the dofs of its point's body's field in the cell
    /// that holds its contact point: global index, index in the ghosted
    /// layout's storage, component (the direction), N_i(x_c).
    std::vector<types::global_dof_index> dof_global;
    std::vector<int>                     dof_local;
    std::vector<unsigned int>            dof_component;
    std::vector<double>                  dof_values;
    bool                                 any = false;
    mutable VectorType                   du_ghosted;
    mutable VectorType                   forces;
    /// Scratch of add_contact_forces(): one cell's nodal forces.
    mutable std::vector<double> values;

    /// Per body driven by a force, b = K_c e_d (the nodal forces of a
    /// unit shift of the body) and beta = e_d^T K_c e_d of the contact
    /// stiffness add_to() gave the preconditioner's matrix (both summed
    /// over the ranks).
    mutable std::vector<VectorType> unit_shift_forces;
    mutable std::vector<double>     unit_shift_stiffness;
    /// The bodies the correction covers, m = K_A^{-1} b of each, and G^{-1}.
    std::vector<unsigned int> corrected_bodies;
    std::vector<VectorType>   corrections;
    FullMatrix<double>        correction_inverse;
    mutable Vector<double>    correction_rhs, correction_solution;
  };
} // namespace qsmpm

#endif
