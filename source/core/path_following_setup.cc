#include <cmath>
#include <deal.II/base/mpi.h>
#include <qsmpm/core/path_following_setup.h>

namespace qsmpm
{
  template <int dim>
  void
  PathFollowingSetup<dim>::make_gauge(const LoadStepper &stepper)
  {
    if (stepper.control() == LoadStepper::Control::opening)
      gauge = std::make_unique<OpeningGauge<dim>>(
        stepper.get_parameters().opening_gauge);
  }



  template <int dim>
  void
  PathFollowingSetup<dim>::check_problem(const LoadStepper             &stepper,
                                         const BoundaryDescriptor<dim> &bcs,
                                         const ConstitutiveModel<dim>  &model)
  {
    const std::string control = LoadStepper::to_string(stepper.control());
    AssertThrow(!bcs.has_loads() && !bcs.has_macroscopic_gradient(),
                ExcMessage("Load stepping: Control = " + control +
                           " needs a problem loaded by prescribed "
                           "displacements only (no body force, traction, "
                           "point load, rigid body or macroscopic "
                           "displacement gradient)."));
    AssertThrow(stepper.control() != LoadStepper::Control::dissipation ||
                  model.computes_dissipation(),
                ExcMessage("Load stepping: Control = dissipation needs a "
                           "material model that computes its dissipation; <" +
                           model.name() + "> does not."));
  }



  template <int dim>
  void
  PathFollowingSetup<dim>::make_direction(
    const LoadStepper                                      &stepper,
    const StepConstraints                                  &unit,
    const std::function<void(AffineConstraints<double> &)> &make_doubled,
    const IndexSet                                         &owned,
    const MPI_Comm                                          communicator,
    VectorType                                             &g)
  {
    const std::string control = LoadStepper::to_string(stepper.control());
    g                         = 0.;
    unit.distribute(g);
    AssertThrow(g.linfty_norm() > 0.,
                ExcMessage("Load stepping: Control = " + control +
                           " needs a displacement condition that changes "
                           "with the load factor; none does."));
    if (proportionality_checked)
      return;
    // The increments of a step are Delta lambda g only if the prescribed
    // displacements are t g; with another dependence on t the step would
    // be wrong without any sign of it.
    AffineConstraints<double> doubled;
    make_doubled(doubled);
    double mismatch = 0.;
    for (const auto i : owned)
      if (doubled.is_constrained(i))
        mismatch = std::max(mismatch,
                            std::abs(doubled.get_inhomogeneity(i) - 2. * g[i]));
    mismatch = dealii::Utilities::MPI::max(mismatch, communicator);
    AssertThrow(mismatch <= 1e-10 * g.linfty_norm(),
                ExcMessage("Load stepping: Control = " + control +
                           " needs prescribed displacements "
                           "proportional to the load factor t (u = t "
                           "g(x))."));
    proportionality_checked = true;
  }



  template <int dim>
  typename PathFollowingSetup<dim>::Solver::Constraint
  PathFollowingSetup<dim>::constraint(const LoadStepper     &stepper,
                                      const ShapeCache<dim> &cache,
                                      const unsigned int     displacement,
                                      const double           cell_size,
                                      const MPI_Comm         communicator,
                                      const VectorType      &layout)
  {
    typename Solver::Constraint constraint{0., 0., 0., 0.};
    constraint.value = stepper.constraint_target();
    if (stepper.control() == LoadStepper::Control::opening)
      {
        if (!gauge)
          make_gauge(stepper);
        w.reinit(layout);
        gauge->make_vector(cache, displacement, cell_size, communicator, w);
        constraint.gauge        = &w;
        constraint.gauge_weight = 1.;
      }
    else
      constraint.dissipation_weight = 1.;
    return constraint;
  }



  template <int dim>
  typename PathFollowingSetup<dim>::Solver::ForceGuard
  PathFollowingSetup<dim>::force_guard(const LoadStepper &stepper)
  {
    const double peak_force = stepper.peak_force();
    return {peak_force > 0. ? 1. : (peak_force < 0. ? -1. : 0.),
            1e-3 * std::abs(peak_force)};
  }



  template class PathFollowingSetup<2>;
  template class PathFollowingSetup<3>;
} // namespace qsmpm
