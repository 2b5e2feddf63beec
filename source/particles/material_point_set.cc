#include <cmath>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numeric>
#include <qsmpm/base/utilities.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <sstream>
#include <tuple>

namespace qsmpm
{
  namespace
  {
    /**
     * A parser of @p n_components expressions in x, y (and z), the text of
     * the entry @p entry of "Material points"; a text that is no such
     * expression stops with a message naming the entry and saying that it
     * must be @p what.
     */
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    make_parser(const std::string &entry,
                const std::string &text,
                const unsigned int n_components,
                const std::string &what)
    {
      auto parser = std::make_unique<FunctionParser<dim>>(n_components);
      try
        {
          parser->initialize(dim == 2 ? "x,y" : "x,y,z",
                             text,
                             std::map<std::string, double>());
          // muParser reads the text at the first evaluation.
          Vector<double> values(n_components);
          parser->vector_value(Point<dim>(), values);
        }
      catch (...)
        {
          AssertThrow(false,
                      ExcMessage("Material points: <" + entry + "> = <" + text +
                                 "> is not " + what + "."));
        }
      return parser;
    }
  } // namespace



  template <int dim>
  void
  MaterialPointSet<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material points");
    {
      prm.add_parameter("Points per cell per direction",
                        points_per_direction,
                        "n: each filled cell receives n^dim material points.",
                        Patterns::Integer(1, 10));
      Utils::add_selection<Placement>(
        prm,
        "Placement",
        placement,
        {{"regular", Placement::regular}, {"gauss", Placement::gauss}},
        "regular: points at the centres of an n^dim "
        "subdivision of the cell, equal volumes; gauss: "
        "points at the n-point Gauss rule with volumes equal "
        "to the Gauss weights times the cell volume (MPM then "
        "coincides with the finite element method at the "
        "first step).");
      prm.add_parameter("Region lower corner",
                        region_lower_corner,
                        "If given (with the upper corner), only points in "
                        "this box are kept; empty: the whole grid is filled.",
                        Patterns::Anything());
      prm.add_parameter("Region upper corner",
                        region_upper_corner,
                        "",
                        Patterns::Anything());
      prm.add_parameter(
        "Region expression",
        region_expression,
        "If given, only points where this expression in x, y (and z) is "
        "positive are created (within the region box, if one is given): "
        "bodies with holes or notches, or two bodies with a gap between "
        "them, e.g. 'if(x < 1 || x > 1.1, 1, 0)'. Empty: everywhere.",
        Patterns::Anything());
      prm.add_parameter(
        "Material id",
        material_id,
        "The material id of the points, an expression in x, y (and z) "
        "evaluated where each point is created; its value must be a "
        "non-negative integer, e.g. 'if(y > 0.5, 1, 0)' for two layers. "
        "Material/<Models by material id> chooses a model per id.",
        Patterns::Anything());
      prm.add_parameter(
        "Initial stress",
        initial_stress,
        "The stress of each point when it is created (Cauchy, tension "
        "positive): expressions in x, y (and z) for xx; yy; zz; xy in 2D "
        "(zz the out-of-plane stress) and xx; yy; zz; xy; xz; yz in 3D, "
        "e.g. a layer 10 m deep of unit weight 20 kN/m^3 at rest (K0 = "
        "0.5) under its weight: '-10*(10-y); -20*(10-y); -10*(10-y); 0'. "
        "The model's state is made to carry it (an elastoplastic model: "
        "inside its yield surface; linear, cubic elastic and UMAT models: "
        "as the stress they add their increments to; hyperelastic and "
        "crack models cannot). It should balance the body force and the loads "
        "of the "
        "first step: what it does not balance moves the body. Empty: the "
        "model's own (zero, or -p0 I for Modified Cam Clay).",
        Patterns::Anything());
      prm.add_parameter(
        "Axisymmetric",
        formulation.axisymmetric,
        "2D only: axisymmetric (r, z) kinematics, x the radius r >= 0 and y "
        "the axis z. Volumes, forces and reactions are per radian (times "
        "2 pi for the whole ring), the strain has the hoop component u_r / r "
        "and the stress sigma_thetatheta (the points' fields hoop_strain and "
        "hoop_stress; at finite strain ln(r / R) and the Cauchy hoop "
        "stress). Linear or GIMP shape functions (the hoop strain from the "
        "weights over r_p, which with GIMP is its exact average over the "
        "point's ring), with or without F-bar (the hoop strain's share of "
        "the volume change included); small strain: "
        "models linear elastic (not plane stress) and the "
        "plasticity models (von Mises, Drucker-Prager, Mohr-Coulomb, "
        "modified Cam clay); finite strain: the plasticity models; both "
        "also under a pore fluid (drained through grid faces). Hold u_r = "
        "0 on the axis r = 0 if the body reaches it.",
        Patterns::Bool());
      prm.add_parameter("Update volumes",
                        update_volumes,
                        "Update point volumes with J (paper eqs. 2.23-2.24). "
                        "false keeps the initial volumes: with the points at "
                        "Gauss points the first step is that of linear "
                        "finite elements (and every step, with <Move points "
                        "= false>).",
                        Patterns::Bool());
      prm.add_parameter(
        "Move points",
        formulation.move_points,
        "true: the points move with the grid's increment at the end of each "
        "step (paper eqs. 2.26-2.27), the material-point method. false: "
        "they stay where they were created and accumulate their "
        "displacement only; with <Update volumes = false>, which it needs, "
        "this is the small-displacement theory with the points as a fixed "
        "quadrature (the finite element method when they sit at Gauss "
        "points), which does not change as the body deforms. Needs <Kinematics "
        "= small strain>; a rigid body meets the points where their "
        "displacement puts them; not with contact between bodies, whose "
        "grids follow the points' positions.",
        Patterns::Bool());
      Utils::add_selection<Kinematics>(
        prm,
        "Kinematics",
        formulation.kinematics,
        {{"small strain", Kinematics::small_strain},
         {"finite strain", Kinematics::finite_strain}},
        "small strain: the paper's formulation (strain "
        "increments sym grad du, Cauchy stress updated "
        "incrementally). finite strain: updated Lagrangian "
        "on the reset grid, Delta F = I + grad du at the "
        "points, F = Delta F F, Kirchhoff stress from a "
        "hyperelastic (or finite-strain) model, internal "
        "force on the current volume det(F) Omega_0. Needs "
        "a model that supports finite strain (hencky, "
        "neo-Hookean, von Mises, Drucker-Prager).");
      Utils::add_selection<ShapeFunctions>(
        prm,
        "Shape functions",
        formulation.shape_functions,
        {{"linear", ShapeFunctions::linear},
         {"uGIMP", ShapeFunctions::ugimp},
         {"cpGIMP", ShapeFunctions::cpgimp}},
        "linear: the FE_Q(1) functions of the point's cell "
        "(the paper). uGIMP: generalized interpolation "
        "material point weights (averages of the linear "
        "functions over the point's box-shaped domain, "
        "Bardenhagen & Kober 2004), which reach the nodes of "
        "neighbouring cells and remove the cell-crossing "
        "error; the domain keeps its initial size. cpGIMP: "
        "the domain's half-lengths follow the stretch of "
        "the point (l_d = l_d^0 U_dd, F = R U). GIMP needs "
        "a uniform grid; a domain is at most half a cell "
        "wide in each direction.");
      Utils::add_selection<VolumetricTreatment>(
        prm,
        "Volumetric locking",
        formulation.volumetric,
        {{"none", VolumetricTreatment::none},
         {"F-bar", VolumetricTreatment::fbar}},
        "none: every point uses its own kinematics (the "
        "paper). F-bar: the volume change of each point is "
        "replaced by the volume-weighted mean over the "
        "points of its cell (Coombs et al. 2018; at small "
        "strain the same on tr d eps), which removes the "
        "volumetric locking of plastic flow and nearly "
        "incompressible materials on bilinear/trilinear "
        "cells. With Drucker-Prager, Mohr-Coulomb or Modified "
        "Cam Clay (also in a material map, under a pore fluid, "
        "axisymmetric, or a UMAT with <Elastic strain state "
        "variable>) only the elastic part of the volume change "
        "is the cell's mean and each point adds its own plastic "
        "one (no dilatancy locking; small strain).");
      prm.add_parameter(
        "Minimum nodal volume",
        min_nodal_volume_fraction,
        "Nodes whose support holds less material than this fraction of a "
        "cell's volume (sum_p Omega_p N_i(x_p) / h^dim) are held fixed in "
        "the step, like the nodes without points (paper Section 2.2). 0: "
        "only nodes without points. With GIMP a node that a point's domain "
        "only just reaches has a nearly vanishing stiffness, which makes "
        "Newton stall at large deformation (most of all with F-bar); a "
        "value of about 0.01 removes those nodes.",
        Patterns::Double(0., 1.));
      prm.add_parameter(
        "Minimum nodal stiffness",
        min_nodal_stiffness_fraction,
        "Degrees of freedom whose stiffness against their own motion (the "
        "diagonal of the tangent the models give at the points, K_ii = "
        "sum_p Omega_p grad N_i . C_p . grad N_i) is at most this fraction "
        "of its mean over the grid are held fixed in the step, like the "
        "nodes without points. A node whose points have all lost their "
        "stiffness in a direction -- the points of a completely failed "
        "crack band that opens, once the intact points beside them have "
        "left the node's cells -- has none, and the step's Jacobian would "
        "be singular. The same threshold holds the motion of two coupled "
        "dofs that no point stiffens although each has stiffness (a point "
        "on a face of its cell beside failed points; the eigenvalues of "
        "the pair's 2 x 2 block of the tangent, searched in the steps "
        "where the points of a cell all lie within sqrt(fraction) of one "
        "face) by a spring on that motion, which carries no load. "
        "0: never.",
        Patterns::Double(0., 1.));
      prm.add_parameter(
        "Ghost penalty",
        ghost_penalty,
        "gamma > 0: the increments of the nodes that the material only "
        "partly surrounds are tied to the gradient of the increment in the "
        "neighbouring cells by the ghost penalty gamma E_s h int_F "
        "[[grad du . n]]^2 on the faces of cut cells (Coombs 2023), with "
        "E_s the mean stiffness of the grid's degrees of freedom. It gives "
        "such nodes stiffness without holding them (it carries no load: "
        "it vanishes for linear fields), so that Newton does not stall "
        "when the body moves into a new row of cells. 0.1 suits an "
        "elastic body; in plastic flow, whose stiffness is far below E_s, "
        "it stiffens the response (the footing at finite strain: +12 % "
        "with 0.1, within 1 % with 1e-3 or 1e-4). 0: none (the paper).",
        Patterns::Double(0.));
    }
    prm.leave_subsection();
  }



  template <int dim>
  bool
  MaterialPointSet<dim>::Parameters::restrict_to_box() const
  {
    return !region_lower_corner.empty() || !region_upper_corner.empty();
  }



  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  MaterialPointSet<dim>::Parameters::region() const
  {
    AssertThrow(region_lower_corner.empty() == region_upper_corner.empty(),
                ExcMessage("Material points: give both <Region lower "
                           "corner> and <Region upper corner>, or neither."));
    return {Utils::parse_point<dim>(region_lower_corner, "Region lower corner"),
            Utils::parse_point<dim>(region_upper_corner,
                                    "Region upper corner")};
  }



  template <int dim>
  void
  MaterialPointSet<dim>::Parameters::check() const
  {
    AssertThrow(update_volumes || !formulation.finite_strain(),
                ExcMessage("Material points: <Update volumes = false> "
                           "(a geometrically linear model) contradicts "
                           "<Kinematics = finite strain>."));
    AssertThrow(formulation.move_points || !formulation.finite_strain(),
                ExcMessage("Material points: <Move points = false> (the "
                           "small-displacement theory) contradicts "
                           "<Kinematics = finite strain>."));
    AssertThrow(formulation.move_points || !update_volumes,
                ExcMessage("Material points: <Move points = false> (the "
                           "points as a fixed quadrature) needs <Update "
                           "volumes = false>: the quadrature's weights do "
                           "not change either."));
    AssertThrow(!formulation.axisymmetric || dim == 2,
                ExcMessage("Material points: <Axisymmetric = true> needs a "
                           "2D grid."));
    AssertThrow(!formulation.axisymmetric || min_nodal_volume_fraction == 0.,
                ExcMessage("Material points: <Axisymmetric = true> is not "
                           "available with <Minimum nodal volume> above 0."));
    if (restrict_to_box())
      region();
  }



  template <int dim>
  MaterialPointSet<dim>::MaterialPointSet(
    const BackgroundGrid<dim>      &grid,
    const ConstitutiveModel<dim>   &model,
    const Formulation              &formulation,
    const unsigned int              n_surface_loads,
    const std::vector<std::string> &contact_bodies)
    : grid(grid)
    , model(model)
    , formulation(formulation)
  {
    AssertThrow(!formulation.finite_strain() || model.supports_finite_strain(),
                ExcMessage("Kinematics = finite strain, but the constitutive "
                           "model <" +
                           model.name() +
                           "> is small-strain only. Finite-strain models: "
                           "hencky, neo-Hookean, von Mises, Drucker-Prager."));
    AssertThrow(!formulation.axisymmetric || !formulation.finite_strain() ||
                  model.supports_axisymmetric_finite_strain(),
                ExcMessage("Material points: Axisymmetric = true and "
                           "Kinematics = finite strain, but the constitutive "
                           "model <" +
                           model.name() +
                           "> has no axisymmetric finite-strain update. Models "
                           "that have one: von Mises, Drucker-Prager, "
                           "Mohr-Coulomb, modified Cam clay (Hencky "
                           "elasticity inside the yield surface)."));
    AssertThrow(!formulation.axisymmetric || model.supports_axisymmetry(),
                ExcMessage("Material points: Axisymmetric = true, but the "
                           "constitutive model <" +
                           model.name() +
                           "> has no axisymmetric update. Models that have "
                           "one: linear elastic (plane strain), von Mises, "
                           "Drucker-Prager, Mohr-Coulomb, modified Cam "
                           "clay."));
    AssertThrow(!formulation.axisymmetric || n_surface_loads == 0,
                ExcMessage("Material points: <Axisymmetric = true> is not "
                           "available with tractions on the body's surface "
                           "(tractions on grid faces are)."));
    AssertThrow(!formulation.axisymmetric || grid.lower_corner()[0] >= 0.,
                ExcMessage("Material points: Axisymmetric = true, but the "
                           "grid reaches x = r < 0; the axis is x = 0."));
    using Kind               = PropertyLayout::Kind;
    const unsigned int n_sym = Utils::n_symmetric_components<dim>;
    offsets.initial_volume   = layout.add("initial_volume", 1, Kind::scalar);
    offsets.volume           = layout.add("volume", 1, Kind::scalar);
    offsets.J                = layout.add("J", 1, Kind::scalar);
    offsets.displacement     = layout.add("displacement", dim, Kind::vector);
    offsets.strain           = layout.add("strain", n_sym, Kind::symmetric);
    offsets.stress           = layout.add("stress", n_sym, Kind::symmetric);
    offsets.material_id      = layout.add("material_id", 1, Kind::scalar);
    if (formulation.finite_strain())
      offsets.deformation_gradient =
        layout.add("deformation_gradient", dim * dim, Kind::scalar);
    if (formulation.axisymmetric)
      {
        offsets.hoop_strain = layout.add("hoop_strain", 1, Kind::scalar);
        offsets.hoop_stress = layout.add("hoop_stress", 1, Kind::scalar);
      }
    if (formulation.gimp())
      offsets.initial_half_length =
        layout.add("initial_half_length", dim, Kind::vector);
    if (n_surface_loads > 0)
      offsets.surface_load = layout.add("surface_load",
                                        n_surface_loads * (2 * dim + 1),
                                        Kind::scalar);
    if (!contact_bodies.empty())
      offsets.contact = layout.size();
    for (const auto &body : contact_bodies)
      layout.add("contact_" + body, dim, Kind::vector);
    if (!contact_bodies.empty())
      offsets.contact_point = layout.size();
    for (const auto &body : contact_bodies)
      {
        layout.add("contact_point_" + body, dim, Kind::vector);
        layout.add("contact_normal_" + body, dim, Kind::vector);
      }
    if (!contact_bodies.empty() && formulation.fbar())
      offsets.fbar_volume_excess =
        layout.add("fbar_volume_excess", 1, Kind::scalar);
    offsets.state = layout.size();
    for (const auto &field : model.state_fields())
      layout.add(field.name, field.n_components, Kind::scalar);

    particle_handler.initialize(grid.get_triangulation(),
                                grid.get_mapping(),
                                layout.size());
  }



  template <int dim>
  Quadrature<dim>
  MaterialPointSet<dim>::reference_rule(const Placement placement,
                                        const std::array<unsigned int, dim> &n)
  {
    // One 1D rule per direction on [0,1], then their tensor product.
    std::array<Quadrature<1>, dim> rules;
    for (unsigned int d = 0; d < dim; ++d)
      {
        AssertThrow(n[d] >= 1,
                    ExcMessage("At least one point per cell and direction "
                               "is needed."));
        if (placement == Placement::gauss)
          rules[d] = QGauss<1>(n[d]);
        else
          {
            std::vector<Point<1>> points_1d(n[d]);
            for (unsigned int i = 0; i < n[d]; ++i)
              points_1d[i][0] = (i + 0.5) / n[d];
            rules[d] =
              Quadrature<1>(points_1d, std::vector<double>(n[d], 1. / n[d]));
          }
      }
    if constexpr (dim == 2)
      return QAnisotropic<2>(rules[0], rules[1]);
    else
      return QAnisotropic<3>(rules[0], rules[1], rules[2]);
  }



  template <int dim>
  void
  MaterialPointSet<dim>::fill(
    const std::function<bool(const Point<dim> &)> &inside,
    const unsigned int                             n,
    const Placement                                placement,
    const unsigned int                             material_id)
  {
    AssertThrow(n >= 1, ExcMessage("At least one point per cell is needed."));
    std::array<unsigned int, dim> n_per_direction;
    n_per_direction.fill(n);
    fill(inside, reference_rule(placement, n_per_direction), material_id);
  }



  template <int dim>
  void
  MaterialPointSet<dim>::fill(
    const std::function<bool(const Point<dim> &)> &inside,
    const Quadrature<dim>                         &rule,
    const unsigned int                             material_id)
  {
    fill(inside, rule, [material_id](const Point<dim> &) {
      return material_id;
    });
  }



  template <int dim>
  void
  MaterialPointSet<dim>::fill(
    const std::function<bool(const Point<dim> &)>         &inside,
    const Quadrature<dim>                                 &rule,
    const std::function<unsigned int(const Point<dim> &)> &material_id)
  {
    fill(inside, rule, material_id, {});
  }



  template <int dim>
  void
  MaterialPointSet<dim>::fill(
    const std::function<bool(const Point<dim> &)>         &inside,
    const Quadrature<dim>                                 &rule,
    const std::function<unsigned int(const Point<dim> &)> &material_id,
    const std::function<SymmetricTensor<2, 3>(const Point<dim> &)>
      &initial_stress)
  {
    // Reference positions and volume fractions of the points in a cell.
    const std::vector<Point<dim>> &reference_points = rule.get_points();
    const std::vector<double>     &fractions        = rule.get_weights();
    AssertThrow(std::abs(
                  std::accumulate(fractions.begin(), fractions.end(), 0.) -
                  1.) < 1e-12,
                ExcMessage("The volume fractions of the points of a cell "
                           "(the weights of the rule) must sum to one."));

    last_rule = rule;

    // First collect the new points, so that globally unique ids can be
    // handed out with one prefix sum over the ranks.
    struct NewPoint
    {
      typename Triangulation<dim>::active_cell_iterator cell;
      Point<dim>                                        location;
      Point<dim>                                        reference;
      double                                            volume;
      double                                            fraction;
      unsigned int                                      material_id;
    };
    std::vector<NewPoint> new_points;
    for (const auto &cell : grid.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double volume = cell->measure();
          for (unsigned int q = 0; q < reference_points.size(); ++q)
            {
              const Point<dim> x =
                grid.get_mapping().transform_unit_to_real_cell(
                  cell, reference_points[q]);
              // Axisymmetric: the volume per radian, r dA.
              if (inside(x))
                new_points.push_back({cell,
                                      x,
                                      reference_points[q],
                                      volume * fractions[q] *
                                        (formulation.axisymmetric ? x[0] : 1.),
                                      fractions[q],
                                      0});
            }
        }

    // The points' ids: consecutive over the ranks, in the order of the
    // cells (which does not depend on the partition).
    const MPI_Comm              comm     = grid.get_communicator();
    const types::particle_index n_local  = new_points.size();
    types::particle_index       first_id = 0;
    MPI_Exscan(&n_local,
               &first_id,
               1,
               Utilities::MPI::mpi_type_id_for_type<types::particle_index>,
               MPI_SUM,
               comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      first_id = 0;
    first_id += particle_handler.n_global_particles();

    // The material ids and the model's initial state of every point. An
    // error here (an id that is not an integer, an id without a model) may
    // arise on some ranks only; all ranks stop with the first rank's
    // message instead of waiting for each other in the collective calls
    // below.
    const unsigned int  n_state = model.n_state_components();
    std::vector<double> initial_states(new_points.size() * n_state);
    std::vector<SymmetricTensor<2, dim>> initial_stresses(new_points.size());
    std::vector<double> initial_hoop_stresses(new_points.size(), 0.);
    std::string         error;
    try
      {
        for (std::size_t i = 0; i < new_points.size(); ++i)
          {
            NewPoint &p   = new_points[i];
            p.material_id = material_id(p.location);
            const ArrayView<double> state(initial_states.data() + i * n_state,
                                          n_state);
            model.initialize_point_state(p.location,
                                         p.material_id,
                                         first_id + i,
                                         state);
            const SymmetricTensor<2, 3> sigma0 = initial_stress ?
                                                   initial_stress(p.location) :
                                                   SymmetricTensor<2, 3>();
            initial_stresses[i] =
              model.initial_stress(p.location,
                                   p.material_id,
                                   initial_stress ? &sigma0 : nullptr,
                                   state);
            initial_hoop_stresses[i] =
              model.initial_hoop_stress(initial_stress ? &sigma0 : nullptr,
                                        state);
          }
      }
    catch (const std::exception &exc)
      {
        error = Utils::error_message(exc);
      }
    Utils::throw_if_any_rank(error, grid.get_communicator());

    particle_handler.reserve(particle_handler.n_locally_owned_particles() +
                             n_local);
    std::vector<double> properties(layout.size(), 0.);
    for (types::particle_index i = 0; i < n_local; ++i)
      {
        const NewPoint &p = new_points[i];
        std::fill(properties.begin(), properties.end(), 0.);
        properties[offsets.initial_volume] = p.volume;
        properties[offsets.volume]         = p.volume;
        properties[offsets.J]              = 1.;
        properties[offsets.material_id]    = p.material_id;
        Utils::write_symmetric<dim>(initial_stresses[i],
                                    properties.data() + offsets.stress);
        if (formulation.finite_strain())
          for (unsigned int d = 0; d < dim; ++d)
            properties[offsets.deformation_gradient + d * dim + d] = 1.;
        if (formulation.axisymmetric)
          properties[offsets.hoop_stress] = initial_hoop_stresses[i];
        if (formulation.gimp())
          for (unsigned int d = 0; d < dim; ++d)
            properties[offsets.initial_half_length + d] =
              0.5 * p.cell->extent_in_direction(d) *
              std::pow(p.fraction, 1. / dim);
        std::copy(initial_states.begin() + i * n_state,
                  initial_states.begin() + (i + 1) * n_state,
                  properties.begin() + offsets.state);
        particle_handler.insert_particle(
          p.location, p.reference, first_id + i, p.cell, properties);
      }
    particle_handler.update_cached_numbers();
  }



  template <int dim>
  void
  MaterialPointSet<dim>::fill(const Parameters &parameters)
  {
    const bool restrict_to_box = parameters.restrict_to_box();
    Point<dim> region_lower, region_upper;
    if (restrict_to_box)
      {
        std::tie(region_lower, region_upper) = parameters.region();
        // A box reaching beyond the grid is clipped to it; say so, since a
        // body smaller than intended changes every result.
        const Point<dim> &lower = grid.lower_corner(),
                         &upper = grid.upper_corner();
        const double tolerance  = 1e-12 * lower.distance(upper);
        bool         outside    = false;
        for (unsigned int d = 0; d < dim; ++d)
          {
            AssertThrow(region_lower[d] < region_upper[d],
                        ExcMessage("Material points: <Region lower corner> "
                                   "must lie below <Region upper corner> in "
                                   "every direction."));
            outside = outside || region_lower[d] < lower[d] - tolerance ||
                      region_upper[d] > upper[d] + tolerance;
          }
        if (outside &&
            Utilities::MPI::this_mpi_process(grid.get_communicator()) == 0)
          std::cerr << "Warning: Material points: the region box ("
                    << region_lower << ") - (" << region_upper
                    << ") reaches beyond the grid (" << lower << ") - ("
                    << upper << "); points are created only inside the grid."
                    << std::endl;
      }
    // The material id expression, checked at every point: a value that is
    // not a non-negative integer is a mistake in the .prm, not something to
    // round.
    const std::string in_xyz =
      std::string("an expression in x, y") + (dim == 3 ? ", z" : "");
    const auto id_parser =
      make_parser<dim>("Material id", parameters.material_id, 1, in_xyz);
    const auto material_id = [&](const Point<dim> &x) -> unsigned int {
      const double value = id_parser->value(x);
      if (!(std::isfinite(value) && value >= 0. && value < 1e9 &&
            std::abs(value - std::round(value)) < 1e-9))
        {
          std::ostringstream message;
          message << "Material points: <Material id> = <"
                  << parameters.material_id << "> is " << value << " at (" << x
                  << "); it must be a non-negative integer.";
          AssertThrow(false, ExcMessage(message.str()));
        }
      return static_cast<unsigned int>(std::round(value));
    };
    // The initial stress expression: dim == 2: xx, yy, zz, xy; dim == 3:
    // xx, yy, zz, xy, xz, yz.
    const unsigned int                   n_stress = dim == 2 ? 4 : 6;
    std::unique_ptr<FunctionParser<dim>> stress_parser;
    if (!parameters.initial_stress.empty())
      stress_parser = make_parser<dim>(
        "Initial stress",
        parameters.initial_stress,
        n_stress,
        std::to_string(n_stress) + " expressions in x, y" +
          (dim == 3 ? ", z" : "") + " separated by ';' (" +
          (dim == 2 ? "xx; yy; zz; xy" : "xx; yy; zz; xy; xz; yz") + ")");
    // The region expression: points where it is positive.
    std::unique_ptr<FunctionParser<dim>> region_parser;
    if (!parameters.region_expression.empty())
      region_parser = make_parser<dim>("Region expression",
                                       parameters.region_expression,
                                       1,
                                       in_xyz);
    Vector<double> values(n_stress);
    const auto     initial_stress =
      [&](const Point<dim> &x) -> SymmetricTensor<2, 3> {
      stress_parser->vector_value(x, values);
      SymmetricTensor<2, 3> sigma;
      sigma[0][0] = values[0];
      sigma[1][1] = values[1];
      sigma[2][2] = values[2];
      sigma[0][1] = values[3];
      if (dim == 3)
        {
          sigma[0][2] = values[4];
          sigma[1][2] = values[5];
        }
      for (unsigned int i = 0; i < n_stress; ++i)
        if (!std::isfinite(values[i]))
          {
            std::ostringstream message;
            message << "Material points: <Initial stress> = <"
                    << parameters.initial_stress << "> is not finite at (" << x
                    << ").";
            AssertThrow(false, ExcMessage(message.str()));
          }
      return sigma;
    };
    std::array<unsigned int, dim> n_per_direction;
    n_per_direction.fill(parameters.points_per_direction);
    fill(
      [restrict_to_box, region_lower, region_upper, &region_parser](
        const Point<dim> &x) {
        if (region_parser && !(region_parser->value(x) > 0.))
          return false;
        if (!restrict_to_box)
          return true;
        for (unsigned int d = 0; d < dim; ++d)
          if (x[d] < region_lower[d] || x[d] > region_upper[d])
            return false;
        return true;
      },
      reference_rule(parameters.placement, n_per_direction),
      material_id,
      stress_parser ?
        std::function<SymmetricTensor<2, 3>(const Point<dim> &)>(
          initial_stress) :
        std::function<SymmetricTensor<2, 3>(const Point<dim> &)>());
  }



  template <int dim>
  double
  MaterialPointSet<dim>::advect(const ShapeCache<dim>               &cache,
                                const TrilinosWrappers::MPI::Vector &du)
  {
    const bool    move    = formulation.move_points;
    double        largest = 0.;
    const double *values  = du.trilinos_vector()[0];
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const auto  &range = cache.cell(c);
        unsigned int p     = range.first_point;
        // The cache was filled in this same order at the start of the step.
        for (auto &particle : particle_handler.particles_in_cell(range.cell))
          {
            double *data = particle.get_properties().data();
            Assert(data == cache.properties(p), ExcInternalError());
            const Tensor<1, dim> u = cache.interpolate(c, p, values);
            if (move)
              {
                largest = std::max(largest, u.norm());
                particle.set_location(particle.get_location() + u);
              }
            for (unsigned int d = 0; d < dim; ++d)
              data[offsets.displacement + d] += u[d];
            ++p;
          }
        Assert(p == range.end_point, ExcInternalError());
      }
    return Utilities::MPI::max(largest, grid.get_communicator());
  }



  template <int dim>
  typename PointStateBatch<dim>::Layout
  MaterialPointSet<dim>::batch_layout() const
  {
    return {offsets.strain,
            offsets.stress,
            offsets.volume,
            offsets.material_id,
            offsets.state,
            n_state_components()};
  }



  template <int dim>
  bool
  MaterialPointSet<dim>::locate_in_cells()
  {
    bool                    inside = true;
    std::vector<Point<dim>> real_locations, reference_locations;
    for (const auto &cell : grid.get_triangulation().active_cell_iterators())
      {
        if (!inside)
          break;
        if (!cell->is_locally_owned())
          continue;
        const auto particles = particle_handler.particles_in_cell(cell);
        if (particles.begin() == particles.end())
          continue;

        const Point<dim> &origin = cell->vertex(0);
        Tensor<2, dim>    jacobian;
        const bool affine = BackgroundGrid<dim>::affine_map(cell, jacobian);
        if (affine)
          {
            const Tensor<2, dim> inverse = invert(jacobian);
            for (auto &particle : particles)
              {
                const Point<dim> xi(inverse *
                                    (particle.get_location() - origin));
                if (!GeometryInfo<dim>::is_inside_unit_cell(xi))
                  {
                    inside = false;
                    break;
                  }
                particle.set_reference_location(xi);
              }
          }
        else
          {
            real_locations.clear();
            for (const auto &particle : particles)
              real_locations.push_back(particle.get_location());
            reference_locations.resize(real_locations.size());
            grid.get_mapping().transform_points_real_to_unit_cell(
              cell, real_locations, reference_locations);
            auto particle = particles.begin();
            for (const auto &xi : reference_locations)
              {
                // deal.II marks a point it could not map by infinity.
                if (!(xi[0] < std::numeric_limits<double>::infinity()) ||
                    !GeometryInfo<dim>::is_inside_unit_cell(xi))
                  {
                    inside = false;
                    break;
                  }
                particle->set_reference_location(xi);
                ++particle;
              }
          }
      }
    return Utilities::MPI::min(inside ? 1 : 0, grid.get_communicator()) == 1;
  }



  template <int dim>
  types::particle_index
  MaterialPointSet<dim>::sort_into_cells()
  {
    const types::particle_index before = particle_handler.n_global_particles();
    particle_handler.sort_particles_into_subdomains_and_cells();
    return before - particle_handler.n_global_particles();
  }



  template <int dim>
  void
  MaterialPointSet<dim>::sort_into_cells_without_loss(const double moved)
  {
    const auto   lost      = sort_into_cells();
    const double cell_size = grid.min_cell_size();
    if (lost > 0 &&
        dealii::Utilities::MPI::n_mpi_processes(grid.get_communicator()) > 1 &&
        moved >= cell_size)
      {
        std::ostringstream message;
        message << lost
                << " material points were lost: in a parallel run a point "
                   "may move at most one cell per load step, and in this "
                   "step a point moved "
                << std::setprecision(3) << moved / cell_size
                << " cells. Use more load steps.";
        AssertThrow(false, ExcMessage(message.str()));
      }
    AssertThrow(lost == 0,
                ExcMessage(std::to_string(lost) +
                           " material points left the background grid. "
                           "Enlarge the grid around the body."));
  }



  template <int dim>
  const Quadrature<dim> &
  MaterialPointSet<dim>::placement_rule() const
  {
    return last_rule;
  }



  template <int dim>
  unsigned int
  MaterialPointSet<dim>::n_surface_loads() const
  {
    return offsets.surface_load == numbers::invalid_unsigned_int ?
             0 :
             layout.n_components("surface_load") / (2 * dim + 1);
  }



  template <int dim>
  unsigned int
  MaterialPointSet<dim>::n_state_components() const
  {
    return layout.size() - offsets.state;
  }



  template <int dim>
  PointState<dim>
  MaterialPointSet<dim>::point_state(
    const Particles::ParticleAccessor<dim> &particle) const
  {
    return read_point_state(particle.get_properties().data(),
                            offsets,
                            n_state_components(),
                            particle.get_location());
  }



  template <int dim>
  Point<dim>
  MaterialPointSet<dim>::initial_location(
    const Particles::ParticleAccessor<dim> &particle) const
  {
    Point<dim> x = particle.get_location();
    for (unsigned int d = 0; d < dim; ++d)
      x[d] -= particle.get_properties()[offsets.displacement + d];
    return x;
  }



  template <int dim>
  PropertyLayout
  MaterialPointSet<dim>::output_layout() const
  {
    PropertyLayout output;
    for (const auto &field : model.output_fields())
      output.add(field.name, field.n_components, PropertyLayout::Kind::scalar);
    return output;
  }



  template <int dim>
  void
  MaterialPointSet<dim>::compute_output_fields(
    const Particles::ParticleAccessor<dim> &particle,
    ArrayView<double>                       values) const
  {
    model.compute_output_fields(point_state(particle), values);
  }



  template <int dim>
  Particles::ParticleHandler<dim> &
  MaterialPointSet<dim>::get_particle_handler()
  {
    return particle_handler;
  }



  template <int dim>
  const Particles::ParticleHandler<dim> &
  MaterialPointSet<dim>::get_particle_handler() const
  {
    return particle_handler;
  }



  template <int dim>
  const PropertyLayout &
  MaterialPointSet<dim>::get_layout() const
  {
    return layout;
  }



  template <int dim>
  const typename MaterialPointSet<dim>::Offsets &
  MaterialPointSet<dim>::get_offsets() const
  {
    return offsets;
  }



  template <int dim>
  const ConstitutiveModel<dim> &
  MaterialPointSet<dim>::get_model() const
  {
    return model;
  }



  template <int dim>
  const Formulation &
  MaterialPointSet<dim>::get_formulation() const
  {
    return formulation;
  }



  template <int dim>
  types::particle_index
  MaterialPointSet<dim>::n_global_points() const
  {
    return particle_handler.n_global_particles();
  }



  template <int dim>
  double
  MaterialPointSet<dim>::total_volume() const
  {
    double volume = 0;
    for (const auto &particle : particle_handler)
      volume += particle.get_properties()[offsets.volume];
    return Utilities::MPI::sum(volume, grid.get_communicator());
  }



  template class MaterialPointSet<2>;
  template class MaterialPointSet<3>;
} // namespace qsmpm
