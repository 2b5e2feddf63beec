// Helpers for tests that set a problem up from .prm text, as a user's
// parameter file would, and read the CSV files a run writes.
#ifndef qsmpm_tests_prm_text_h
#define qsmpm_tests_prm_text_h

#include <fstream>
#include <qsmpm/core/quasi_static_problem.h>
#include <sstream>
#include <string>
#include <vector>

namespace qsmpm_tests
{
  /// Parse @p text (a whole .prm file, with its "Dimension" entry) and
  /// initialize @p problem from it, its progress output silenced.
  template <int dim>
  void
  initialize_from_text(qsmpm::QuasiStaticProblem<dim> &problem,
                       const std::string              &text)
  {
    dealii::ParameterHandler prm;
    prm.declare_entry("Dimension",
                      std::to_string(dim),
                      dealii::Patterns::Integer(2, 3),
                      "");
    qsmpm::QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(text);
    problem.pcout().set_condition(false);
    problem.initialize(prm);
  }

  /// The rows of a CSV file of numbers (its header line skipped).
  inline std::vector<std::vector<double>>
  read_csv(const std::string &filename)
  {
    std::vector<std::vector<double>> rows;
    std::ifstream                    file(filename);
    std::string                      line;
    std::getline(file, line);
    while (std::getline(file, line))
      {
        std::vector<double> row;
        std::istringstream  fields(line);
        std::string         field;
        while (std::getline(fields, field, ','))
          row.push_back(std::stod(field));
        rows.push_back(row);
      }
    return rows;
  }
} // namespace qsmpm_tests

#endif
