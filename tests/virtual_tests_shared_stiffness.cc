// The six virtual tests of one sample start from the same points in the
// same state, so that tests fixing the same degrees of freedom have the
// same stiffness: VirtualTests hands the stiffness and its AMG hierarchy
// from one test of a group to the next (QuasiStaticProblem::
// hand_over_preconditioner() and take_over_preconditioner()) instead of
// assembling and building them again. A small columnar polycrystal
// (uniform texture, cubic nickel crystals), all six tests in one group of
// all ranks (Test groups = 1) and in groups of ranks (the default), with
// the paper's mixed conditions and with affine ones:
//
// - builds: mixed, one per pair of loaded faces (x, y, z: 3) against 6
//   without sharing; affine, 1 against 6 (all faces fixed in every test).
//   In groups of ranks (2 ranks: tests 11, 22, 12 and 33, 23, 13) mixed
//   needs 3, affine 2 (one per group). A stiffness taken over for other
//   constrained dofs would show as fewer builds;
// - the answers do not change: a test that takes the stiffness over
//   solves with the same preconditioner as one that builds it from the
//   same matrix, so GMRES needs the same iterations in every test
//   (difference 0) and C is the same to round-off (1e-12 relative, far
//   below the solver tolerances of 1e-8: a preconditioner built for other
//   constrained dofs would change the iterations and C by about those).
#include "small_polycrystal.h"
#include "tests.h"

using namespace qsmpm;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  const SmallPolycrystal sample;
  const unsigned int     cells = SmallPolycrystal::cells;

  struct Result
  {
    VirtualTests::Matrix6     C;
    std::vector<unsigned int> gmres;
    unsigned int              builds = 0;
  };
  const auto run = [&](const VirtualTests::BoundaryType type,
                       const unsigned int               test_groups,
                       const bool                       share) {
    VirtualTests::Parameters p;
    p.boundary_type           = type;
    p.test_groups             = test_groups;
    p.share_preconditioner    = share;
    p.subdivisions            = {{cells, cells, 3}};
    p.points_per_direction    = SmallPolycrystal::ppd;
    p.solver.tolerance        = 1e-8;
    p.solver.residual_floor   = 0.;
    p.solver.linear_tolerance = 1e-8;
    p.output_directory        = "results";
    VirtualTests tests(p, MPI_COMM_WORLD);
    tests.run(sample.model());
    Result result;
    result.C = tests.stiffness();
    for (const auto &report : tests.reports())
      {
        result.gmres.push_back(report.gmres_iterations);
        result.builds += report.preconditioner_builds;
      }
    return result;
  };

  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  deallog << n_ranks << " rank(s)" << std::endl;
  for (const auto type :
       {VirtualTests::BoundaryType::mixed, VirtualTests::BoundaryType::affine})
    for (const unsigned int groups : {1u, 0u})
      {
        const std::string name =
          VirtualTests::name(type) + ", " +
          (groups == 1 ? "one group" : "groups of ranks");
        const Result shared = run(type, groups, true);
        const Result own    = run(type, groups, false);
        // One build per group and pair of loaded faces (mixed) or per
        // group (affine); the groups take the tests in the order 11, 22,
        // 12, 33, 23, 13 in contiguous runs.
        const unsigned int n_groups = groups == 1 ? 1 : std::min(n_ranks, 6u);
        unsigned int       expected = 0;
        if (type == VirtualTests::BoundaryType::affine)
          expected = n_groups;
        else
          {
            const unsigned int direction[6] = {0, 1, 1, 2, 2, 2};
            for (unsigned int n = 0; n < 6; ++n)
              if (n == 0 || n * n_groups / 6 != (n - 1) * n_groups / 6 ||
                  direction[n] != direction[n - 1])
                ++expected;
          }
        check(name + ": builds shared - expected (" + std::to_string(expected) +
                ")",
              double(shared.builds) - double(expected),
              0.);
        check(name + ": builds without sharing - 6",
              double(own.builds) - 6.,
              0.);
        double gmres_difference = 0.;
        for (unsigned int k = 0; k < 6; ++k)
          gmres_difference = std::max<double>(gmres_difference,
                                              std::abs(double(shared.gmres[k]) -
                                                       double(own.gmres[k])));
        check(name + ": GMRES iterations per test, |shared - own|",
              gmres_difference,
              0.);
        double diff = 0., norm = 0.;
        for (unsigned int a = 0; a < 6; ++a)
          for (unsigned int b = 0; b < 6; ++b)
            {
              diff += std::pow(shared.C[a][b] - own.C[a][b], 2);
              norm += std::pow(own.C[a][b], 2);
            }
        check(name + ": |C shared - C own| / |C|",
              std::sqrt(diff / norm),
              1e-12);
      }
}
