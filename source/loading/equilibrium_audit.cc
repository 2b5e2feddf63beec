#include <algorithm>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <qsmpm/loading/equilibrium_audit.h>
#include <sstream>

namespace qsmpm
{
  template <int dim>
  void
  EquilibriumAudit<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Equilibrium check");
    {
      prm.add_parameter(
        "Lost load tolerance",
        tolerance,
        "After every converged step the applied load (tractions, body "
        "forces, point loads) is balanced against the reactions of the "
        "displacement conditions; the part they do not carry, relative to "
        "the largest of the applied load and the reactions, may be at most "
        "this. Lost load goes to nodes held for lack of material or "
        "stiffness, or to nodes without material that a traction acts on, "
        "and each cause is named. It also bounds what Newton's stopping "
        "test may leave unbalanced: at most this times the largest force "
        "the body carried in the steps before (applied load, reaction or "
        "a rigid body's contact force), however large the step's first "
        "residual (a rigid body's penalty forces on the points it moves "
        "into).",
        Patterns::Double(0.));
      prm.add_parameter(
        "Stop on lost load",
        stop_on_lost_load,
        "true: a step that loses more load than the tolerance stops the run "
        "with a message naming the cause; the last converged state is "
        "written. false: a warning, once, and the run goes on.",
        Patterns::Bool());
    }
    prm.leave_subsection();
  }



  template <int dim>
  double
  EquilibriumAudit<dim>::Result::imbalance() const
  {
    return scale > 0. ? (applied + supports).norm() / scale : 0.;
  }



  template <int dim>
  double
  EquilibriumAudit<dim>::Result::structural_loss() const
  {
    return scale > 0. ? (applied + supports + free_residual).norm() / scale :
                        0.;
  }



  template <int dim>
  double
  EquilibriumAudit<dim>::Result::solver_residual() const
  {
    return scale > 0. ? free_residual.norm() / scale : 0.;
  }



  template <int dim>
  std::string
  EquilibriumAudit<dim>::Result::lost_load(const double t_new,
                                           const double tolerance,
                                           const double newton_tolerance) const
  {
    const double residual_tolerance =
      std::max(tolerance, 10. * newton_tolerance);
    if (!(structural_loss() > tolerance ||
          solver_residual() > residual_tolerance))
      return "";
    std::ostringstream message;
    // Short enough that Utils::error_message() (which cuts a message of
    // more than 600 characters in its middle) keeps it whole, with the
    // run's note on its last converged state after it.
    message << "the converged step to t = " << t_new << " lost "
            << std::setprecision(3) << 100. * imbalance()
            << " % of the load (Equilibrium check/Lost load tolerance = "
            << tolerance << "): " << causes(tolerance, residual_tolerance)
            << '.';
    return message.str();
  }



  template <int dim>
  std::string
  EquilibriumAudit<dim>::Result::causes(const double tolerance,
                                        const double residual_tolerance) const
  {
    const double       limit = tolerance * scale;
    std::ostringstream text;
    text << std::setprecision(3);
    const auto share = [&](const Tensor<1, dim> &f) {
      return 100. * f.norm() / scale;
    };
    const auto add = [&](const std::string &words) {
      text << (text.tellp() > 0 ? "; " : "") << words;
    };
    if (held_load.norm() > limit)
      {
        std::ostringstream words;
        words << std::setprecision(3) << share(held_load)
              << " % of the load acts on nodes without material (a traction "
                 "on a grid face the body has left?)";
        add(words.str());
      }
    if ((held - held_load).norm() > limit)
      {
        std::ostringstream words;
        words << std::setprecision(3) << share(held - held_load)
              << " % is carried by the nodes held fixed for lack of material "
                 "or stiffness (Material points/Minimum nodal volume, "
                 "Minimum nodal stiffness)";
        add(words.str());
      }
    if (internal.norm() > limit)
      {
        std::ostringstream words;
        words << std::setprecision(3) << share(internal)
              << " % is the sum of the internal forces, which vanishes where "
                 "the points' weights are a partition of unity on the grid "
                 "(an internal error)";
        add(words.str());
      }
    if (free_residual.norm() > residual_tolerance * scale)
      {
        std::ostringstream words;
        words << std::setprecision(3) << share(free_residual)
              << " % is left unbalanced by Newton's stopping test "
                 "(Nonlinear solver/Residual floor too large for the units "
                 "of the forces?)";
        add(words.str());
      }
    if (text.tellp() == 0)
      add("no single cause exceeds the tolerance");
    return text.str();
  }



  template <int dim>
  void
  EquilibriumAudit<dim>::set_axisymmetric(const bool value)
  {
    axisymmetric = value;
  }



  template <int dim>
  typename EquilibriumAudit<dim>::Result
  EquilibriumAudit<dim>::evaluate(
    const BackgroundGrid<dim>           &grid,
    const DisplacementConstraints<dim>  &conditions,
    const IndexSet                      &held,
    const TrilinosWrappers::MPI::Vector &R,
    const TrilinosWrappers::MPI::Vector &f_ext,
    const double                         reference_scale)
  {
    const IndexSet &owned = grid.locally_owned_dofs();
    if (component.size() != owned.n_elements() || !(component_owned == owned))
      {
        component.assign(owned.n_elements(), 0);
        const FESystem<dim>                 &fe = grid.get_fe();
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (owned.is_element(dofs[i]))
                  component[owned.index_within_set(dofs[i])] =
                    fe.system_to_component_index(i).first % dim;
            }
        component_owned = owned;
      }

    // What each owned degree of freedom is: 0 free, 1 a support of a
    // displacement condition, 2 held.
    std::vector<unsigned char> kind(owned.n_elements(), 0);
    Result                     result;
    result.reactions.resize(conditions.n_conditions());
    for (unsigned int k = 0; k < conditions.n_conditions(); ++k)
      for (const auto &dof : conditions.prescribed_dofs(k))
        {
          result.reactions[k][dof.component] -= R(dof.index);
          kind[owned.index_within_set(dof.index)] = 1;
        }
    for (const auto dof : held)
      if (owned.is_element(dof) && kind[owned.index_within_set(dof)] == 0)
        kind[owned.index_within_set(dof)] = 2;

    double magnitudes = 0.;
    for (unsigned int i = 0; i < kind.size(); ++i)
      {
        const types::global_dof_index dof = owned.nth_index_in_set(i);
        const unsigned int            c   = component[i];
        const double                  r = R(dof), f = f_ext(dof);
        magnitudes += std::abs(r) + std::abs(f);
        result.applied[c] += f;
        if (kind[i] == 1)
          result.supports[c] -= r;
        else if (kind[i] == 2)
          {
            result.held[c] -= r;
            result.held_load[c] -= f;
            if (r != 0.)
              ++result.n_held_loaded;
          }
        else
          result.free_residual[c] -= r;
      }

    const MPI_Comm communicator = grid.get_communicator();
    for (auto &reaction : result.reactions)
      reaction = dealii::Utilities::MPI::sum(reaction, communicator);
    for (Tensor<1, dim> *term : {&result.applied,
                                 &result.supports,
                                 &result.held,
                                 &result.held_load,
                                 &result.free_residual})
      *term = dealii::Utilities::MPI::sum(*term, communicator);
    result.n_held_loaded =
      dealii::Utilities::MPI::sum(result.n_held_loaded, communicator);
    // C + H + F = -sum R = -A + sum f_int: the coupled (periodic) rows are
    // zero, their forces added to their masters' rows.
    result.internal =
      result.applied + result.supports + result.held + result.free_residual;
    if (axisymmetric)
      for (Tensor<1, dim> *term : {&result.applied,
                                   &result.supports,
                                   &result.held,
                                   &result.held_load,
                                   &result.internal})
        (*term)[0] = 0.;

    // Supports whose forces balance each other (a body whose every node
    // is prescribed) have a resultant of round-off size: measured against
    // it, its round-off would be a loss of 100 %. The sum of the nodal
    // forces' magnitudes bounds that round-off.
    magnitudes = dealii::Utilities::MPI::sum(magnitudes, communicator);
    result.scale =
      std::max({reference_scale, result.applied.norm(), 1e-6 * magnitudes});
    for (const auto &reaction : result.reactions)
      result.scale = std::max(result.scale, reaction.norm());
    return result;
  }



  template class EquilibriumAudit<2>;
  template class EquilibriumAudit<3>;
} // namespace qsmpm
