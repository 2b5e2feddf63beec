#ifndef qsmpm_io_run_state_h
#define qsmpm_io_run_state_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <functional>
#include <qsmpm/core/step_report.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/io/output_writer.h>
#include <qsmpm/loading/load_stepper.h>
#include <qsmpm/particles/material_point_set.h>
#include <string>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * What of a run carries over from one load step to the next besides the
   * grid and the points: the reactions of the last step, the largest scale
   * of the loads so far, and the reports of the steps (summaries of a
   * resumed run count all steps). save() and load() turn it, with the load
   * stepper (load factor, increment, step count), the output writer's
   * records and a caller's own text, into the text a Checkpoint stores and
   * back. Doubles are written with max_digits10 digits, which reads back
   * exactly. write_checkpoint() and read_checkpoint() write and read the
   * whole checkpoint, grid and points included; restore() then restores
   * the state of the run that was read.
   */
  template <int dim>
  class RunState
  {
  public:
    /// Reaction forces of the last accepted step, per displacement
    /// condition.
    std::vector<Tensor<1, dim>> reactions;
    /// The largest scale of the loads of the steps so far (see
    /// EquilibriumAudit::evaluate()).
    double load_scale = 0.;
    /// The largest force the body has carried in the steps so far: the
    /// applied load, a support's reaction or a rigid body's contact force
    /// (unlike load_scale, without the steps' first residuals).
    double force_scale = 0.;
    /// The displacement of each rigid plate along its normal so far
    /// (BoundaryDescriptor::add_rigid_plate(), in that order).
    std::vector<double> plate_displacements;
    /// The displacement of each rigid body along its load direction so
    /// far (0 for the bodies not driven by a force; add_rigid_body()
    /// order).
    std::vector<double> body_displacements;
    /// With a pore fluid: the largest integral of the excess pore pressure
    /// over the body in the steps so far (QuasiStaticProblem::
    /// degree_of_consolidation()).
    double peak_excess_pressure = 0.;
    /// Reports of the accepted steps.
    std::vector<StepReport> reports;

    /**
     * The text of a checkpoint: the state of @p stepper, this state, the
     * records of @p writer and @p user, the caller's own text.
     */
    std::string
    save(const LoadStepper       &stepper,
         const OutputWriter<dim> &writer,
         const std::string       &user) const;

    /**
     * Read a text of save() into this state, @p stepper and @p writer, and
     * return the caller's text. Throws with a message if the text is
     * incomplete or the stepper's state is not that of the checkpoint's
     * @p step.
     */
    std::string
    load(const std::string &text,
         const unsigned int step,
         LoadStepper       &stepper,
         OutputWriter<dim> &writer);

    /**
     * Write the checkpoint of the step of @p stepper into @p directory
     * (collective over @p communicator): @p grid, @p points and the text of
     * save() with the caller's text @p user (called on rank 0 only, if
     * set).
     */
    void
    write_checkpoint(const std::string                  &directory,
                     const MPI_Comm                      communicator,
                     const LoadStepper                  &stepper,
                     BackgroundGrid<dim>                &grid,
                     MaterialPointSet<dim>              &points,
                     const OutputWriter<dim>            &writer,
                     const std::function<std::string()> &user) const;

    /**
     * Read the newest complete checkpoint in @p directory into @p grid and
     * @p points (see Checkpoint::read()) and keep its text for restore();
     * return its step. Throws with a message if there is none.
     */
    unsigned int
    read_checkpoint(const std::string     &directory,
                    const MPI_Comm         communicator,
                    BackgroundGrid<dim>   &grid,
                    MaterialPointSet<dim> &points);

    /// Whether read_checkpoint() has read a state that restore() has not
    /// restored yet.
    bool
    resuming() const;

    /// load() the text that read_checkpoint() read; returns the caller's
    /// text.
    std::string
    restore(LoadStepper &stepper, OutputWriter<dim> &writer);

  private:
    bool         resumed      = false;
    unsigned int resumed_step = 0;
    std::string  resume_text;
  };
} // namespace qsmpm

#endif
