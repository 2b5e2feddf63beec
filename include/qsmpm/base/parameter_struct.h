#ifndef qsmpm_base_parameter_struct_h
#define qsmpm_base_parameter_struct_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  namespace Utils
  {
    /**
     * The inverse of the name mangling of ParameterHandler's JSON and XML
     * output, which writes every character other than [a-zA-Z0-9] of a
     * name as _xx (hex).
     */
    std::string
    demangle(const std::string &name);

    /**
     * Call @p add_parameters on @p prm, which declares entries bound to the
     * members of @p owner (ParameterHandler::add_parameter()), and let @p prm
     * keep @p owner alive: parsing @p prm writes into it.
     */
    void
    declare_owned(ParameterHandler                              &prm,
                  const std::function<void(ParameterHandler &)> &add_parameters,
                  const std::shared_ptr<const void>             &owner);

    /**
     * Read the entries that @p add_parameters declares from @p prm (parsed,
     * at the subsection where they were declared) into the members they are
     * bound to: @p add_parameters declares them in a handler of its own,
     * where each is set to its value in @p prm, which converts the text as
     * parsing does.
     */
    void
    read_entries(const ParameterHandler                        &prm,
                 const std::function<void(ParameterHandler &)> &add_parameters);

    /**
     * ParameterHandler::add_parameter() for a member that takes one of a few
     * named values (an enum, or a bool named by a selection): the entry
     * @p entry with the pattern Patterns::Selection of the names in
     * @p choices (in that order), whose default is the name of the present
     * value of @p parameter, and which sets @p parameter to the value of
     * the name read.
     */
    template <typename T>
    void
    add_selection(ParameterHandler                             &prm,
                  const std::string                            &entry,
                  T                                            &parameter,
                  const std::vector<std::pair<std::string, T>> &choices,
                  const std::string                            &documentation)
    {
      std::string names, current;
      for (const auto &[name, value] : choices)
        {
          names += (names.empty() ? "" : "|") + name;
          if (value == parameter && current.empty())
            current = name;
        }
      prm.declare_entry(entry,
                        current,
                        Patterns::Selection(names),
                        documentation);
      prm.add_action(entry, [&parameter, choices](const std::string &text) {
        for (const auto &[name, value] : choices)
          if (name == text)
            parameter = value;
      });
    }
  } // namespace Utils



  /**
   * The base of a parameter struct in the manner of deal.II's step-68 and
   * ExaDG: @p Derived has a member function
   *
   *   void add_parameters(ParameterHandler &prm);
   *
   * that declares each of its entries once, with ParameterHandler::
   * add_parameter() (or Utils::add_selection()), bound to a member whose
   * initializer is the default. Parsing @p prm then writes into that
   * object, which must outlive the parse; a check() that needs several
   * entries (hiding the empty one here) is called after parse_input().
   *
   * For a handler that is declared before the object exists and parsed
   * into it later, this base adds the pair of functions that the programs
   * call:
   *  - declare_parameters(prm): the entries with their defaults (bound to a
   *    default object that @p prm owns);
   *  - parse_parameters(prm): read the parsed values into this object, then
   *    check().
   */
  template <class Derived>
  struct ParameterStruct
  {
    /// Declare the entries of @p Derived with their defaults.
    static void
    declare_parameters(ParameterHandler &prm)
    {
      const auto defaults = std::make_shared<Derived>();
      Utils::declare_owned(
        prm,
        [&defaults](ParameterHandler &handler) {
          defaults->add_parameters(handler);
        },
        defaults);
    }

    /// Read the values of a parsed @p prm (declared with
    /// declare_parameters()) and check them.
    void
    parse_parameters(const ParameterHandler &prm)
    {
      Derived &self = static_cast<Derived &>(*this);
      Utils::read_entries(prm, [&self](ParameterHandler &handler) {
        self.add_parameters(handler);
      });
      self.check();
    }

    /// A @p Derived object with the values of a parsed @p prm.
    static Derived
    from(const ParameterHandler &prm)
    {
      Derived parameters;
      parameters.parse_parameters(prm);
      return parameters;
    }

    /// Checks after parsing that involve several entries: none.
    void
    check() const
    {
    }
  };
} // namespace qsmpm

#endif
