#include <deal.II/base/function_parser.h>
#include <iostream>
#include <memory>
#include <qsmpm/base/parsed_region.h>
#include <qsmpm/base/utilities.h>
#include <sstream>

namespace qsmpm
{
  template <int dim>
  std::function<bool(const Point<dim> &)>
  parse_region(const std::string &expression,
               const std::string &entry,
               const std::string &meaning,
               const RegionTest   test)
  {
    auto parser = std::make_shared<FunctionParser<dim>>(1);
    // muparser prints its own report to std::cerr before deal.II throws:
    // the user should see one line that names the entry.
    std::ostringstream    swallowed;
    std::streambuf *const original = std::cerr.rdbuf(swallowed.rdbuf());
    try
      {
        parser->initialize(FunctionParser<dim>::default_variable_names(),
                           expression,
                           {});
        parser->value(Point<dim>());
        std::cerr.rdbuf(original);
      }
    catch (const std::exception &exc)
      {
        std::cerr.rdbuf(original);
        AssertThrow(
          false,
          ExcMessage(
            entry + " = <" + expression + ">: " + Utils::error_message(exc) +
            " (an expression in " + (dim == 2 ? "x, y" : "x, y, z") + ", " +
            (test == RegionTest::nonzero ? "non-zero" : "greater than 1/2") +
            " " + meaning + ")."));
      }
    if (test == RegionTest::nonzero)
      return [parser](const Point<dim> &x) { return parser->value(x) != 0.; };
    return [parser](const Point<dim> &x) { return parser->value(x) > 0.5; };
  }



  template std::function<bool(const Point<2> &)>
  parse_region<2>(const std::string &,
                  const std::string &,
                  const std::string &,
                  RegionTest);
  template std::function<bool(const Point<3> &)>
  parse_region<3>(const std::string &,
                  const std::string &,
                  const std::string &,
                  RegionTest);
} // namespace qsmpm
