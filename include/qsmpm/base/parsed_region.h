#ifndef qsmpm_base_parsed_region_h
#define qsmpm_base_parsed_region_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>
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
   * Evaluate @p f at @p point with std::cerr silenced. deal.II compiles an
   * expression at its first evaluation and, for a syntax error or an
   * unknown variable, prints a five-line description to std::cerr before
   * it throws; the exception already holds the reason, and the user should
   * see one line that names the entry.
   */
  template <int dim>
  void
  evaluate_quietly(const Function<dim> &f,
                   const Point<dim>    &point,
                   Vector<double>      &values);

  /**
   * The region of space that the expression in x, y (and z) of a .prm entry
   * describes ("Cracking region", "Surface traction region", "Drained
   * surface region"), as a predicate on points. The expression is parsed
   * and evaluated at the origin here (evaluate_quietly()), so that a
   * mistake in it stops the run at once with one line: "<@p entry> =
   * <expression>: what the parser found (an expression in x, y, non-zero
   * @p meaning)."
   */
  template <int dim>
  std::function<bool(const Point<dim> &)>
  parse_region(const std::string &expression,
               const std::string &entry,
               const std::string &meaning,
               const RegionTest   test = RegionTest::nonzero);
} // namespace qsmpm

#endif
