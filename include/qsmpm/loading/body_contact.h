#ifndef qsmpm_loading_body_contact_h
#define qsmpm_loading_body_contact_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * Contact between deformable bodies on a multi-field grid (Bardenhagen et
   * al., "An improved contact algorithm for the material point method and
   * application to stress propagation in granular material", CMES 2001):
   * every body has its own displacement field on the grid
   * (BackgroundGrid::set_n_bodies()), so that two bodies that share a node
   * can move apart, and at the nodes where two bodies meet this class
   * decides whether they are in contact and, if so, ties their fields.
   *
   * At a node i shared by bodies a < b (both have material in its support)
   * the contact normal points from a to b: with g = sum_p Omega_p grad
   * N_i(x_p) over a body's points (it points out of the body where the node
   * lies on its surface), n = g_a / |g_a| if |g_a| >= |g_b|, else -g_b /
   * |g_b| (the body with the larger gradient decides, Nairn's "maximum
   * volume gradient": a corner resting on a flat face gets the face's
   * normal). The gap is measured between the points' boxes (half-lengths
   * l_d = Omega_p0^(1/dim) / 2, deformed with the point): the smallest n . x
   * of the corners of b's points around the node minus the largest of a's.
   * A node is in contact when the gap is closed; then the normal
   * displacements of the two fields are tied so that the gap stays closed,
   * (u_b - u_a) . n = -gap (frictionless), or all of them, u_b - u_a = -gap
   * n (rough: no slip). The ties are constraints of the step (exact, no
   * penalty), so two bodies in contact along a grid line behave as one body.
   * With Coulomb friction a node sticks (all displacements tied) or slips
   * (the normal tie, and a friction force mu lambda against the slip, a load
   * on both bodies' dofs, lambda the normal force of the last solve).
   *
   * The contact set of a step is found by an active-set iteration: it
   * starts with the nodes whose gap is closed at the start of the step
   * (sticking); after a converged solve, a tied node whose contact force is
   * tensile is released, a free node whose gap the solution closes (the
   * bodies would overlap) is tied, a sticking node whose tangential force
   * exceeds mu lambda slips, a slipping node that does not slide against its
   * friction force sticks, and the friction forces follow the new normal
   * forces; if anything changed, the step is solved again.
   *
   * Everything is decided from values that are the same on every rank
   * (sums and maxima over ranks, ghosted vectors), so all ranks that see a
   * node make the same constraint.
   */
  template <int dim>
  class BodyContact
  {
  public:
    /// The subsection "Contact between bodies" of a .prm file.
    struct Parameters : ParameterStruct<Parameters>
    {
      /// The material ids of each body: bodies separated by ';', the ids
      /// of one body by ','. Empty: one body, no contact.
      std::string bodies;
      /// How two bodies in contact move along each other.
      enum class Friction
      {
        /// Only the normal displacements are tied: free sliding.
        frictionless,
        /// All displacements are tied: no slip.
        rough,
        /// Coulomb's law: a node sticks (all displacements tied) while
        /// its tangential force is at most mu times its normal force,
        /// and slips (normal tie, tangential force mu times the normal
        /// force against the slip) otherwise.
        coulomb
      };
      Friction friction = Friction::frictionless;
      /// mu of Coulomb friction.
      double friction_coefficient = 0.;
      /// A gap at most this times the cell size counts as closed.
      double gap_tolerance = 1e-3;
      /// Solves of one step with a changed contact set at most.
      unsigned int max_iterations = 10;

      void
      add_parameters(ParameterHandler &prm);

      /// The body of every material id (numbers::invalid_unsigned_int for
      /// an id of no body); empty without bodies. Throws on a malformed
      /// list or an id given to two bodies.
      std::vector<unsigned int>
      body_of_material() const;

      void
      check() const;
    };

    /// The contact state of one node shared by two bodies.
    struct Node
    {
      /// The dofs of body a and of body b at the node.
      std::array<types::global_dof_index, dim> dofs_a, dofs_b;
      Point<dim>                               location;
      Tensor<1, dim>                           normal;
      /// The gap at the start of the step.
      double gap = 0.;
      /// Whether the node was in contact at the start of the step (its
      /// gap within the tolerance): the tie keeps the bodies where they
      /// are, instead of closing what is left of the gap.
      bool touching = false;
      bool active   = false;
      /// Coulomb friction: whether the node sticks (all displacements
      /// tied) or slips.
      bool stick = true;
      /// Coulomb friction: whether the node went back from slip to stick
      /// in the solves of this step. It then slips again only if its
      /// tangential force exceeds mu times the normal force by more than
      /// the tolerance of the friction forces (see update()).
      bool stuck_again = false;
      /// Coulomb friction, while the node slips: the friction force on
      /// body b (body a gets the opposite), tangential, mu times the
      /// normal force of the last solve.
      Tensor<1, dim> friction;
      /// Per component, whose dof the tie constrains: 0 body b's, 1 body
      /// a's, -1 none (both held by displacement conditions, or not tied).
      std::array<int, dim> tied;
    };

    /// Set up from the parameters; n_bodies() is then the number of bodies.
    void
    initialize(const Parameters &parameters);

    /// Whether there are several bodies.
    bool
    enabled() const
    {
      return n_body_fields > 1;
    }

    unsigned int
    n_bodies() const
    {
      return n_body_fields;
    }

    const std::vector<unsigned int> &
    body_of_material() const
    {
      return body_of;
    }

    /**
     * Stop, on all ranks together, if a point of @p points has a material
     * id that belongs to none of the bodies (a point's body decides which
     * field carries it, in every step).
     */
    void
    check_points(const MaterialPointSet<dim> &points,
                 const MPI_Comm               communicator) const;

    /**
     * At the start of a step: the nodes shared by two bodies (of the
     * locally relevant ones, without those in @p inactive), their normals
     * and gaps from the points at the start of the step, and the nodes in
     * contact (closed gap).
     */
    void
    reinit_step(const BackgroundGrid<dim>   &grid,
                const ShapeCache<dim>       &cache,
                const MaterialPointSet<dim> &points,
                const IndexSet              &inactive);

    /**
     * Add the ties of the nodes in contact to @p constraints (not closed).
     * A dof that is already constrained (a displacement condition) is not
     * constrained again: the other body's dof is tied instead, or, if both
     * are held, nothing.
     */
    void
    add_constraints(AffineConstraints<double> &constraints);

    /**
     * Add the friction forces of the slipping nodes (Coulomb friction) to
     * @p f_ext (owned layout, not compressed: each rank adds those of its
     * own dofs).
     */
    void
    add_friction_forces(TrilinosWrappers::MPI::Vector &f_ext) const;

    /**
     * After a converged solve with increment @p du and residual @p R
     * (R = f_ext - f_int, owned layout): release the tied nodes with a
     * tensile contact force and tie the free nodes whose gap has closed;
     * with Coulomb friction, let a sticking node whose tangential force
     * exceeds mu times its normal force slip, stick a slipping node that
     * slides along its friction force, and set the friction force of a
     * slipping node to mu times its new normal force against its slip.
     * Returns whether the step must be solved again: the contact set
     * changed, or a friction force by more than 1e-4 of the largest
     * contact force.
     */
    bool
    update(const BackgroundGrid<dim>           &grid,
           const TrilinosWrappers::MPI::Vector &du,
           const TrilinosWrappers::MPI::Vector &R);

    /// The number of nodes in contact (over all ranks, each once).
    unsigned int
    n_active(const BackgroundGrid<dim> &grid) const;

    /**
     * The sum of the normal contact forces of the nodes in contact at the
     * last update() (each node once, over all ranks; per unit thickness in
     * 2D): the force with which the bodies press on each other.
     */
    double
    total_normal_force() const
    {
      return total_force;
    }

    const Parameters &
    get_parameters() const
    {
      return parameters;
    }

  private:
    /// Whether all displacements of @p node are tied (rough, or Coulomb
    /// friction while it sticks).
    bool
    ties_all(const Node &node) const
    {
      return parameters.friction == Parameters::Friction::rough ||
             (parameters.friction == Parameters::Friction::coulomb &&
              node.stick);
    }

    /// The force of body a on body b through the ties of a tied node,
    /// from the residual with ghost values (without the friction force of
    /// a slipping node, which is a load).
    Tensor<1, dim>
    tie_force(const Node &node, const TrilinosWrappers::MPI::Vector &R) const;

    /// The contact force of a tied node (positive: compression), from the
    /// residual with ghost values.
    double
    normal_force(const Node                          &node,
                 const TrilinosWrappers::MPI::Vector &R) const;

    Parameters                parameters;
    unsigned int              n_body_fields = 1;
    std::vector<unsigned int> body_of;
    std::vector<Node>         nodes;
    double                    gap_tolerance = 0.;
    double                    total_force   = 0.;
  };
} // namespace qsmpm

#endif
