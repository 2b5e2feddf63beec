#include <algorithm>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/homogenization/virtual_tests.h>
#include <type_traits>

namespace qsmpm
{
  namespace
  {
    // Voigt index -> tensor index pair, order 11, 22, 33, 23, 13, 12.
    constexpr unsigned int voigt_i[6] = {0, 1, 2, 1, 0, 0};
    constexpr unsigned int voigt_j[6] = {0, 1, 2, 2, 2, 1};

    // u(x, t) = t H (x - c).
    class LinearDisplacement : public Function<3>
    {
    public:
      LinearDisplacement(const Tensor<2, 3> &H, const Point<3> &c)
        : Function<3>(3)
        , H(H)
        , c(c)
      {
      }

      double
      value(const Point<3> &x, const unsigned int component) const override
      {
        return this->get_time() * (H * (x - c))[component];
      }

      void
      vector_value(const Point<3> &x, Vector<double> &values) const override
      {
        const Tensor<1, 3> u = this->get_time() * (H * (x - c));
        for (unsigned int d = 0; d < 3; ++d)
          values[d] = u[d];
      }

    private:
      const Tensor<2, 3> H;
      const Point<3>     c;
    };
  } // namespace



  VirtualTests::VirtualTests(const Parameters &parameters,
                             const MPI_Comm    communicator)
    : prm(parameters)
    , communicator(communicator)
  {
    AssertThrow(prm.side_length > 0 && prm.strain != 0. &&
                  prm.n_load_steps >= 1 && prm.points_per_direction >= 1,
                ExcMessage("Virtual tests: side length, strain, load steps "
                           "and points per direction must be positive."));
    for (const unsigned int k : prm.tests)
      AssertThrow(k < 6, ExcMessage("Virtual tests: test index must be < 6."));
  }



  VirtualTests::BoundaryType
  VirtualTests::parse_boundary_type(const std::string &name)
  {
    if (name == "mixed")
      return BoundaryType::mixed;
    if (name == "affine")
      return BoundaryType::affine;
    if (name == "periodic")
      return BoundaryType::periodic;
    AssertThrow(false,
                ExcMessage("Unknown boundary conditions <" + name +
                           ">; choose mixed, affine or periodic."));
    return BoundaryType::mixed;
  }



  std::string
  VirtualTests::name(const BoundaryType type)
  {
    switch (type)
      {
        case BoundaryType::mixed:
          return "mixed";
        case BoundaryType::affine:
          return "affine";
        default:
          return "periodic";
      }
  }



  void
  VirtualTests::run(const ModelFactory &make_model,
                    const MaterialId   &material_id)
  {
    test_reports.assign(6, TestReport());
    C_volume   = Matrix6{};
    C_reaction = Matrix6{};
    for (auto &row : mask)
      row.fill(false);

    // The groups of ranks: contiguous ranks. The tests in the order of the
    // faces they load (stable: in the order of the list among those), in
    // contiguous runs to the groups, so that the tests of a group that fix
    // the same dofs follow each other and share their stiffness.
    std::vector<unsigned int> order = prm.tests;
    std::stable_sort(order.begin(),
                     order.end(),
                     [this](const unsigned int a, const unsigned int b) {
                       return loaded_direction(a) < loaded_direction(b);
                     });
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_tests = prm.tests.size();
    const unsigned int n_groups =
      std::max(1u,
               std::min({prm.test_groups == 0 ? n_ranks : prm.test_groups,
                         n_ranks,
                         n_tests}));
    const auto group_of_rank = [&](const unsigned int r) {
      return r * n_groups / n_ranks;
    };
    const auto group_of_test = [&](const unsigned int n) {
      return n * n_groups / n_tests;
    };
    const unsigned int group = group_of_rank(rank);
    MPI_Comm           group_communicator;
    const int          ierr =
      MPI_Comm_split(communicator, group, rank, &group_communicator);
    AssertThrowMPI(ierr);

    // A test that fails on one group must stop every rank: the others
    // would wait for its results below. Its message travels to all. With
    // Verbose, the first rank prints the steps of its own group's tests.
    std::string                                error;
    std::unique_ptr<PreconditionerHandover<3>> handover;
    for (unsigned int n = 0; n < n_tests; ++n)
      if (group_of_test(n) == group && error.empty())
        {
          try
            {
              test_reports[order[n]] = run_test(order[n],
                                                group_communicator,
                                                prm.solver.verbose && rank == 0,
                                                make_model,
                                                material_id,
                                                handover);
              // What the test freed goes back to the system before the
              // next one sets up beside the handed-over matrix and
              // hierarchy (the polycrystal: a peak of 0.89 GB per rank
              // instead of 0.94).
              Utils::release_free_heap();
            }
          catch (const std::exception &exc)
            {
              error = Utils::error_message(exc);
            }
        }
    handover.reset();
    MPI_Comm_free(&group_communicator);
    Utils::throw_if_any_rank(error, communicator);

    // Every rank gets every test's report from the first rank of the group
    // that ran it (a report is plain data).
    static_assert(std::is_trivially_copyable_v<TestReport>);
    for (unsigned int n = 0; n < n_tests; ++n)
      {
        unsigned int root = 0;
        while (group_of_rank(root) != group_of_test(n))
          ++root;
        MPI_Bcast(&test_reports[order[n]],
                  sizeof(TestReport),
                  MPI_BYTE,
                  root,
                  communicator);
      }
    points = dealii::Utilities::MPI::max(points, communicator);
    cells  = dealii::Utilities::MPI::max(cells, communicator);

    for (const unsigned int k : prm.tests)
      for (unsigned int a = 0; a < 6; ++a)
        {
          const TestReport &report = test_reports[k];
          C_volume[a][k]           = report.stress_volume[a] / prm.strain;
          C_reaction[a][k]         = report.stress_reaction[a] / prm.strain;
          mask[a][k]               = report.reaction_measured[a];
        }
  }



  unsigned int
  VirtualTests::loaded_direction(const unsigned int k) const
  {
    return prm.boundary_type == BoundaryType::mixed ? voigt_j[k] : 0;
  }



  VirtualTests::TestReport
  VirtualTests::run_test(const unsigned int  k,
                         const MPI_Comm      group,
                         const bool          verbose,
                         const ModelFactory &make_model,
                         const MaterialId   &material_id,
                         std::unique_ptr<PreconditionerHandover<3>> &handover)
  {
    const double L = prm.side_length;
    Point<3>     centre, upper;
    for (unsigned int d = 0; d < 3; ++d)
      {
        centre[d] = 0.5 * L;
        upper[d]  = L;
      }
    const double area = L * L;

    Timer                 timer(group, true);
    QuasiStaticProblem<3> problem(group);
    problem.pcout().set_condition(verbose);
    problem.grid().make_box(Point<3>(), upper, prm.subdivisions);
    if (prm.boundary_type == BoundaryType::periodic)
      problem.grid().make_periodic({0, 1, 2});
    problem.set_model(make_model());
    // The material ids are given to fill(), so that the model
    // initializes each point's state for its id.
    std::array<unsigned int, 3> n_per_direction;
    n_per_direction.fill(prm.points_per_direction);
    problem.points().fill([](const Point<3> &) { return true; },
                          MaterialPointSet<3>::reference_rule(
                            MaterialPointSet<3>::Placement::regular,
                            n_per_direction),
                          material_id ?
                            material_id :
                            MaterialId([](const Point<3> &) { return 0u; }));
    const auto &offsets = problem.points().get_offsets();
    points              = problem.points().n_global_points();
    cells = problem.grid().get_triangulation().n_global_active_cells();

    // The macroscopic displacement gradient H of the test.
    const unsigned int i = voigt_i[k], j = voigt_j[k];
    Tensor<2, 3>       H;
    auto              &bcs = problem.boundary_conditions();
    // Per condition: its face and whether all components are prescribed.
    std::vector<std::pair<unsigned int, bool>> faces;
    std::array<bool, 3>                        all{{true, true, true}};
    if (prm.boundary_type == BoundaryType::mixed)
      {
        H[i][j]      = prm.strain;
        const auto g = std::make_shared<LinearDisplacement>(H, centre);
        for (const unsigned int f : {2 * j, 2 * j + 1})
          {
            bcs.add_dirichlet_boundary(f, all, g);
            faces.emplace_back(f, true);
          }
        const auto zero = std::make_shared<Functions::ZeroFunction<3>>(3);
        for (unsigned int d = 0; d < 3; ++d)
          if (d != j)
            for (const unsigned int f : {2 * d, 2 * d + 1})
              {
                bcs.add_dirichlet_boundary(f, {}, zero, true);
                faces.emplace_back(f, false);
              }
      }
    else
      {
        // The symmetric macroscopic strain tensor of the test.
        H[i][j] = (i == j ? prm.strain : 0.5 * prm.strain);
        H[j][i] = H[i][j];
      }
    if (prm.boundary_type == BoundaryType::periodic)
      bcs.set_macroscopic_displacement_gradient(
        [H](const double t) { return t * H; }, centre);
    else if (prm.boundary_type == BoundaryType::affine)
      {
        const auto g = std::make_shared<LinearDisplacement>(H, centre);
        for (unsigned int f = 0; f < 6; ++f)
          {
            bcs.add_dirichlet_boundary(f, all, g);
            faces.emplace_back(f, true);
          }
      }

    auto &p                           = problem.parameters();
    p.nonlinear_solver                = prm.solver;
    p.load_stepping.n_steps           = prm.n_load_steps;
    p.load_stepping.final_load_factor = 1.;
    p.output.interval                 = 0;
    p.output.write_increment          = false;
    p.output.directory = prm.output_directory + "/test_" + std::to_string(k);
    p.material_points.update_volumes = prm.update_volumes;
    if (handover)
      problem.take_over_preconditioner(std::move(handover));
    problem.run();

    TestReport report;
    for (const auto &step : problem.step_reports())
      {
        report.newton_iterations += step.newton.newton_iterations;
        report.gmres_iterations += step.newton.linear_iterations;
      }
    report.preconditioner_builds = problem.n_preconditioner_builds();

    // Volume averages of stress and strain at the points.
    double sums[13] = {};
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const double *data   = particle.get_properties().data();
        const double  volume = data[offsets.volume];
        const auto    sigma  = Utils::read_symmetric<3>(data + offsets.stress);
        const auto    eps    = Utils::read_symmetric<3>(data + offsets.strain);
        for (unsigned int a = 0; a < 6; ++a)
          {
            sums[a] += volume * sigma[voigt_i[a]][voigt_j[a]];
            sums[6 + a] +=
              volume * eps[voigt_i[a]][voigt_j[a]] * (a < 3 ? 1. : 2.);
          }
        sums[12] += volume;
      }
    dealii::Utilities::MPI::sum(ArrayView<const double>(sums, 13),
                                group,
                                ArrayView<double>(sums, 13));
    for (unsigned int a = 0; a < 6; ++a)
      {
        report.stress_volume[a] = sums[a] / sums[12];
        report.mean_strain[a]   = sums[6 + a] / sums[12];
      }

    // Reaction forces per face, averaged over the pair of faces.
    const auto                 &reactions = problem.reactions();
    std::array<Tensor<1, 3>, 6> F;
    std::array<bool, 6>         full{}, loaded{};
    for (unsigned int c = 0; c < faces.size(); ++c)
      {
        F[faces[c].first]      = reactions[c];
        full[faces[c].first]   = faces[c].second;
        loaded[faces[c].first] = true;
      }
    for (unsigned int a = 0; a < 6; ++a)
      {
        const unsigned int ii = voigt_i[a], jj = voigt_j[a];
        double             sum = 0;
        unsigned int       n   = 0;
        // sigma_ii (normal): measured wherever the faces carry a
        // condition (mixed and affine: the normal component is
        // prescribed on every face; periodic: none). sigma_ij from the
        // faces normal to x_j (component i) and to x_i (component j),
        // where prescribed.
        for (const auto &[comp, dir] :
             {std::make_pair(ii, jj), std::make_pair(jj, ii)})
          {
            if (!(loaded[2 * dir] && loaded[2 * dir + 1]) ||
                (comp != dir && !(full[2 * dir] && full[2 * dir + 1])))
              continue;
            sum += (F[2 * dir + 1][comp] - F[2 * dir][comp]) / (2. * area);
            ++n;
            if (ii == jj)
              break;
          }
        report.reaction_measured[a] = n > 0;
        report.stress_reaction[a]   = n > 0 ? sum / n : 0.;
      }

    if (prm.share_preconditioner)
      handover = problem.hand_over_preconditioner();
    timer.stop();
    report.wall_time = timer.wall_time();
    return report;
  }



  const VirtualTests::Matrix6 &
  VirtualTests::stiffness() const
  {
    return C_volume;
  }



  VirtualTests::Matrix6
  VirtualTests::stiffness_from_mean_strains() const
  {
    AssertThrow(prm.tests.size() == 6,
                ExcMessage("The stiffness from the mean strains needs all "
                           "six tests."));
    Matrix6 sigma, eps;
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int k = 0; k < 6; ++k)
        {
          sigma[a][k] = test_reports[k].stress_volume[a];
          eps[a][k]   = test_reports[k].mean_strain[a];
        }
    const Matrix6 eps_inverse = StiffnessBounds::inverse(eps);
    Matrix6       C{};
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        for (unsigned int k = 0; k < 6; ++k)
          C[a][b] += sigma[a][k] * eps_inverse[k][b];
    return C;
  }



  const VirtualTests::Matrix6 &
  VirtualTests::stiffness_from_reactions() const
  {
    return C_reaction;
  }



  const std::array<std::array<bool, 6>, 6> &
  VirtualTests::reaction_mask() const
  {
    return mask;
  }



  const std::vector<VirtualTests::TestReport> &
  VirtualTests::reports() const
  {
    return test_reports;
  }



  unsigned long
  VirtualTests::n_points() const
  {
    return points;
  }



  unsigned long
  VirtualTests::n_cells() const
  {
    return cells;
  }



  VirtualTests::Matrix6
  VirtualTests::symmetric_part(const Matrix6 &C)
  {
    Matrix6 S;
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        S[a][b] = 0.5 * (C[a][b] + C[b][a]);
    return S;
  }



  double
  VirtualTests::relative_asymmetry(const Matrix6 &C)
  {
    double skew = 0, norm = 0;
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        {
          skew += 0.25 * (C[a][b] - C[b][a]) * (C[a][b] - C[b][a]);
          norm += C[a][b] * C[a][b];
        }
    return std::sqrt(skew / norm);
  }
} // namespace qsmpm
