#ifndef qsmpm_materials_point_state_batch_h
#define qsmpm_materials_point_state_batch_h

#include <limits>
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
     * The fields of the committed state that a model's batched functions
     * (ConstitutiveModel::update_stresses(), tangents(), dissipation())
     * read: see ConstitutiveModel::batch_fields(). The residual keeps a
     * copy of only these (and its own) per point for the load step.
     */
    struct Fields
    {
      bool strain      = true;
      bool stress      = true;
      bool state       = true;
      bool volume      = true;
      bool material_id = true;
    };

    /**
     * Where the fields of PointState lie in a point's data, and how many
     * doubles the model's own fields have. A field that is not there
     * (not among the Fields of a packed copy) has the offset
     * numbers::invalid_unsigned_int.
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

    /**
     * The @p n points whose data are the consecutive records of
     * @p stride doubles from @p first (a packed copy), with positions
     * @p positions[i].
     */
    PointStateBatch(const Layout      &layout,
                    const double      *first,
                    const unsigned int stride,
                    const Point<dim>  *positions,
                    const unsigned int n)
      : layout(layout)
      , first(first)
      , stride(stride)
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

    /**
     * The whole committed state of point @p i. Fields that the batch does
     * not hold (a model that reads more than its batch_fields()) are NaN
     * (the material id numbers::invalid_unsigned_int, the model's fields
     * an empty view), so that the mistake shows in the residual instead of
     * passing as a plausible value.
     */
    PointState<dim>
    operator[](const unsigned int i) const
    {
      const double  nan  = std::numeric_limits<double>::quiet_NaN();
      const double *data = point(i);
      return {has(layout.strain) ? strain(i) : nan_tensor(),
              has(layout.stress) ? stress(i) : nan_tensor(),
              has(layout.state) ? state(i) : ArrayView<const double>(),
              has(layout.volume) ? data[layout.volume] : nan,
              has(layout.material_id) ?
                static_cast<unsigned int>(data[layout.material_id]) :
                numbers::invalid_unsigned_int,
              positions[i]};
    }

    /// The committed Cauchy stress of point @p i.
    SymmetricTensor<2, dim>
    stress(const unsigned int i) const
    {
      Assert(has(layout.stress), ExcMessage("The batch has no stresses."));
      return Utils::read_symmetric<dim>(point(i) + layout.stress);
    }

    /// The committed small strain of point @p i.
    SymmetricTensor<2, dim>
    strain(const unsigned int i) const
    {
      Assert(has(layout.strain), ExcMessage("The batch has no strains."));
      return Utils::read_symmetric<dim>(point(i) + layout.strain);
    }

    /// The model's committed fields of point @p i.
    ArrayView<const double>
    state(const unsigned int i) const
    {
      Assert(has(layout.state) || layout.n_state == 0,
             ExcMessage("The batch has no model fields."));
      return {point(i) + layout.state, layout.n_state};
    }

  private:
    static SymmetricTensor<2, dim>
    nan_tensor()
    {
      SymmetricTensor<2, dim> t;
      for (unsigned int k = 0; k < t.n_independent_components; ++k)
        t.access_raw_entry(k) = std::numeric_limits<double>::quiet_NaN();
      return t;
    }

    static bool
    has(const unsigned int offset)
    {
      return offset != numbers::invalid_unsigned_int;
    }

    const double *
    point(const unsigned int i) const
    {
      return properties != nullptr ? properties[i] : first + i * stride;
    }

    const Layout        &layout;
    const double *const *properties = nullptr;
    const double        *first      = nullptr;
    const unsigned int   stride     = 0;
    const Point<dim>    *positions;
    const unsigned int   n;
  };
} // namespace qsmpm

#endif
