#ifndef qsmpm_core_step_report_h
#define qsmpm_core_step_report_h

#include <qsmpm/solvers/newton_krylov.h>
#include <string>

namespace qsmpm
{
  /**
   * What happened in one accepted load step of QuasiStaticProblem::run()
   * (QuasiStaticProblem::StepReport).
   */
  struct StepReport
  {
    unsigned int step;
    double       load_factor;
    unsigned int cut_backs;
    NewtonReport newton;
    double       wall_time;
    /// Fixed-stress iterations of a step with a pore fluid (0: none).
    unsigned int coupling_iterations = 0;
    /// Motions of pairs of dofs without stiffness held in the step
    /// (NullModeHold; 0: none).
    unsigned int null_modes_held = 0;

    /**
     * The progress line of the step: load factor, Newton and GMRES
     * iterations, the residual norms, the fraction of the load @p lost
     * (EquilibriumAudit::Result::imbalance()), the wall time and any
     * cut-backs, line-search halvings and held null modes.
     */
    std::string
    progress_line(const double lost) const;
  };
} // namespace qsmpm

#endif
