// The UMAT adapter (Material/Model = umat, doc/user_models.md) at small
// strain: UMATs written in this directory (tests/umat/) against the
// built-in models with the same equations.
//
// A strip (2D plane strain, 16 x 16 cells; 3D, 4 x 4 x 4 cells) held on
// its sides and bottom, pressed by a traction of 1e3 t on half of its top,
// 5 load steps, E = 1e6, nu = 0.3:
//
//  1. Fortran UMAT of isotropic linear elasticity (umat_elastic.f) against
//     `linear elastic`;
//  2. Fortran UMAT of von Mises plasticity with linear hardening
//     (umat_von_mises.f: yield stress 600, H = 1e4) against `von Mises`;
//     it yields (the punch's limit load is about (2 + pi) 600 / sqrt 3 =
//     1780, the traction reaches 1000 on the loaded half's edge);
//  3. the same UMAT written in C (umat_von_mises_c.c) against the Fortran
//     one;
//  4. a material map: `linear elastic` for y < 0.5, the elastic UMAT for
//     material id 1 above, against `linear elastic` everywhere.
//
// The check: the displacements of all points after every step agree to
// 1e-10 of the largest. Both runs solve to a Newton tolerance of 1e-13
// (relative): the tolerance allows for runs whose Newton iterations
// differ, though here they do not (measured: 3e-16 to 1.6e-15, the
// round-off of the two stress updates); a wrong Voigt order, a factor 2 on
// the shear strains or a lost out-of-plane stress would differ by 1e-3 or
// more.
#include "prm_text.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  const std::string umat_dir = QSMPM_UMAT_DIR;

  /// The subsection Material of a built-in model or a UMAT.
  std::string
  material(const std::string &model)
  {
    std::ostringstream m;
    m << "subsection Material\n";
    if (model == "map")
      {
        // Linear elastic below y = 0.5, the elastic UMAT above: its
        // subsection goes before the "end" that closes Material.
        std::string text = material("linear elastic");
        text.insert(text.rfind("end\n"),
                    "  set Models by material id = 1: umat\n"
                    "  subsection umat\n"
                    "    set UMAT library = " +
                      umat_dir +
                      "/libumat_elastic.so\n"
                      "    set Properties = 1e6, 0.3\n"
                      "  end\n");
        return text + "subsection Material points\n"
                      "  set Material id = if(y > 0.5, 1, 0)\nend\n";
      }
    if (model == "linear elastic" || model == "von Mises")
      {
        m << "  set Model = " << model << "\n  subsection " << model << "\n"
          << "    set Young's modulus = 1e6\n    set Poisson's ratio = 0.3\n";
        if (model == "von Mises")
          m << "    set Yield stress = 600\n    set Hardening modulus = 1e4\n";
      }
    else
      {
        const bool elastic = (model == "umat_elastic");
        m << "  set Model = umat\n  subsection umat\n"
          << "    set UMAT library = " << umat_dir << "/lib" << model << ".so\n"
          << "    set Material name = " << model << "\n"
          << "    set Properties = 1e6, 0.3" << (elastic ? "" : ", 600, 1e4")
          << "\n"
          << "    set Number of state variables = " << (elastic ? 0 : 1)
          << "\n";
      }
    m << "  end\nend\n";
    return m.str();
  }

  template <int dim>
  std::string
  strip_prm(const std::string &model)
  {
    std::ostringstream prm;
    prm << "set Dimension = " << dim << "\n"
        << "subsection Geometry\n  set Subdivisions = "
        << (dim == 2 ? "16,16" : "4,4,4") << "\nend\n"
        << material(model) << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = "
        << (dim == 2 ? "0:x, 1:x, 2:y" : "0:x, 1:x, 2:y, 3:y, 4:z") << "\n"
        << "  set Traction boundaries = " << 2 * dim - 1 << "\n"
        << "  subsection Traction\n"
        << "    set Function expression = " << (dim == 2 ? "0; " : "0; 0; ")
        << "-1e3*t*(x<0.5 ? 1 : 0)\n"
        << "  end\nend\n"
        << "subsection Load stepping\n  set Number of steps = 5\nend\n"
        << "subsection Nonlinear solver\n  set Tolerance = 1e-13\nend\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = auto-out\nend\n";
    return prm.str();
  }

  /// The displacements of all points after every step, by particle id.
  template <int dim>
  using Curve = std::vector<std::map<types::particle_index, Tensor<1, dim>>>;

  template <int dim>
  Curve<dim>
  run(const std::string &model)
  {
    QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, strip_prm<dim>(model));
    Curve<dim> curve;
    problem.set_step_callback(
      [&](const typename QuasiStaticProblem<dim>::StepReport &) {
        curve.push_back(point_displacements(problem));
        return true;
      });
    problem.run();
    AssertThrow(curve.size() == 5, ExcMessage("the run did not finish"));
    return curve;
  }

  /// max over steps and points |u_a - u_b| / max |u_a|.
  template <int dim>
  double
  difference(const Curve<dim> &a, const Curve<dim> &b)
  {
    double largest = 0., diff = 0.;
    for (unsigned int s = 0; s < a.size(); ++s)
      for (const auto &[id, u] : a[s])
        {
          largest = std::max(largest, u.norm());
          diff    = std::max(diff, (u - b[s].at(id)).norm());
        }
    return diff / largest;
  }

  template <int dim>
  void
  compare()
  {
    deallog << dim << "D" << std::endl;
    const Curve<dim> elastic = run<dim>("linear elastic");
    check("UMAT elastic (Fortran) vs linear elastic",
          difference(elastic, run<dim>("umat_elastic")),
          1e-10);
    check("UMAT elastic for material id 1 only vs linear elastic",
          difference(elastic, run<dim>("map")),
          1e-10);
    const Curve<dim> plastic = run<dim>("von Mises");
    check_at_least("it yields: von Mises vs linear elastic",
                   difference(elastic, plastic),
                   1e-3);
    const Curve<dim> fortran = run<dim>("umat_von_mises");
    check("UMAT von Mises (Fortran) vs von Mises",
          difference(plastic, fortran),
          1e-10);
    check("UMAT von Mises (C) vs (Fortran)",
          difference(fortran, run<dim>("umat_von_mises_c")),
          1e-10);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  compare<2>();
  compare<3>();
}
