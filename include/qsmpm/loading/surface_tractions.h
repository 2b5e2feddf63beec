#ifndef qsmpm_loading_surface_tractions_h
#define qsmpm_loading_surface_tractions_h

#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <vector>

namespace qsmpm
{
  /**
   * Tractions on the body's own surface, carried by its surface points so
   * that the load moves with the body (BoundaryDescriptor::
   * add_surface_traction()). A traction on a grid face (add_traction())
   * loads the nodes of that face, and once the body has left the face it
   * loads nodes without material: the load is lost (EquilibriumAudit
   * stops the run). Here the load belongs to the points.
   *
   * <h3>Which points, and their area</h3>
   * mark() finds the body's surface from the points themselves, once,
   * before the first step: the points of a cell sit on the tensor-product
   * rule of MaterialPointSet::fill() (MaterialPointSet::placement_rule()),
   * so each point has a next position in each direction +-e_d, in its own
   * cell or the neighbouring one. If no point sits there (on any rank: the
   * neighbour's points are read as ghost particles), the point's domain
   * has a face on the body's surface, halfway to that position, with
   * outward normal +-e_d and area
   *
   *   A_p = Omega_p^0 / (w_d h_d),
   *
   * the point's volume over the thickness of its layer (w_d the weight of
   * its coordinate in the 1D rule: 1/n for n regular points per
   * direction). A condition whose selector is true at that face's centre
   * gives the point the share A_p of its loaded area; a point at a corner
   * may get the areas of several faces. Over a loaded face of the body the
   * A_p sum to the face's area exactly. The selector sees the face centre
   * in the initial configuration.
   *
   * <h3>The force</h3>
   * A point's load acts on its loaded surface, not at the point: at the
   * area-weighted centre D_p of its loaded faces (relative to the point,
   * in the initial configuration), which moves with the point's
   * deformation, x_f = x_p + F_p D_p (x_p + D_p at small strain), and is
   * spread to the nodes of the cell around x_f with the grid's Q1
   * functions, f_i = N_i(x_f) f_p, the integral int t N_i dA of the
   * surface's share of the point (with any shape functions of the points:
   * the Q1 functions are the grid's own). A load at the point instead,
   * half a layer inside the surface, would not be in equilibrium with a
   * uniform stress in the cell that holds the surface, and a bar under an
   * end traction would deform non-uniformly near its end. As the points'
   * own shape functions, N_i(x_f) is that of the start of the step (the
   * grid is reset after every step).
   *  - dead: f_p = t(X_p, t) A_p, with X_p the point's initial position:
   *    a force per unit initial area of fixed direction;
   *  - pressure: f_p = -p(X_p, t) a_p, a_p = J F^{-T} N A_p the point's
   *    current area vector (Nanson), which commit() updates with the
   *    converged increment as a_p <- cof(Delta F) a_p. In a step the force
   *    follows the trial Delta F = I + grad du at the point, so it is part
   *    of the residual (add_pressure_forces()) and Newton sees the load
   *    stiffness through the Jacobian-free products (the preconditioner
   *    does not). At small strain a_p = N A_p: a dead load -p N.
   * The Q1 functions are a partition of unity: the nodes receive the
   * resultant of the loads exactly.
   */
  template <int dim>
  class SurfaceTractions
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /// The surface tractions of @p boundary, which must outlive this object.
    explicit SurfaceTractions(const BoundaryDescriptor<dim> &boundary);

    /// Whether there are surface tractions at all.
    bool
    empty() const;

    /**
     * Find the surface points of every condition and store their areas
     * (MaterialPointSet::Offsets::surface_load). Call once, with the points
     * where fill() put them. Collective. Throws if @p points carry no area
     * for each condition (the conditions were added after the points were
     * made) or if a condition selects no face of the body's surface.
     * Returns the loaded area of each condition (the sum over all ranks).
     */
    std::vector<double>
    mark(const BackgroundGrid<dim> &grid, MaterialPointSet<dim> &points) const;

    /**
     * The data of a step: the points of @p cache that carry a pressure,
     * the load factor @p t at the end of the step, and whether the points
     * deform at finite strain. @p ghosted_layout is a vector with the
     * layout the cache's local dof indices refer to
     * (QuasiStaticResidual::ghosted_layout()).
     */
    void
    reinit_step(const BackgroundGrid<dim>   &grid,
                const ShapeCache<dim>       &cache,
                const MaterialPointSet<dim> &points,
                const VectorType            &ghosted_layout,
                const double                 t);

    /// Add the dead loads at the load factor of reinit_step() to @p f_ext
    /// (not compressed).
    void
    add_dead_loads(VectorType &f_ext) const;

    /// Whether a pressure acts in this step.
    bool
    has_pressure() const;

    /**
     * Add the pressure forces of the increment @p du (owned entries) to
     * @p R (compressed).
     */
    void
    add_pressure_forces(const VectorType &du, VectorType &R) const;

    /**
     * For each point of condition @p k in this step (reinit_step()):
     * @p action(point, x_f, dofs, values, components) with the point's index
     * in the ShapeCache, the centre x_f of its faces, and the
     * dofs_per_cell dofs of the cell whose Q1 functions carry its load with
     * N_i(x_f) and the component (direction) of each: on a multi-field
     * grid (Contact between bodies) those of the point's body's field. A
     * drained surface of a pore fluid (PorePressureSolver) is such a condition
     * without load.
     */
    void
    for_each_load(
      const unsigned int                                         k,
      const std::function<void(const unsigned int             point,
                               const Point<dim>              &x_f,
                               const types::global_dof_index *dofs,
                               const double                  *values,
                               const unsigned int *components)> &action) const;

    /**
     * Store the current area vectors of the converged increment
     * @p du_ghosted (with the layout of reinit_step()) on the points.
     */
    void
    commit(MaterialPointSet<dim> &points, const VectorType &du_ghosted) const;

  private:
    struct Load;

    /// Add N_i(x_f) @p force of @p load to @p f (@p values: scratch of
    /// dofs_per_cell entries).
    void
    spread(const Load           &load,
           const Tensor<1, dim> &force,
           std::vector<double>  &values,
           VectorType           &f) const;

    /// The initial position X_p = x_p - u_p of cache point @p p.
    Point<dim>
    initial_position(const unsigned int p) const;

    /**
     * The area vector of condition @p k of cache point @p p in group
     * @p c at the increment whose entries @p du_local holds (the ghosted
     * layout): cof(Delta F) a_p at finite strain, a_p at small strain.
     */
    Tensor<1, dim>
    current_area(const unsigned int c,
                 const unsigned int p,
                 const unsigned int k,
                 const double      *du_local) const;

    const BoundaryDescriptor<dim> &boundary;

    /**
     * The load of one condition of one point in this step: the point in
     * the ShapeCache (its group and index), the condition, and the first
     * of its entries in load_dofs, load_values, load_components (one per
     * dof of the cell around x_f: N_i(x_f) and the component of dof i).
     */
    struct Load
    {
      unsigned int group;
      unsigned int point;
      unsigned int condition;
      unsigned int first;
      /// The centre x_f of the point's loaded faces.
      Point<dim> face_centre;
    };

    /// The step's data (reinit_step()).
    const ShapeCache<dim> *cache         = nullptr;
    unsigned int           offset        = 0;
    unsigned int           displacement  = 0;
    bool                   finite_strain = false;
    double                 time          = 0.;
    /// The dofs of a load: those of one body's field in a cell.
    unsigned int                         dofs_per_cell = 0;
    std::vector<Load>                    loads;
    std::vector<types::global_dof_index> load_dofs;
    std::vector<double>                  load_values;
    std::vector<unsigned int>            load_components;
    bool                                 pressure = false;
    mutable VectorType                   du_ghosted;
    mutable VectorType                   forces;
  };
} // namespace qsmpm

#endif
