#ifndef qsmpm_materials_point_state_batch_h
#define qsmpm_materials_point_state_batch_h

#include <qsmpm/base/utilities.h>
#include <qsmpm/materials/point_state.h>

namespace qsmpm
{
  /**
   * The committed states of a batch of material points (the points of one
   * cell), as ConstitutiveModel::update_stresses() reads them: a view of
   * the points' property arrays, nothing copied.
   *
   * operator[] assembles the whole PointState of a point, as the per-point
   * interface receives it. A model that needs only part of it (an elastic
   * model only the committed stress) reads that part with stress(),
   * strain() or state(), so that the batched stress update does not copy
   * what it does not use.
   */
  template <int dim>
  class PointStateBatch
  {
  public:
    /**
     * Where the fields of PointState lie in a point's property array, and
     * how many doubles the model's own fields have.
     */
    struct Layout
    {
      unsigned int strain;
      unsigned int stress;
      unsigned int volume;
      unsigned int material_id;
      unsigned int state;
      unsigned int n_state;
    };

    /**
     * The @p n points whose property arrays start at @p properties[i] and
     * whose positions are @p positions[i], i = 0..n-1.
     */
    PointStateBatch(const Layout        &layout,
                    const double *const *properties,
                    const Point<dim>    *positions,
                    const unsigned int   n)
      : layout(layout)
      , properties(properties)
      , positions(positions)
      , n(n)
    {
    }

    /// The number of points.
    unsigned int
    size() const
    {
      return n;
    }

    /// The number of doubles of the model's fields per point.
    unsigned int
    n_state_components() const
    {
      return layout.n_state;
    }

    /// The whole committed state of point @p i.
    PointState<dim>
    operator[](const unsigned int i) const
    {
      return {strain(i),
              stress(i),
              state(i),
              properties[i][layout.volume],
              static_cast<unsigned int>(properties[i][layout.material_id]),
              positions[i]};
    }

    /// The committed Cauchy stress of point @p i.
    SymmetricTensor<2, dim>
    stress(const unsigned int i) const
    {
      return Utils::read_symmetric<dim>(properties[i] + layout.stress);
    }

    /// The committed small strain of point @p i.
    SymmetricTensor<2, dim>
    strain(const unsigned int i) const
    {
      return Utils::read_symmetric<dim>(properties[i] + layout.strain);
    }

    /// The model's committed fields of point @p i.
    ArrayView<const double>
    state(const unsigned int i) const
    {
      return {properties[i] + layout.state, layout.n_state};
    }

  private:
    const Layout        &layout;
    const double *const *properties;
    const Point<dim>    *positions;
    const unsigned int   n;
  };
} // namespace qsmpm

#endif
