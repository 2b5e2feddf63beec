#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <qsmpm/base/parameter_struct.h>
#include <sstream>

namespace qsmpm
{
  namespace Utils
  {
    std::string
    demangle(const std::string &name)
    {
      std::string result;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size())
          {
            result.push_back(
              static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16)));
            i += 2;
          }
        else
          result.push_back(name[i]);
      return result;
    }



    namespace
    {
      /// An entry: the subsections that lead to it and its name.
      using EntryPath = std::pair<std::vector<std::string>, std::string>;

      void
      collect_entries(const boost::property_tree::ptree &node,
                      std::vector<std::string>          &path,
                      std::vector<EntryPath>            &entries)
      {
        for (const auto &[key, child] : node)
          if (child.get_child_optional("value"))
            entries.emplace_back(path, demangle(key));
          else if (!child.empty())
            {
              path.push_back(demangle(key));
              collect_entries(child, path, entries);
              path.pop_back();
            }
      }

      /// The entries that @p add_parameters declares, relative to where
      /// it is called.
      std::vector<EntryPath>
      declared_entries(ParameterHandler &handler)
      {
        std::stringstream json;
        handler.print_parameters(json, ParameterHandler::JSON);
        boost::property_tree::ptree tree;
        boost::property_tree::read_json(json, tree);
        std::vector<std::string> path;
        std::vector<EntryPath>   entries;
        collect_entries(tree, path, entries);
        return entries;
      }

      /// Call @p action on @p prm inside the subsections @p path.
      void
      in_subsections(ParameterHandler               &prm,
                     const std::vector<std::string> &path,
                     const std::function<void()>    &action)
      {
        for (const auto &subsection : path)
          prm.enter_subsection(subsection);
        action();
        for (std::size_t i = 0; i < path.size(); ++i)
          prm.leave_subsection();
      }
    } // namespace



    void
    declare_owned(ParameterHandler                              &prm,
                  const std::function<void(ParameterHandler &)> &add_parameters,
                  const std::shared_ptr<const void>             &owner)
    {
      add_parameters(prm);
      // The handler owns nothing but its actions: one more, on the first
      // entry, holds the object the entries are bound to.
      ParameterHandler scratch;
      add_parameters(scratch);
      const auto entries = declared_entries(scratch);
      if (!entries.empty())
        in_subsections(prm, entries.front().first, [&]() {
          prm.add_action(entries.front().second,
                         [owner](const std::string &) {});
        });
    }



    void
    read_entries(const ParameterHandler                        &prm,
                 const std::function<void(ParameterHandler &)> &add_parameters)
    {
      ParameterHandler scratch;
      add_parameters(scratch);
      for (const auto &[path, name] : declared_entries(scratch))
        {
          const std::string value = prm.get(path, name);
          in_subsections(scratch, path, [&]() { scratch.set(name, value); });
        }
    }
  } // namespace Utils
} // namespace qsmpm
