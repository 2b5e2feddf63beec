#ifndef qsmpm_particles_material_point_set_h
#define qsmpm_particles_material_point_set_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/particles/particle_handler.h>
#include <functional>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/particles/formulation.h>
#include <qsmpm/particles/property_layout.h>

namespace qsmpm
{
  template <int dim>
  class ShapeCache;

  /**
   * The material points: a Particles::ParticleHandler on the background grid
   * whose particles carry all the state of the body (paper Section 2.2):
   * initial and current volume Omega_p, J_p, displacement u_p, strain
   * epsilon_p, stress sigma_p, a material id and the constitutive model's own
   * fields. The grid carries nothing between load steps.
   *
   * The class also provides the generators that fill a region with points.
   */
  template <int dim>
  class MaterialPointSet
  {
  public:
    /// Where points are put inside a cell.
    enum class Placement
    {
      /// n^dim points at the centres of a uniform n x n (x n) subdivision.
      regular,
      /// the n^dim Gauss points, with Gauss weights times cell volume.
      gauss
    };

    /**
     * The subsection "Material points" of a .prm file.
     */
    struct Parameters : ParameterStruct<Parameters>
    {
      unsigned int points_per_direction = 2;
      Placement    placement            = Placement::regular;
      /// The corners "x,y" ("x,y,z") of the box to fill, both or neither;
      /// empty: the whole grid.
      std::string region_lower_corner;
      std::string region_upper_corner;
      /// Omega_p follows J_p (2.23-2.24); false keeps Omega_p^0.
      bool update_volumes = true;
      /// Small or finite strain; linear or GIMP shape functions.
      Formulation formulation;
      /// Nodes holding less material than this fraction of a cell's volume
      /// are held fixed in a step like nodes without points.
      double min_nodal_volume_fraction = 0.;
      /// Degrees of freedom whose stiffness (diagonal of the tangent) is at
      /// most this fraction of the mean are held fixed in a step; pairs of
      /// dofs with a motion that stiff, by NullModeHold.
      double min_nodal_stiffness_fraction = 1e-8;
      /// The factor gamma of the ghost penalty of cut cells (GhostPenalty);
      /// 0: none.
      double ghost_penalty = 0.;
      /// The material id of a point created at x, an expression in x, y
      /// (and z) whose value is a non-negative integer.
      std::string material_id = "0";
      /// Where points are created (with the region box): an expression in
      /// x, y (and z), points where its value is positive; empty: all.
      std::string region_expression;
      /// The stress of a point created at x (its components xx; yy; zz;
      /// xy in 2D, xx; yy; zz; xy; xz; yz in 3D, expressions in x, y (and
      /// z)); empty: the model's own (ConstitutiveModel::initial_stress()).
      std::string initial_stress;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);

      /// Whether only a box is filled (a region corner is given).
      bool
      restrict_to_box() const;

      /// The region box (lower, upper corner); throws if only one corner
      /// is given or one is not a point.
      std::pair<Point<dim>, Point<dim>>
      region() const;

      /// The region and the agreement of volume update and kinematics.
      void
      check() const;
    };

    /// Offsets of the fields every point carries.
    struct Offsets
    {
      unsigned int initial_volume;
      unsigned int volume;
      unsigned int J;
      unsigned int displacement;
      unsigned int strain;
      unsigned int stress;
      unsigned int material_id;
      /// Finite strain only: F, dim x dim, row by row (else invalid).
      unsigned int deformation_gradient = numbers::invalid_unsigned_int;
      /// Axisymmetric only: the hoop strain (small strain: the sum of the
      /// steps' d u_r / r; finite strain: ln(r / R)) and the Cauchy hoop
      /// stress sigma_thetatheta (else invalid).
      unsigned int hoop_strain = numbers::invalid_unsigned_int;
      unsigned int hoop_stress = numbers::invalid_unsigned_int;
      /// GIMP only: the half-lengths l_d^0 of the point's initial domain.
      unsigned int initial_half_length = numbers::invalid_unsigned_int;
      /// With surface tractions only: per condition, the point's share A_0
      /// of the loaded initial area, its current area vector n da and the
      /// area-weighted sum of its faces' offsets from the point (2 dim + 1
      /// doubles each; SurfaceTractions).
      unsigned int surface_load = numbers::invalid_unsigned_int;
      /// With rigid bodies only: per body, the contact traction on the
      /// point's surface (dim doubles each; RigidContact).
      unsigned int contact = numbers::invalid_unsigned_int;
      /// With rigid bodies only: per body, where the grid moved the point's
      /// contact point in the last step, and the body's outward normal
      /// there (2 dim doubles each, the normal zero where the point was not
      /// near the body): the next step's contact point (RigidContact).
      unsigned int contact_point = numbers::invalid_unsigned_int;
      /// With rigid bodies and F-bar only: the point's own volumetric
      /// strain minus the one F-bar gives it (its cell's mean), summed over
      /// the steps (small strain: traces of the increments; finite strain:
      /// logarithms of their determinants). The point's box, with which
      /// it touches a body, follows the grid's motion with it
      /// (RigidContact).
      unsigned int fbar_volume_excess = numbers::invalid_unsigned_int;
      /// First of the constitutive model's own fields.
      unsigned int state;
    };

    /**
     * Points for @p model on @p grid. The @p formulation decides which
     * fields the points carry besides the common ones: F at finite strain,
     * the initial domain half-lengths with GIMP; @p n_surface_loads the
     * number of surface tractions whose area each point carries;
     * @p contact_bodies the names of the rigid bodies whose contact
     * traction each point carries (the fields contact_<name>).
     */
    MaterialPointSet(const BackgroundGrid<dim>      &grid,
                     const ConstitutiveModel<dim>   &model,
                     const Formulation              &formulation     = {},
                     const unsigned int              n_surface_loads = 0,
                     const std::vector<std::string> &contact_bodies  = {});

    /**
     * Fill every locally owned cell with points at the positions given by
     * @p placement, keeping those at which @p inside is true. Volumes are the
     * cell volume divided equally (regular) or weighted by the Gauss weights
     * (gauss). With GIMP, a point's initial domain is the box of
     * half-lengths l_d = h_d / (2n) around it. Point ids are globally unique
     * and independent of the number of MPI ranks only up to ordering.
     */
    void
    fill(const std::function<bool(const Point<dim> &)> &inside,
         const unsigned int                             points_per_direction,
         const Placement                                placement,
         const unsigned int                             material_id = 0);

    /**
     * As above, with the points of every cell at the points of @p rule on
     * the reference cell [0,1]^dim and volumes equal to its weights (which
     * must sum to one) times the cell volume (GIMP domains: half-lengths
     * h_d w^(1/dim) / 2 for weight w). Use reference_rule() for
     * rules with a different number of points per direction, e.g. a cell
     * with 1 x N points.
     */
    void
    fill(const std::function<bool(const Point<dim> &)> &inside,
         const Quadrature<dim>                         &rule,
         const unsigned int                             material_id = 0);

    /**
     * As above, with the material id of each point given by @p material_id
     * at the point's position: layers, inclusions, a footing on soil. The
     * model's initialize_point_state() sees the id (and the point's id).
     */
    void
    fill(const std::function<bool(const Point<dim> &)>         &inside,
         const Quadrature<dim>                                 &rule,
         const std::function<unsigned int(const Point<dim> &)> &material_id);

    /**
     * As above, with the stress of each point given by @p initial_stress
     * at its position (3D, Cauchy; in 2D the zz component is the
     * out-of-plane stress): the model makes the point's state carry it
     * (ConstitutiveModel::initial_stress(), which stops with a message if
     * the model cannot). An empty function: the model's own initial stress.
     */
    void
    fill(const std::function<bool(const Point<dim> &)>         &inside,
         const Quadrature<dim>                                 &rule,
         const std::function<unsigned int(const Point<dim> &)> &material_id,
         const std::function<SymmetricTensor<2, 3>(const Point<dim> &)>
           &initial_stress);

    /**
     * The reference positions and volume fractions of @p placement with
     * @p n[d] points in direction d: the centres of a uniform
     * n[0] x n[1] (x n[2]) subdivision with equal weights (regular), or the
     * tensor product of n[d]-point Gauss rules (gauss).
     */
    static Quadrature<dim>
    reference_rule(const Placement                      placement,
                   const std::array<unsigned int, dim> &n);

    /// Fill as described by the parameters.
    void
    fill(const Parameters &parameters);

    /**
     * Move the points with the converged grid increment (paper eqs.
     * 2.26-2.27): x_p += sum_i du_i N_i(x_p), u_p += the same. @p du_ghosted
     * must hold the locally relevant entries. Call locate_in_cells() next,
     * and sort_into_cells() if it returns false. Returns the largest
     * distance a point moved (over all ranks). Points that do not move
     * (Formulation::move_points = false) only accumulate u_p, and 0 is
     * returned.
     */
    double
    advect(const ShapeCache<dim>               &cache,
           const TrilinosWrappers::MPI::Vector &du_ghosted);

    /**
     * After the points' locations were changed: if every point (on every
     * rank) is still inside the cell it was in, update the points'
     * reference locations and return true. Otherwise return false, and
     * call sort_into_cells(). This is the first half of deal.II's sort,
     * with the same test (GeometryInfo::is_inside_unit_cell), but without
     * deal.II's reordering of all particle data in memory, which is the
     * larger half and needless when no point changes cells. On affine
     * cells (the Cartesian grids of MPM) the reference location is that of
     * the inverse affine map; on others that of the grid's mapping.
     * Collective: one reduction.
     */
    bool
    locate_in_cells();

    /**
     * After the points' locations were changed: sort them into cells and
     * onto the MPI ranks that own those cells. Points that left the grid are
     * lost; the number of lost points (over all ranks) is returned.
     */
    types::particle_index
    sort_into_cells();

    /**
     * sort_into_cells() after a step in which a point moved at most
     * @p moved (advect()); throws with a message if points were lost: in a
     * parallel run, deal.II finds a point's new cell only among the
     * neighbours of its old one (the ghost layer), so a point that moved
     * more than a cell is lost there; otherwise points that left the grid
     * are.
     */
    void
    sort_into_cells_without_loss(const double moved);

    Particles::ParticleHandler<dim> &
    get_particle_handler();
    const Particles::ParticleHandler<dim> &
    get_particle_handler() const;

    const PropertyLayout &
    get_layout() const;
    const Offsets &
    get_offsets() const;

    /// Where a PointStateBatch of these points finds the fields of a point.
    typename PointStateBatch<dim>::Layout
    batch_layout() const;
    const ConstitutiveModel<dim> &
    get_model() const;
    const Formulation &
    get_formulation() const;

    /**
     * The committed state of the point whose properties are @p data, at
     * @p position, as its constitutive model sees it (the state view, of
     * @p n_state doubles, points into @p data). The one place that reads
     * it: the residual and the tangent call it for every point.
     */
    static PointState<dim>
    read_point_state(const double      *data,
                     const Offsets     &offsets,
                     const unsigned int n_state,
                     const Point<dim>  &position)
    {
      return {Utils::read_symmetric<dim>(data + offsets.strain),
              Utils::read_symmetric<dim>(data + offsets.stress),
              ArrayView<const double>(data + offsets.state, n_state),
              data[offsets.volume],
              static_cast<unsigned int>(data[offsets.material_id]),
              position};
    }

    /// Number of doubles of the model's own fields per point (the last
    /// fields of the layout).
    unsigned int
    n_state_components() const;

    /**
     * The committed state of @p particle as its constitutive model sees it
     * (the state view points into the particle's properties).
     */
    PointState<dim>
    point_state(const Particles::ParticleAccessor<dim> &particle) const;

    /**
     * Where @p particle was created: its location less its displacement
     * (the total displacement since the start, which the points carry).
     * Programs that classify points by where they started (a crack band,
     * a layer) use it once the body has deformed.
     */
    Point<dim>
    initial_location(const Particles::ParticleAccessor<dim> &particle) const;

    /**
     * The layout of the model's output fields (ConstitutiveModel::
     * output_fields()), in the order compute_output_fields() writes them.
     */
    PropertyLayout
    output_layout() const;

    /**
     * The values of the model's output fields (ConstitutiveModel::
     * output_fields()) at @p particle, written into @p values.
     */
    void
    compute_output_fields(const Particles::ParticleAccessor<dim> &particle,
                          ArrayView<double>                       values) const;

    /**
     * The rule of the last fill(): the points' positions in every cell
     * they filled, on the reference cell (SurfaceTractions finds the
     * neighbours of a point with it).
     */
    const Quadrature<dim> &
    placement_rule() const;

    /// The number of surface tractions each point carries an area of.
    unsigned int
    n_surface_loads() const;

    /// Number of points on all ranks.
    types::particle_index
    n_global_points() const;

    /// Sum of the current point volumes over all ranks.
    double
    total_volume() const;

  private:
    const BackgroundGrid<dim>      &grid;
    const ConstitutiveModel<dim>   &model;
    const Formulation               formulation;
    PropertyLayout                  layout;
    Offsets                         offsets;
    Quadrature<dim>                 last_rule;
    Particles::ParticleHandler<dim> particle_handler;
  };
} // namespace qsmpm

#endif
