// The saturated column of two layers that the tests
// contact_bodies_consolidation and layered_consolidation load: Terzaghi's
// column of terzaghi_consolidation (H = 10 m, E = 1.5 MPa, nu = 0.25, b = 1,
// 1/M = 0, rollers on the sides, held at the base, a traction on the top,
// boundary id 3), one cell wide, 2 x 2 points per cell, its lower half
// material id 0 and its upper half id 1 (the layers meet on a grid line
// for an even number of cells). Set a problem up from its text with
// qsmpm_tests::initialize_from_text() (prm_text.h).
#ifndef qsmpm_tests_two_layer_column_h
#define qsmpm_tests_two_layer_column_h

#include <deal.II/base/parameter_handler.h>
#include <iomanip>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/porous/poroelastic_model.h>
#include <sstream>
#include <string>

namespace two_layer_column
{
  using namespace dealii;

  constexpr double H = 10., E = 1.5e6, nu = 0.25;
  /// The constrained modulus, 1.8 MPa.
  constexpr double E_oed = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));

  /// The column's parameter text: @p cells cells along y, the traction
  /// @p load (downwards) on the top, the `Pore fluid` entries
  /// @p pore_fluid (besides `Enabled`), to the time @p t_end in @p steps
  /// steps growing by @p growth, and any further text @p more.
  inline std::string
  prm_text(const unsigned int cells,
           const double       load,
           const std::string &pore_fluid,
           const double       t_end,
           const unsigned int steps,
           const double       growth = 1.,
           const std::string &more   = "")
  {
    std::ostringstream prm;
    prm << std::setprecision(12) << "set Dimension = 2\n"
        << "subsection Geometry\n  set Lower corner = 0,0\n"
        << "  set Upper corner = " << H / cells << "," << H
        << "\n  set Subdivisions = 1," << cells << "\nend\n"
        << "subsection Material points\n"
        << "  set Points per cell per direction = 2\n"
        << "  set Material id = if(y > " << H / 2 << ", 1, 0)\nend\n"
        << "subsection Material\n  set Model = linear elastic\n"
        << "  subsection linear elastic\n"
        << "    set Young's modulus = " << E << "\n"
        << "    set Poisson's ratio = " << nu << "\n  end\nend\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x, 1:x, 2:xy\n"
        << "  set Traction boundaries = 3\n"
        << "  subsection Displacement\n    set Function expression = 0; 0\n"
        << "  end\n"
        << "  subsection Traction\n    set Function expression = 0; " << -load
        << "\n  end\nend\n"
        << "subsection Pore fluid\n  set Enabled = true\n"
        << pore_fluid << "end\n"
        << "subsection Load stepping\n  set Number of steps = " << steps
        << "\n  set Final load factor = " << t_end
        << "\n  set Increment growth factor = " << growth << "\nend\n"
        << "subsection Output\n  set Interval = 0\n  set Directory = "
           "two-layer-column-out\nend\n"
        << more;
    return prm.str();
  }

  /// Where the points keep their pore pressure.
  inline unsigned int
  pressure_offset(const qsmpm::MaterialPointSet<2> &points)
  {
    return points.get_offsets().state +
           dynamic_cast<const qsmpm::PoroelasticModel<2> &>(points.get_model())
             .pressure_offset();
  }
} // namespace two_layer_column

#endif
