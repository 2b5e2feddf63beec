#include <deal.II/base/function_parser.h>
#include <iostream>
#include <memory>
#include <qsmpm/base/parsed_region.h>
#include <qsmpm/base/utilities.h>
#include <sstream>

namespace qsmpm
{
  template <int dim>
  void
  evaluate_quietly(const Function<dim> &f,
                   const Point<dim>    &point,
                   Vector<double>      &values)
  {
    std::ostringstream    swallowed;
    std::streambuf *const original = std::cerr.rdbuf(swallowed.rdbuf());
    try
      {
        f.vector_value(point, values);
      }
    catch (...)
      {
        std::cerr.rdbuf(original);
        throw;
      }
    std::cerr.rdbuf(original);
  }



  template <int dim>
  std::function<bool(const Point<dim> &)>
  parse_region(const std::string &expression,
               const std::string &entry,
               const std::string &meaning,
               const RegionTest   test)
  {
    auto parser = std::make_shared<FunctionParser<dim>>(1);
    try
      {
        parser->initialize(FunctionParser<dim>::default_variable_names(),
                           expression,
                           {});
        Vector<double> value(1);
        evaluate_quietly<dim>(*parser, Point<dim>(), value);
      }
    catch (const std::exception &exc)
      {
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



  template void
  evaluate_quietly<2>(const Function<2> &, const Point<2> &, Vector<double> &);
  template void
  evaluate_quietly<3>(const Function<3> &, const Point<3> &, Vector<double> &);
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
