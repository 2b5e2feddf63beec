#include <filesystem>
#include <iomanip>
#include <limits>
#include <qsmpm/io/checkpoint.h>
#include <qsmpm/io/run_state.h>
#include <sstream>

namespace qsmpm
{
  template <int dim>
  std::string
  RunState<dim>::save(const LoadStepper       &stepper,
                      const OutputWriter<dim> &writer,
                      const std::string       &user) const
  {
    std::ostringstream state;
    state << std::setprecision(std::numeric_limits<double>::max_digits10);
    state << "stepper ";
    stepper.save(state);
    state << "\nreactions " << reactions.size();
    for (const auto &reaction : reactions)
      for (unsigned int d = 0; d < dim; ++d)
        state << ' ' << reaction[d];
    state << "\nload_scale " << load_scale;
    state << "\nforce_scale " << force_scale;
    state << "\nplates " << plate_displacements.size();
    for (const double u : plate_displacements)
      state << ' ' << u;
    state << "\nbodies " << body_displacements.size();
    for (const double u : body_displacements)
      state << ' ' << u;
    state << "\nconsolidation " << peak_excess_pressure;
    state << "\nreports " << reports.size() << '\n';
    for (const auto &r : reports)
      state << r.step << ' ' << r.load_factor << ' ' << r.cut_backs << ' '
            << r.newton.converged << ' ' << r.newton.newton_iterations << ' '
            << r.newton.linear_iterations << ' '
            << r.newton.inexact_linear_solves << ' '
            << r.newton.line_search_steps << ' ' << r.newton.initial_residual
            << ' ' << r.newton.final_residual << ' ' << r.wall_time << '\n';
    state << "output ";
    writer.save(state);
    state << "user " << user.size() << '\n' << user;
    return state.str();
  }



  template <int dim>
  std::string
  RunState<dim>::load(const std::string &text,
                      const unsigned int step,
                      LoadStepper       &stepper,
                      OutputWriter<dim> &writer)
  {
    std::istringstream in(text);
    std::string        keyword;
    const auto         expect = [&](const std::string &word) {
      in >> keyword;
      AssertThrow(in && keyword == word,
                  ExcMessage("Cannot resume: the checkpoint's state has no <" +
                             word + "> entry."));
    };
    expect("stepper");
    stepper.load(in);
    AssertThrow(stepper.step() == step,
                ExcMessage("Cannot resume: the checkpoint's load stepping "
                           "state does not belong to its step."));
    expect("reactions");
    std::size_t n = 0;
    in >> n;
    reactions.assign(n, Tensor<1, dim>());
    for (auto &reaction : reactions)
      for (unsigned int d = 0; d < dim; ++d)
        in >> reaction[d];
    expect("load_scale");
    in >> load_scale;
    // A checkpoint of an earlier version has no force scale: Newton's
    // ceiling (QuasiStaticProblem::solver_parameters()) then starts again
    // from the first step resumed.
    const auto before_force_scale = in.tellg();
    in >> keyword;
    force_scale = 0.;
    if (keyword == "force_scale")
      in >> force_scale;
    else
      in.seekg(before_force_scale);
    expect("plates");
    in >> n;
    plate_displacements.assign(n, 0.);
    for (double &u : plate_displacements)
      in >> u;
    expect("bodies");
    in >> n;
    body_displacements.assign(n, 0.);
    for (double &u : body_displacements)
      in >> u;
    expect("consolidation");
    in >> peak_excess_pressure;
    expect("reports");
    in >> n;
    reports.assign(n, StepReport());
    for (auto &r : reports)
      in >> r.step >> r.load_factor >> r.cut_backs >> r.newton.converged >>
        r.newton.newton_iterations >> r.newton.linear_iterations >>
        r.newton.inexact_linear_solves >> r.newton.line_search_steps >>
        r.newton.initial_residual >> r.newton.final_residual >> r.wall_time;
    expect("output");
    writer.resume(in, step);
    expect("user");
    in >> n;
    in.get();
    std::string user(n, '\0');
    in.read(user.data(), n);
    AssertThrow(in,
                ExcMessage("Cannot resume: the checkpoint's state is "
                           "incomplete."));
    return user;
  }



  template <int dim>
  void
  RunState<dim>::write_checkpoint(
    const std::string                  &directory,
    const MPI_Comm                      communicator,
    const LoadStepper                  &stepper,
    BackgroundGrid<dim>                &grid,
    MaterialPointSet<dim>              &points,
    const OutputWriter<dim>            &writer,
    const std::function<std::string()> &user) const
  {
    const std::string state =
      dealii::Utilities::MPI::this_mpi_process(communicator) == 0 ?
        save(stepper, writer, user ? user() : "") :
        "";
    Checkpoint<dim>(directory, communicator)
      .write(stepper.step(), grid, points, state);
  }



  template <int dim>
  unsigned int
  RunState<dim>::read_checkpoint(const std::string     &directory,
                                 const MPI_Comm         communicator,
                                 BackgroundGrid<dim>   &grid,
                                 MaterialPointSet<dim> &points)
  {
    const Checkpoint<dim> checkpoint(directory, communicator);
    const std::string     path = checkpoint.newest();
    AssertThrow(!path.empty(),
                ExcMessage("Cannot resume: there is no complete checkpoint "
                           "(checkpoint-<step>) in the output directory <" +
                           directory +
                           ">; write them with Output/Checkpoint interval."));
    resume_text = checkpoint.read(path, grid, points);
    resumed     = true;
    resumed_step =
      Checkpoint<dim>::step_of(std::filesystem::path(path).filename().string());
    return resumed_step;
  }



  template <int dim>
  bool
  RunState<dim>::resuming() const
  {
    return resumed;
  }



  template <int dim>
  std::string
  RunState<dim>::restore(LoadStepper &stepper, OutputWriter<dim> &writer)
  {
    const std::string user = load(resume_text, resumed_step, stepper, writer);
    resumed                = false;
    return user;
  }



  template class RunState<2>;
  template class RunState<3>;
} // namespace qsmpm
