// Helpers for tests that set a problem up from .prm text, as a user's
// parameter file would, and read the CSV files a run writes.
#ifndef qsmpm_tests_prm_text_h
#define qsmpm_tests_prm_text_h

#include <algorithm>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <map>
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

  /// Set a problem up from @p text, run it and destroy it; then wait for
  /// all ranks: rank 0 writes the CSV files (reactions.csv, probes.csv),
  /// and the others may read them only once it has closed them.
  template <int dim>
  void
  run_from_text(const std::string &text)
  {
    {
      qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
      initialize_from_text(problem, text);
      problem.run();
    }
    const int ierr = MPI_Barrier(MPI_COMM_WORLD);
    AssertThrowMPI(ierr);
  }

  /// max |u_a - u_b| / max |u_a| over the points of two runs' displacement
  /// maps (point_displacements()).
  template <int dim>
  double
  max_relative_difference(
    const std::map<dealii::types::particle_index, dealii::Tensor<1, dim>> &a,
    const std::map<dealii::types::particle_index, dealii::Tensor<1, dim>> &b)
  {
    double largest = 0., difference = 0.;
    for (const auto &[id, u] : a)
      {
        largest    = std::max(largest, u.norm());
        difference = std::max(difference, (u - b.at(id)).norm());
      }
    return difference / largest;
  }

  /// The displacements of all points (of all ranks of @p communicator,
  /// the problem's) by particle id.
  template <int dim>
  std::map<dealii::types::particle_index, dealii::Tensor<1, dim>>
  point_displacements(const qsmpm::QuasiStaticProblem<dim> &problem,
                      const MPI_Comm communicator = MPI_COMM_WORLD)
  {
    const auto         &offsets = problem.points().get_offsets();
    std::vector<double> local;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        local.push_back(particle.get_id());
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(particle.get_properties()[offsets.displacement + d]);
      }
    std::map<dealii::types::particle_index, dealii::Tensor<1, dim>> u;
    for (const auto &part :
         dealii::Utilities::MPI::all_gather(communicator, local))
      for (unsigned int i = 0; i + dim + 1 <= part.size(); i += dim + 1)
        for (unsigned int d = 0; d < dim; ++d)
          u[static_cast<dealii::types::particle_index>(part[i])][d] =
            part[i + 1 + d];
    return u;
  }

  /// A strip 1 x 1 of 32 x 32 cells on rollers, a traction 1e3 t on the
  /// left half of its top, 5 load steps, Newton tolerance 1e-9, of the
  /// @p model (E = 1e6, nu = 0.3; von Mises with yield stress 600, which
  /// yields under the loaded half's edge), with the entries
  /// @p material_points and @p solver (lines of "set ...") in those
  /// subsections, and no output but in @p directory.
  inline std::string
  yielding_strip_prm(const std::string &model,
                     const std::string &material_points,
                     const std::string &solver,
                     const std::string &directory)
  {
    std::ostringstream prm;
    prm << "set Dimension = 2\n"
        << "subsection Geometry\n  set Subdivisions = 32,32\nend\n"
        << "subsection Material points\n"
        << material_points << "end\n"
        << "subsection Material\n  set Model = " << model << "\n"
        << "  subsection " << model << "\n"
        << "    set Young's modulus = 1e6\n"
        << "    set Poisson's ratio = 0.3\n";
    if (model == "von Mises")
      prm << "    set Yield stress = 600\n";
    prm << "  end\nend\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
        << "  set Traction boundaries = 3\n"
        << "  subsection Traction\n"
        << "    set Function expression = 0; -1e3*t*(x<0.5 ? 1 : 0)\n"
        << "  end\nend\n"
        << "subsection Load stepping\n  set Number of steps = 5\nend\n"
        << "subsection Nonlinear solver\n  set Tolerance = 1e-9\n"
        << solver << "end\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = " << directory << "\nend\n";
    return prm.str();
  }

  /// What a run from .prm text gives: the points' displacements by
  /// particle id and the Newton and GMRES iterations of all its steps.
  template <int dim>
  struct RecordedRun
  {
    std::map<dealii::types::particle_index, dealii::Tensor<1, dim>>
                 displacement;
    unsigned int newton = 0, gmres = 0;

    double
    gmres_per_newton() const
    {
      return static_cast<double>(gmres) / newton;
    }
  };

  /// Set a problem up from @p text, run it and record what it gives.
  template <int dim>
  RecordedRun<dim>
  run_and_record(const std::string &text)
  {
    qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, text);
    RecordedRun<dim> result;
    problem.set_step_callback(
      [&](const typename qsmpm::QuasiStaticProblem<dim>::StepReport &report) {
        result.newton += report.newton.newton_iterations;
        result.gmres += report.newton.linear_iterations;
        return true;
      });
    problem.run();
    result.displacement = point_displacements(problem);
    return result;
  }

  /// max |u_a - u_b| / max |u_a| over the points of two recorded runs.
  template <int dim>
  double
  max_relative_difference(const RecordedRun<dim> &a, const RecordedRun<dim> &b)
  {
    return max_relative_difference(a.displacement, b.displacement);
  }

  /// The shipped example file examples/@p name (e.g.
  /// "consolidation/terzaghi.prm") with the replacements @p edits (each: a
  /// text of the file, which must be there, and what replaces its first
  /// occurrence), and an Output subsection that writes into @p directory
  /// and no fields.
  inline std::string
  edited_example(const std::string                                      &name,
                 const std::vector<std::pair<std::string, std::string>> &edits,
                 const std::string &directory)
  {
    std::ifstream file(std::string(QSMPM_EXAMPLES_DIR) + "/" + name);
    AssertThrow(file, dealii::ExcMessage("cannot read " + name));
    std::stringstream buffer;
    buffer << file.rdbuf();
    std::string text = buffer.str();
    for (const auto &[from, to] : edits)
      {
        const auto at = text.find(from);
        AssertThrow(at != std::string::npos,
                    dealii::ExcMessage(name + " has no <" + from + ">"));
        text.replace(at, from.size(), to);
      }
    return text + "subsection Output\n  set Directory = " + directory +
           "\n  set Interval = 0\nend\n";
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

  /// The index of the column @p name in the header line of a CSV file
  /// (throws if there is none).
  inline unsigned int
  csv_column(const std::string &filename, const std::string &name)
  {
    std::ifstream file(filename);
    std::string   line, field;
    std::getline(file, line);
    std::istringstream fields(line);
    for (unsigned int i = 0; std::getline(fields, field, ','); ++i)
      if (field == name)
        return i;
    throw std::runtime_error(filename + " has no column " + name);
  }

  /// The column @p name of a CSV file, row by row.
  inline std::vector<double>
  csv_values(const std::string &filename, const std::string &name)
  {
    const unsigned int  c = csv_column(filename, name);
    std::vector<double> values;
    for (const auto &row : read_csv(filename))
      values.push_back(row[c]);
    return values;
  }

  /// The edits (for edited_example()) that replace an isotropic elastic
  /// material's entries "set Young's modulus = @p E" and "set Poisson's
  /// ratio = @p nu" by those of a nearly incompressible solid of the same
  /// shear modulus: nu_u and E_u = 2 G (1 + nu_u). An elastic skeleton
  /// with incompressible pore water responds so when loaded undrained.
  inline std::vector<std::pair<std::string, std::string>>
  same_shear_modulus(const std::string &E,
                     const std::string &nu,
                     const double       nu_u)
  {
    const double G = std::stod(E) / (2. * (1. + std::stod(nu)));
    return {{"set Young's modulus = " + E,
             "set Young's modulus = " + std::to_string(2. * G * (1. + nu_u))},
            {"set Poisson's ratio = " + nu,
             "set Poisson's ratio = " + std::to_string(nu_u)}};
  }
} // namespace qsmpm_tests

#endif
