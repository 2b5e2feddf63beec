#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <qsmpm/io/checkpoint.h>
#include <sstream>
#include <vector>

namespace qsmpm
{
  namespace
  {
    const std::string prefix     = "checkpoint-";
    const std::string state_file = "state.txt";
    const std::string header     = "qsmpm checkpoint 1";

    // Run @p action on rank 0 only and throw its error on every rank, so
    // that no rank waits forever in the next collective call.
    void
    on_rank_zero(const MPI_Comm                      communicator,
                 const std::function<std::string()> &action)
    {
      std::string error;
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          try
            {
              error = action();
            }
          catch (const std::exception &exc)
            {
              error = exc.what();
            }
        }
      error = Utilities::MPI::broadcast(communicator, error, 0);
      AssertThrow(error.empty(), ExcMessage(error));
    }
  } // namespace



  template <int dim>
  Checkpoint<dim>::Checkpoint(const std::string &directory,
                              const MPI_Comm     communicator)
    : directory(directory)
    , communicator(communicator)
  {
  }



  // What a checkpoint must share with the run that reads it: the coarse
  // grid (p4est refuses another one, and a grid of the same number of cells
  // but another size would silently move every point) and the points'
  // property layout (the bytes attached to each cell are read back as this
  // many doubles per point). The number of points tells apart most other
  // changes of the body, e.g. another region or number of points per cell.
  template <int dim>
  std::string
  Checkpoint<dim>::fingerprint(const BackgroundGrid<dim>   &grid,
                               const MaterialPointSet<dim> &points)
  {
    std::ostringstream out;
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "dimension " << dim << '\n';
    out << "grid lower corner";
    for (unsigned int d = 0; d < dim; ++d)
      out << ' ' << grid.lower_corner()[d];
    out << "\ngrid upper corner";
    for (unsigned int d = 0; d < dim; ++d)
      out << ' ' << grid.upper_corner()[d];
    out << "\ngrid cells " << grid.get_triangulation().n_global_active_cells();
    out << "\nperiodic directions";
    for (const unsigned int d : grid.periodic_directions())
      out << ' ' << d;
    out << "\npoint properties";
    for (const auto &name : points.get_layout().component_names(dim))
      out << ' ' << name;
    out << "\nmaterial points " << points.n_global_points() << '\n';
    return out.str();
  }



  template <int dim>
  unsigned int
  Checkpoint<dim>::step_of(const std::string &name)
  {
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix))
      return numbers::invalid_unsigned_int;
    const std::string digits = name.substr(prefix.size());
    if (!std::all_of(digits.begin(), digits.end(), [](const char c) {
          return std::isdigit(static_cast<unsigned char>(c));
        }))
      return numbers::invalid_unsigned_int;
    return std::stoul(digits);
  }



  template <int dim>
  void
  Checkpoint<dim>::write(const unsigned int     step,
                         BackgroundGrid<dim>   &grid,
                         MaterialPointSet<dim> &points,
                         const std::string     &state,
                         const unsigned int     keep) const
  {
    namespace fs          = std::filesystem;
    const std::string tmp = directory + "/checkpoint.tmp";
    // A checkpoint.tmp left behind by a run that was killed while writing
    // is incomplete: start afresh.
    on_rank_zero(communicator, [&]() {
      fs::remove_all(tmp);
      fs::create_directories(tmp);
      return std::string();
    });

    // Every rank writes its cells and the points in them into the same
    // files (p4est and deal.II use MPI I/O).
    points.get_particle_handler().prepare_for_serialization();
    grid.get_triangulation().save(tmp + "/grid");

    const std::string description = fingerprint(grid, points);
    MPI_Barrier(communicator);
    on_rank_zero(communicator, [&]() -> std::string {
      {
        std::ofstream file(tmp + "/" + state_file);
        file << header << '\n'
             << "step " << step << '\n'
             << "ranks " << Utilities::MPI::n_mpi_processes(communicator)
             << '\n'
             << description << "end\n"
             << state;
        file.close();
        if (!file)
          return "Cannot write the checkpoint file " + tmp + "/" + state_file;
      }

      // Only now is the checkpoint complete; make it one in one step.
      std::ostringstream name;
      name << prefix << std::setw(5) << std::setfill('0') << step;
      const std::string final_path = directory + "/" + name.str();
      fs::remove_all(final_path);
      fs::rename(tmp, final_path);

      // Older checkpoints: keep the newest `keep`.
      std::vector<std::pair<unsigned int, fs::path>> complete;
      for (const auto &entry : fs::directory_iterator(directory))
        {
          const unsigned int s = step_of(entry.path().filename().string());
          if (s != numbers::invalid_unsigned_int && entry.is_directory())
            complete.emplace_back(s, entry.path());
        }
      std::sort(complete.begin(), complete.end());
      for (std::size_t i = 0; i + keep < complete.size(); ++i)
        fs::remove_all(complete[i].second);
      return std::string();
    });
  }



  template <int dim>
  std::string
  Checkpoint<dim>::newest() const
  {
    namespace fs = std::filesystem;
    std::string path;
    if (Utilities::MPI::this_mpi_process(communicator) == 0 &&
        fs::is_directory(directory))
      {
        unsigned int newest_step = 0;
        for (const auto &entry : fs::directory_iterator(directory))
          {
            const unsigned int s = step_of(entry.path().filename().string());
            if (s != numbers::invalid_unsigned_int &&
                fs::exists(entry.path() / state_file) &&
                (path.empty() || s > newest_step))
              {
                newest_step = s;
                path        = entry.path().string();
              }
          }
      }
    return Utilities::MPI::broadcast(communicator, path, 0);
  }



  template <int dim>
  std::string
  Checkpoint<dim>::read(const std::string     &path,
                        BackgroundGrid<dim>   &grid,
                        MaterialPointSet<dim> &points) const
  {
    // Rank 0 reads the small file, all ranks check it.
    std::string contents;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ifstream      file(path + "/" + state_file);
        std::ostringstream buffer;
        buffer << file.rdbuf();
        contents = buffer.str();
      }
    contents = Utilities::MPI::broadcast(communicator, contents, 0);

    std::istringstream in(contents);
    std::string        line;
    std::getline(in, line);
    AssertThrow(line == header,
                ExcMessage("Cannot resume: " + path + "/" + state_file +
                           " is not a qsmpm checkpoint."));
    std::getline(in, line); // step
    std::getline(in, line); // ranks
    std::istringstream expected(fingerprint(grid, points));
    std::string        here;
    while (std::getline(in, line) && line != "end")
      {
        std::getline(expected, here);
        if (line == here)
          continue;
        // The list of property names is long; count them instead.
        const std::string properties = "point properties";
        if (line.rfind(properties, 0) == 0 && here.rfind(properties, 0) == 0)
          {
            const auto count = [](const std::string &names) {
              return std::to_string(
                       std::count(names.begin(), names.end(), ' ') - 1) +
                     " property components per point";
            };
            line = count(line) + " (another material model or formulation?)";
            here = count(here);
          }
        AssertThrow(false,
                    ExcMessage("Cannot resume from " + path +
                               ": it was written for another problem (" + line +
                               " in the checkpoint, " + here +
                               " in this run)."));
      }
    AssertThrow(line == "end" && !std::getline(expected, here),
                ExcMessage("Cannot resume: " + path + "/" + state_file +
                           " is incomplete."));

    // The fresh points go; the checkpoint's come with their cells, which
    // p4est distributes anew over the ranks of this run.
    auto &particle_handler = points.get_particle_handler();
    particle_handler.clear_particles();
    grid.get_triangulation().load(path + "/grid");
    particle_handler.deserialize();
    grid.distribute_dofs();

    const auto rest = in.tellg();
    return rest < 0 ? std::string() : contents.substr(rest);
  }



  template <int dim>
  void
  Checkpoint<dim>::truncate_csv(const std::string &filename,
                                const unsigned int step)
  {
    std::vector<std::string> kept;
    {
      std::ifstream file(filename);
      std::string   line;
      if (std::getline(file, line))
        kept.push_back(line);
      while (std::getline(file, line))
        {
          // A row is "step,...". A line cut off by a crash may lack even
          // its newline; the rows are in step order, so stop at the first
          // one that is not a complete row of an earlier step.
          const auto comma = line.find(',');
          if (file.eof() || comma == 0 || comma == std::string::npos ||
              line.find_first_not_of("0123456789") != comma ||
              std::stoul(line.substr(0, comma)) > step)
            break;
          kept.push_back(line);
        }
    }
    const std::string tmp = filename + ".tmp";
    {
      std::ofstream file(tmp);
      for (const auto &line : kept)
        file << line << '\n';
      AssertThrow(file, ExcMessage("Cannot write " + tmp));
    }
    std::filesystem::rename(tmp, filename);
  }



  template class Checkpoint<2>;
  template class Checkpoint<3>;
} // namespace qsmpm
