#ifndef qsmpm_homogenization_virtual_tests_h
#define qsmpm_homogenization_virtual_tests_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <functional>
#include <memory>
#include <mpi.h>
#include <qsmpm/homogenization/stiffness_bounds.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/solvers/newton_parameters.h>
#include <string>
#include <vector>

namespace qsmpm
{
  template <int dim>
  struct PreconditionerHandover;

  /**
   * The six virtual tests of paper Section 4.4 (Fig. 6) on a box of
   * material, in 3D, that give the full effective stiffness C of eq. (4.3)
   * column by column without assuming any symmetry.
   *
   * Test k (Voigt order 11, 22, 33, 23, 13, 12) prescribes the macroscopic
   * strain eps_k = "Strain" (0.004 in the paper: faces displaced by 0.002 L
   * each, equal and opposite) in "Load steps" steps. Boundary conditions:
   *
   * - mixed (the paper's): tests 11, 22, 33 load the faces normal to x_k
   *   with u = +-(strain L / 2) e_k (all components prescribed), tests ij
   *   (23, 13, 12) the faces normal to x_j with u = +-(strain L / 2) e_i
   *   (simple shear, gamma_ij = strain); the four other faces are confined:
   *   zero normal displacement, free to slide. The loaded faces' conditions
   *   are added first, so at shared edges they win.
   * - affine (kinematic uniform): u = E (x - x_centre) on all six faces,
   *   E the macroscopic strain tensor of the test.
   * - periodic: the grid is periodic in x, y and z and u = E (x - x_centre)
   *   + w with a periodic fluctuation w (BoundaryDescriptor::
   *   set_macroscopic_displacement_gradient()); the mean strain is then
   *   exactly E. There are no loaded faces, so no reaction stress.
   *
   * Results: the effective stress of every test twice, from the reaction
   * forces (paper: the force on each face, averaged over the pair of
   * opposite faces, per unit area; a shear component only where the face's
   * tangential component is prescribed, the average of both faces' estimates
   * where both are) and as the volume average of the point stresses,
   * sum_p Omega_p sigma_p / sum_p Omega_p; column k of C is the stress
   * divided by the strain. The volume average is the complete one and gives
   * the main result.
   */
  class VirtualTests
  {
  public:
    using Matrix6 = StiffnessBounds::Matrix6;

    enum class BoundaryType
    {
      mixed,
      affine,
      periodic
    };

    struct Parameters
    {
      BoundaryType                boundary_type        = BoundaryType::mixed;
      double                      side_length          = 1.;
      std::array<unsigned int, 3> subdivisions         = {{16, 16, 4}};
      unsigned int                points_per_direction = 2;
      double                      strain               = 0.004;
      unsigned int                n_load_steps         = 2;
      /// Update the point volumes with det F (geometrically nonlinear).
      bool             update_volumes = true;
      NewtonParameters solver;
      /// Where each test writes its reactions.csv (subdirectory test_k).
      std::string output_directory = "output";
      /// Tests to run (Voigt indices); default all six.
      std::vector<unsigned int> tests = {0, 1, 2, 3, 4, 5};
      /**
       * The tests are independent: they run at once in this many groups of
       * ranks, each test on the ranks of one group (the tests of a group
       * one after the other). 0: one group per rank, at most as many groups
       * as tests; 1: every test on all ranks. A group of fewer ranks holds
       * more of its sample per rank, and its tests scale better than one
       * sample spread over all ranks. The results are those of a run on
       * the group's ranks, so they do not depend on the grouping beyond
       * the solver's tolerances.
       */
      unsigned int test_groups = 0;
      /**
       * The tests of a group that fix the same degrees of freedom (mixed:
       * those that load the same pair of faces; affine and periodic: all)
       * take the stiffness and preconditioner over from the test before
       * instead of building their own (QuasiStaticProblem::
       * take_over_preconditioner()): they start from the same points. The
       * groups get the tests in the order of the faces they load. false:
       * each test builds its own.
       */
      bool share_preconditioner = true;
    };

    /// Result of one test.
    struct TestReport
    {
      std::array<double, 6> stress_volume{};
      std::array<double, 6> stress_reaction{};
      /// Whether stress_reaction[a] was measured by some face.
      std::array<bool, 6> reaction_measured{};
      /// Volume average of the point strains (Voigt, engineering shear).
      std::array<double, 6> mean_strain{};
      unsigned int          newton_iterations = 0;
      unsigned int          gmres_iterations  = 0;
      /// Preconditioners the test built (not those it took over).
      unsigned int preconditioner_builds = 0;
      double       wall_time             = 0;
    };

    /// Creates a fresh constitutive model for each test.
    using ModelFactory = std::function<std::unique_ptr<ConstitutiveModel<3>>()>;
    /// Optional: the material id (e.g. grain) of a point at x.
    using MaterialId = std::function<unsigned int(const Point<3> &)>;

    VirtualTests(const Parameters &parameters, const MPI_Comm communicator);

    /// Run the tests; every rank returns the same results.
    void
    run(const ModelFactory &make_model, const MaterialId &material_id = {});

    /// C from the volume averages (columns of tests not run are zero).
    const Matrix6 &
    stiffness() const;

    /// C from the reaction forces; unmeasured entries are zero.
    const Matrix6 &
    stiffness_from_reactions() const;

    /**
     * C = Sigma E^-1 from the volume-averaged stresses (columns of Sigma)
     * and the volume-averaged point strains (columns of E) of the six tests:
     * the stiffness that relates the mean stress to the strain the sample
     * actually has on average, which differs from the nominal strain where
     * the boundary conditions let the sample rotate or bend. Needs all six
     * tests.
     */
    Matrix6
    stiffness_from_mean_strains() const;

    /// Whether an entry of stiffness_from_reactions() was measured.
    const std::array<std::array<bool, 6>, 6> &
    reaction_mask() const;

    const std::vector<TestReport> &
    reports() const;

    /// Number of material points and grid cells of each test.
    unsigned long
    n_points() const;
    unsigned long
    n_cells() const;

    /// "mixed", "affine" or "periodic" -> BoundaryType; throws otherwise.
    static BoundaryType
    parse_boundary_type(const std::string &name);
    static std::string
    name(const BoundaryType type);

    /// Symmetric part (C + C^T) / 2 of a 6x6 matrix.
    static Matrix6
    symmetric_part(const Matrix6 &C);

    /// Frobenius norm of the skew part over the norm of C.
    static double
    relative_asymmetry(const Matrix6 &C);

  private:
    /**
     * Test @p k on the ranks of @p group (all of them take part), with the
     * stiffness and preconditioner of the group's test before in
     * @p handover (if not null); returns with those of this test there if
     * Parameters::share_preconditioner.
     */
    TestReport
    run_test(const unsigned int                          k,
             const MPI_Comm                              group,
             const bool                                  verbose,
             const ModelFactory                         &make_model,
             const MaterialId                           &material_id,
             std::unique_ptr<PreconditionerHandover<3>> &handover);

    /// The pair of faces test @p k loads (mixed; 0 for the others).
    unsigned int
    loaded_direction(const unsigned int k) const;

    Parameters                         prm;
    MPI_Comm                           communicator;
    Matrix6                            C_volume{};
    Matrix6                            C_reaction{};
    std::array<std::array<bool, 6>, 6> mask{};
    std::vector<TestReport>            test_reports;
    unsigned long                      points = 0, cells = 0;
  };
} // namespace qsmpm

#endif
