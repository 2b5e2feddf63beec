// A model per material id (MaterialMap, issue 15), through the .prm route:
// Material points/<Material id> gives each point its id, Material/<Models by
// material id> the model of each id.
//
// A column [0,1] x [0,2] of two layers in series, pulled at the top by a
// uniform traction s = 10 (a grid boundary), held by rollers at x = 0 and
// y = 0: the lower layer (id 0, <Model> = von Mises, E_0 = 1000, yield
// stress far above s) and the upper one (id 1, decohesion, E_1 = 4000,
// tensile strength 1000, so neither yields nor cracks). With nu = 0 the
// layers deform in uniaxial stress without lateral strain, so the exact
// solution is sigma_yy = s everywhere, u_x = 0 and
//
//   u_y(y) = s y / E_0                        (y <= 1),
//   u_y(y) = s / E_0 + s (y - 1) / E_1        (y >= 1),
//
// piecewise linear with the kink on a grid line: Q1 holds it, and one load
// step of the geometrically linear formulation (small strain, volumes not
// updated, as in periodic_laminate) reproduces it to the solver tolerance
// (Newton 1e-10 relative; checked to 1e-7 of s / E_0). With the wrong model at
// a point (the default for every point, or the ids swapped) the top moves 0.02
// or 0.0125 + 0.0075 instead of 0.0125.
//
// The state layout is the union of the models' fields: the decohesion
// model's "crack_allowed" is 1 at points of id 1 (its initial value in the
// cracking region) and 0 at points of id 0, which it never initializes.
// The output fields are the decohesion model's three, computed from the
// committed state at output time: sigma_yy / tau_nf = s / 1000 at points of
// id 1 and 0 (no such field) at points of id 0.
//
// Then the errors: a list entry without ':', an unknown model, an id that is
// not a number, the same id twice, a material id expression that is not a
// non-negative integer, and (C++) a map without a default model that meets
// a point of an id it does not know. Each must stop the run with a message
// that names the entry (checked by phrases, not by wording). Run on 1 and
// 2 ranks.
#include "tests.h"

#include <deal.II/base/quadrature_lib.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/materials/material_map.h>

using namespace qsmpm;

namespace
{
  constexpr double s = 10., E_0 = 1000., E_1 = 4000., tau_nf = 1000.;

  std::string
  column(const std::string &models_by_id,
         const std::string &material_id = "if(y > 1, 1, 0)")
  {
    return "subsection Geometry\n"
           "  set Lower corner = 0,0\n"
           "  set Upper corner = 1,2\n"
           "  set Subdivisions = 2,4\n"
           "end\n"
           "subsection Material points\n"
           "  set Update volumes = false\n"
           "  set Material id = " +
           material_id +
           "\n"
           "end\n"
           "subsection Material\n"
           "  set Model = von Mises\n"
           "  set Models by material id = " +
           models_by_id +
           "\n"
           "  subsection von Mises\n"
           "    set Young's modulus = 1000\n"
           "    set Poisson's ratio = 0\n"
           "    set Yield stress = 1e6\n"
           "  end\n"
           "  subsection decohesion\n"
           "    set Young's modulus = 4000\n"
           "    set Poisson's ratio = 0\n"
           "    set Tensile strength = 1000\n"
           "    set Fracture energy = 1e6\n"
           "    set Crack band width = 0.5\n"
           "  end\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet boundaries = 0:x, 2:y\n"
           "  set Traction boundaries = 3\n"
           "  subsection Traction\n"
           "    set Function expression = 0; 10\n"
           "  end\n"
           "end\n"
           "subsection Load stepping\n"
           "  set Number of steps = 1\n"
           "end\n"
           "subsection Nonlinear solver\n"
           "  set Tolerance = 1e-10\n"
           "  set Residual floor = 0\n"
           "  set Linear tolerance = 1e-12\n"
           "end\n"
           "subsection Output\n"
           "  set Interval = 0\n"
           "  set Directory = material-map-out\n"
           "end\n";
  }

  /// Run @p input; return the error message, or "" if it ran to the end.
  std::string
  try_run(const std::string &input)
  {
    ParameterHandler prm;
    QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    try
      {
        prm.parse_input_from_string(input);
        QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
        problem.pcout().set_condition(false);
        problem.initialize(prm);
        problem.run();
      }
    catch (const std::exception &exc)
      {
        return Utils::error_message(exc);
      }
    return "";
  }

  void
  check_stops(const std::string              &what,
              const std::string              &input,
              const std::vector<std::string> &phrases)
  {
    const std::string message = try_run(input);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << what << ": " << message << std::endl;
    check_that(what + ": stops", !message.empty());
    for (const auto &phrase : phrases)
      check_that(what + ": the message names '" + phrase + "'",
                 message.find(phrase) != std::string::npos);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  deallog << "Two layers in series, von Mises (id 0) and decohesion (id 1)"
          << std::endl;
  {
    ParameterHandler prm;
    QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(column("1: decohesion"));
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    problem.initialize(prm);
    problem.run();

    const auto &points  = problem.points();
    const auto &layout  = points.get_layout();
    const auto &offsets = points.get_offsets();
    const auto &model   = points.get_model();
    const auto  allowed = layout.offset("crack_allowed");
    // The output fields, by name, in the map's union.
    PropertyLayout output_layout;
    for (const auto &field : model.output_fields())
      output_layout.add(field.name,
                        field.n_components,
                        PropertyLayout::Kind::scalar);
    const unsigned int  syy = output_layout.offset("sigma_yy_over_tau_nf");
    std::vector<double> values(output_layout.size());

    double u_error = 0., stress_error = 0., allowed_error = 0.,
           output_error  = 0.;
    unsigned int n_id[2] = {0, 0};
    for (const auto &particle : points.get_particle_handler())
      {
        const double      *data = particle.get_properties().data();
        const unsigned int id =
          static_cast<unsigned int>(data[offsets.material_id]);
        const double y0 =
          particle.get_location()[1] - data[offsets.displacement + 1];
        const double u_exact =
          y0 <= 1. ? s * y0 / E_0 : s / E_0 + s * (y0 - 1.) / E_1;
        u_error           = std::max({u_error,
                                      std::abs(data[offsets.displacement + 1] - u_exact),
                                      std::abs(data[offsets.displacement])});
        const auto stress = Utils::read_symmetric<2>(data + offsets.stress);
        stress_error      = std::max(
          {stress_error, std::abs(stress[1][1] - s), std::abs(stress[0][0])});
        allowed_error = std::max(allowed_error,
                                 std::abs(data[allowed] - (id == 1 ? 1. : 0.)));
        points.compute_output_fields(particle, ArrayView<double>(values));
        output_error =
          std::max(output_error,
                   std::abs(values[syy] - (id == 1 ? s / tau_nf : 0.)));
        if (id < 2)
          ++n_id[id];
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    u_error             = Utilities::MPI::max(u_error, comm);
    stress_error        = Utilities::MPI::max(stress_error, comm);
    allowed_error       = Utilities::MPI::max(allowed_error, comm);
    output_error        = Utilities::MPI::max(output_error, comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "errors: u " << u_error << ", stress " << stress_error
                << ", output " << output_error << std::endl;
    const unsigned int n_0 = Utilities::MPI::sum(n_id[0], comm),
                       n_1 = Utilities::MPI::sum(n_id[1], comm);

    check_that("16 points of id 0 (y < 1) and 16 of id 1",
               n_0 == 16 && n_1 == 16 && n_0 + n_1 == points.n_global_points());
    check_that("the model is a map of <von Mises> and <decohesion>",
               model.name().find("von Mises") != std::string::npos &&
                 model.name().find("decohesion") != std::string::npos);
    check_that("max |u_p - u_exact| <= 1e-7 s / E_0",
               u_error <= 1e-7 * s / E_0);
    check_that("max |sigma_p - s e_y (x) e_y| <= 1e-7 s",
               stress_error <= 1e-7 * s);
    check_that("crack_allowed: 1 at id 1, 0 at id 0 (exact)",
               allowed_error == 0.);
    check_that("output sigma_yy / tau_nf: s / tau_nf at id 1, 0 at id 0, "
               "within 1e-7 s / tau_nf",
               output_error <= 1e-7 * s / tau_nf);
  }

  deallog << "Errors" << std::endl;
  check_stops("list entry without ':'",
              column("1 decohesion"),
              {"Models by material id", "1 decohesion"});
  check_stops("unknown model",
              column("1: concrete"),
              {"Models by material id", "concrete"});
  check_stops("id not a number",
              column("one: decohesion"),
              {"Models by material id", "one"});
  check_stops("the same id twice",
              column("1: decohesion, 1: linear elastic"),
              {"material id 1"});
  check_stops("material id not an integer",
              column("1: decohesion", "y / 2"),
              {"Material id", "non-negative integer"});
  check_stops("negative material id",
              column("1: decohesion", "-1"),
              {"Material id", "non-negative integer"});
  {
    // C++: a map with models for ids 0 and 1 only meets a point of id 2.
    std::string message;
    try
      {
        ParameterHandler prm;
        QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
        prm.parse_input_from_string(column(""));
        QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
        problem.pcout().set_condition(false);
        problem.parameters().parse_parameters(prm);
        problem.grid().make_box(problem.parameters().geometry);
        auto map = std::make_unique<MaterialMap<2>>();
        map->add(0, std::make_unique<LinearElastic<2>>(E_0, 0., false));
        map->add(1, std::make_unique<LinearElastic<2>>(E_1, 0., false));
        problem.set_model(std::move(map));
        problem.points().fill([](const Point<2> &) { return true; },
                              QGauss<2>(2),
                              [](const Point<2> &x) -> unsigned int {
                                return x[1] > 1.5 ? 2 : x[1] > 1. ? 1 : 0;
                              });
      }
    catch (const std::exception &exc)
      {
        message = Utils::error_message(exc);
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "unknown id: " << message << std::endl;
    check_that("a map without default meets material id 2: stops naming it",
               message.find("material id 2") != std::string::npos);
  }
}
