#ifndef qsmpm_base_parsed_region_h
#define qsmpm_base_parsed_region_h

#include <deal.II/base/point.h>
#include <functional>
#include <string>

namespace qsmpm
{
  using namespace dealii;

  /// Which values of a region's expression are inside it.
  enum class RegionTest
  {
    /// Every value but 0 (a condition such as "x > 5.99" is 1 or 0).
    nonzero,
    /// Values above 1/2 (the same for a condition).
    above_one_half
  };

  /**
   * The region of space that the expression in x, y (and z) of a .prm entry
   * describes ("Cracking region", "Surface traction region", "Drained
   * surface region"), as a predicate on points. The expression is parsed
   * and evaluated at the origin here, so that a mistake in it stops the
   * run at once with one line: "<@p entry> = <expression>: what the parser
   * found (an expression in x, y, non-zero @p meaning)." (muparser's own
   * report on the standard error is swallowed).
   */
  template <int dim>
  std::function<bool(const Point<dim> &)>
  parse_region(const std::string &expression,
               const std::string &entry,
               const std::string &meaning,
               const RegionTest   test = RegionTest::nonzero);
} // namespace qsmpm

#endif
