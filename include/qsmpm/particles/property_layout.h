#ifndef qsmpm_particles_property_layout_h
#define qsmpm_particles_property_layout_h

#include <deal.II/numerics/data_component_interpretation.h>
#include <string>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * Named per-point properties: where in a particle's property array each
   * quantity lives. Every module asks the layout for an offset by name once,
   * instead of hard-coding magic offsets, so that constitutive models can add
   * their own fields (history variables, orientations, ...).
   */
  class PropertyLayout
  {
  public:
    /// How a field is shown in visualization output.
    enum class Kind
    {
      scalar,
      vector,   ///< dim components
      symmetric ///< a symmetric tensor in deal.II's unrolled order
    };

    /**
     * Append a field and return its offset. Names must be unique.
     */
    unsigned int
    add(const std::string &name,
        const unsigned int n_components,
        const Kind         kind);

    /// Offset of the field @p name; throws if there is none.
    unsigned int
    offset(const std::string &name) const;

    /// Whether a field called @p name exists.
    bool
    has(const std::string &name) const;

    /// Number of components of the field @p name.
    unsigned int
    n_components(const std::string &name) const;

    /// Total number of doubles per point.
    unsigned int
    size() const;

    /**
     * Names of all components for Particles::DataOut (vector fields repeat
     * their name, symmetric tensors are split into "stress_xx" etc.).
     */
    std::vector<std::string>
    component_names(const unsigned int dim) const;

    /// The matching interpretations for Particles::DataOut.
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    component_interpretations() const;

  private:
    struct Field
    {
      std::string  name;
      unsigned int offset;
      unsigned int n_components;
      Kind         kind;
    };

    const Field &
    find(const std::string &name) const;

    std::vector<Field> fields;
    unsigned int       total = 0;
  };
} // namespace qsmpm

#endif
