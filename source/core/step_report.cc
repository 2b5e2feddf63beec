#include <iomanip>
#include <qsmpm/core/step_report.h>
#include <sstream>

namespace qsmpm
{
  std::string
  StepReport::progress_line(const double lost) const
  {
    std::ostringstream line;
    line << "step " << std::setw(5) << step << "  t = " << std::setw(10)
         << std::setprecision(5) << load_factor << "  newton " << std::setw(2)
         << newton.newton_iterations << "  gmres " << std::setw(4)
         << newton.linear_iterations << "  |R| " << std::scientific
         << std::setprecision(2) << newton.initial_residual << " -> "
         << newton.final_residual << "  lost " << std::setprecision(1) << lost
         << std::defaultfloat << "  " << std::fixed << std::setprecision(3)
         << wall_time << " s";
    if (coupling_iterations > 0)
      line << "  coupling " << coupling_iterations;
    if (cut_backs > 0)
      line << "  cut-backs " << cut_backs;
    if (newton.line_search_steps > 0)
      line << "  line search " << newton.line_search_steps;
    if (newton.stagnated)
      line << "  stagnated at 1e-6 of the forces";
    if (null_modes_held > 0)
      line << "  held modes " << null_modes_held;
    return line.str();
  }
} // namespace qsmpm
