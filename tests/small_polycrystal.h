// The small columnar polycrystal of the tests of the virtual tests
// (polycrystal_uniform, virtual_tests_shared_stiffness): 40 Voronoi grains
// on the unit square (seed 3), orientations assigned from the uniform ODF
// of the polycrystal example with 4000 elementary volumes (seed 3), cubic
// nickel crystals (C11, C12, C44 = 249, 155, 114 GPa), a grid of 12 x 12
// cells in the plane with 2 points per cell and direction.
#ifndef qsmpm_tests_small_polycrystal_h
#define qsmpm_tests_small_polycrystal_h

#include <filesystem>
#include <memory>
#include <qsmpm/homogenization/columnar_voronoi.h>
#include <qsmpm/homogenization/orientation_distribution.h>
#include <qsmpm/homogenization/texture_sampler.h>
#include <qsmpm/homogenization/virtual_tests.h>
#include <qsmpm/materials/cubic_elastic.h>
#include <vector>

namespace qsmpm_tests
{
  using namespace qsmpm;

  struct SmallPolycrystal
  {
    static constexpr unsigned int n_grains = 40, cells = 12, ppd = 2;

    const ColumnarVoronoi        grains{n_grains, {{0., 0.}}, {{1., 1.}}, 3};
    const std::vector<double>    areas = grains.areas(cells * ppd, cells *ppd);
    const TextureSampler::Result texture = TextureSampler(4000).assign(
      OrientationDistribution((std::filesystem::path(__FILE__).parent_path() /
                               ".." / "examples" / "polycrystal" / "odf" /
                               "uniform.txt")
                                .string()),
      areas,
      3);

    /// The crystals, each point with the orientation of its grain.
    VirtualTests::ModelFactory
    model() const
    {
      return [this]() {
        auto m = std::make_unique<CubicElastic<3>>(249., 155., 114.);
        m->set_orientation([this](const Point<3> &x) {
          return texture.orientations[grains.grain(x)];
        });
        return std::unique_ptr<ConstitutiveModel<3>>(std::move(m));
      };
    }
  };
} // namespace qsmpm_tests

#endif
