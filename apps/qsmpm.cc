// The general driver: runs any quasi-static problem described by a .prm file.
//
//   qsmpm problem.prm                       run it
//   qsmpm --resume problem.prm              continue from the newest
//                                           checkpoint in the output
//                                           directory (Output/Checkpoint
//                                           interval, doc/restart.md)
//   qsmpm --plugin libmodel.so problem.prm  load user models first
//   qsmpm --print-parameters                every parameter, its default and
//                                           documentation
//   qsmpm --print-parameters-markdown       the same as Markdown (the
//                                           source of doc/parameters.md)
//   qsmpm --version                         qsmpm and deal.II versions
//
// Plugins are shared libraries with user-defined constitutive models (see
// doc/user_models.md): dlopen() runs their static initializers, which
// register the models (QSMPM_REGISTER_CONSTITUTIVE_MODEL), so they must be
// loaded before the parameters are declared. --plugin may be repeated and
// may come before or after the options above.
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <deal.II/base/config.h>
#include <deal.II/base/mpi.h>
#include <dlfcn.h>
#include <filesystem>
#include <iostream>
#include <map>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/base/version.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;

  const char *const usage =
    "Usage: qsmpm [--plugin <library.so>]... [--resume] <file.prm>\n"
    "       qsmpm [--plugin <library.so>]... --print-parameters\n"
    "       qsmpm --version | --help\n"
    "\n"
    "  <file.prm>            run the problem described by the parameter "
    "file\n"
    "  --resume              continue from the newest checkpoint in the\n"
    "                        output directory (doc/restart.md)\n"
    "  --plugin <lib.so>     load a shared library with user-defined models\n"
    "                        before reading parameters (repeatable)\n"
    "  --print-parameters    print every parameter with its default and\n"
    "                        documentation (with the plugins' models)\n"
    "  --print-parameters-markdown\n"
    "                        the same as a Markdown page (doc/parameters.md)\n"
    "  --version             print the versions of qsmpm and deal.II\n";

  template <int dim>
  void
  declare(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the problem: 2 or 3.");
    qsmpm::QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
  }

  template <int dim>
  void
  run(const std::string &filename, const bool resume)
  {
    ParameterHandler prm;
    declare<dim>(prm);
    prm.parse_input(filename);
    qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    problem.return_large_blocks_to_system();
    problem.initialize(prm);
    if (resume)
      problem.resume();
    problem.run();
  }

  /**
   * Text on one line, for a Markdown list item, with the characters that
   * Markdown would interpret (emphasis, code, HTML tags, links) escaped.
   */
  std::string
  markdown_text(const std::string &text)
  {
    std::string result;
    for (const char c : text)
      if (c == '\n' || c == '\t')
        result.push_back(' ');
      else
        {
          if (std::string("\\`*_<>[]|").find(c) != std::string::npos)
            result.push_back('\\');
          result.push_back(c);
        }
    return result;
  }



  /**
   * Write the entries of @p node (a subsection of the XML tree printed by
   * ParameterHandler) and then, recursively, its subsections, each under a
   * heading with its full path.
   */
  void
  write_markdown(const boost::property_tree::ptree &node,
                 const std::string                 &path,
                 std::ostream                      &out)
  {
    bool heading = false;
    for (const auto &[key, child] : node)
      if (child.get_child_optional("value"))
        {
          if (!heading)
            {
              out << '\n'
                  << (path.empty() ? "## Top level" : "## `" + path + "`")
                  << "\n\n";
              heading = true;
            }
          const auto value = child.get<std::string>("default_value");
          out << "- **" << markdown_text(qsmpm::Utils::demangle(key))
              << "** = " << (value.empty() ? "*(empty)*" : "`" + value + "`")
              << "  \n"
              << "  *"
              << markdown_text(child.get<std::string>("pattern_description"))
              << "*";
          const auto documentation = child.get<std::string>("documentation");
          if (!documentation.empty())
            out << "  \n  " << markdown_text(documentation);
          out << '\n';
        }
    for (const auto &[key, child] : node)
      if (!child.get_child_optional("value"))
        write_markdown(child,
                       (path.empty() ? "" : path + "/") +
                         qsmpm::Utils::demangle(key),
                       out);
  }

  /// The parameter reference doc/parameters.md (2D, the registered models).
  void
  print_markdown(ParameterHandler &prm, std::ostream &out)
  {
    std::stringstream xml;
    prm.print_parameters(xml, ParameterHandler::XML);
    boost::property_tree::ptree tree;
    boost::property_tree::read_xml(xml, tree);
    out << "# Parameter reference\n\n"
        << "Every entry of a qsmpm parameter file, by subsection: its "
           "default value, the\nvalues it accepts and its documentation, "
           "for `set Dimension = 2` (in 3D\nlists of coordinates have three "
           "components) and the models built into\nqsmpm "
        << QSMPM_VERSION
        << " (with `--plugin`, the driver also lists the plugins' "
           "models).\n\n"
        << "Generated by `qsmpm --print-parameters-markdown`; do not edit, "
           "run\n`make parameter_reference` in the build directory after "
           "changing a\ndeclaration (the test `parameter_reference` "
           "checks that this page is\nup to date).\n";
    write_markdown(tree.get_child("ParameterHandler"), "", out);
  }

  /**
   * The parameters in the format of a .prm file (ParameterHandler::PRM),
   * with long documentation printed once. The three function subsections
   * of <Boundary conditions> (Body force, Displacement, Traction) are
   * deal.II's ParsedFunction, whose entries carry some 35 lines of
   * documentation of the function parser each; a documentation of more
   * than four lines that has been printed already is replaced by a line
   * that refers to the entry where it was printed.
   *
   * The text that ParameterHandler prints is a sequence of comment lines
   * ("# ...") followed by the "set" line of the entry they document, and
   * "subsection"/"end" lines, all indented by their depth.
   */
  void
  print_prm(const ParameterHandler &prm, std::ostream &out)
  {
    std::stringstream text;
    prm.print_parameters(text, ParameterHandler::PRM);

    std::vector<std::string>           path;
    std::map<std::string, std::string> printed; // documentation -> entry
    std::vector<std::string>           comment;
    std::string                        documentation;
    const auto                         trimmed = [](const std::string &line) {
      const auto first = line.find_first_not_of(' ');
      return first == std::string::npos ? std::string() : line.substr(first);
    };
    std::string line;
    while (std::getline(text, line))
      {
        const std::string content = trimmed(line);
        const std::string indent = line.substr(0, line.size() - content.size());
        // The header "# Listing of Parameters" is a comment at depth 0 that
        // no "set" line follows directly; it is short and passes through.
        if (content.rfind('#', 0) == 0)
          {
            comment.push_back(line);
            documentation += content + '\n';
            continue;
          }
        if (content.rfind("set ", 0) == 0 && comment.size() > 4)
          {
            std::string name = content.substr(4, content.find('=') - 4);
            name             = name.substr(0, name.find_last_not_of(' ') + 1);
            std::string where;
            for (const auto &p : path)
              where += (where.empty() ? "" : "/") + p;
            const auto [first, inserted] =
              printed.emplace(documentation,
                              "<" + name + "> of subsection <" + where + ">");
            if (!inserted)
              comment = {indent + "# As " + first->second + " above."};
          }
        for (const auto &c : comment)
          out << c << '\n';
        comment.clear();
        documentation.clear();
        if (content.rfind("subsection ", 0) == 0)
          path.push_back(content.substr(11));
        else if (content == "end" && !path.empty())
          path.pop_back();
        out << line << '\n';
      }
    for (const auto &c : comment)
      out << c << '\n';
  }



  /**
   * dlopen() a plugin with RTLD_NOW | RTLD_GLOBAL (all symbols resolved now,
   * so that a missing one is reported here and not in the middle of a run).
   * A name that exists as a file is opened as that file (dlopen() alone
   * would search only the library path for a name without a '/'); any
   * other name is left to the library search (LD_LIBRARY_PATH, RPATH).
   * The library is never closed: the registry keeps its factory functions.
   */
  void
  load_plugin(const std::string &name)
  {
    std::string path = name;
    if (name.find('/') == std::string::npos && std::filesystem::exists(name))
      path = "./" + name;
    dlerror();
    if (dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL) == nullptr)
      {
        const char *reason = dlerror();
        AssertThrow(false,
                    ExcMessage("Cannot load the plugin <" + name + ">: " +
                               (reason != nullptr ? reason : "unknown error")));
      }
  }
} // namespace

int
main(int argc, char *argv[])
{
  // The rank of this process, for the catch blocks below: by the time they
  // run, the MPI_InitFinalize object of the try block is gone, and MPI with
  // it.
  unsigned int rank = 0;
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      rank            = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const bool root = rank == 0;

      // The command line: options and at most one parameter file.
      std::vector<std::string> plugins;
      std::string              action, filename;
      bool                     resume = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string argument = argv[i];
          if (argument == "--plugin")
            {
              AssertThrow(i + 1 < argc,
                          ExcMessage("--plugin needs a library name."));
              plugins.emplace_back(argv[++i]);
            }
          else if (argument == "--resume")
            resume = true;
          else if (argument.rfind("--plugin=", 0) == 0)
            plugins.push_back(argument.substr(9));
          else if (argument == "--help" || argument == "-h" ||
                   argument == "--version" ||
                   argument == "--print-parameters" ||
                   argument == "--print-parameters-markdown")
            action = argument;
          else if (!argument.empty() && argument[0] == '-')
            {
              if (root)
                std::cerr << "qsmpm: unknown option <" << argument << ">\n"
                          << usage;
              return 1;
            }
          else if (filename.empty())
            filename = argument;
          else
            {
              if (root)
                std::cerr << "qsmpm: more than one parameter file (<"
                          << filename << ">, <" << argument << ">)\n"
                          << usage;
              return 1;
            }
        }

      if (action == "--help" || action == "-h" ||
          (action.empty() && filename.empty()))
        {
          if (root)
            std::cout << usage;
          return action.empty() ? 1 : 0;
        }
      if (action == "--version")
        {
          if (root)
            std::cout << "qsmpm " << QSMPM_VERSION << " (deal.II "
                      << DEAL_II_PACKAGE_VERSION << ")" << std::endl;
          return 0;
        }

      for (const auto &plugin : plugins)
        load_plugin(plugin);

      if (action == "--print-parameters")
        {
          ParameterHandler prm;
          declare<2>(prm);
          if (root)
            print_prm(prm, std::cout);
          return 0;
        }
      if (action == "--print-parameters-markdown")
        {
          ParameterHandler prm;
          declare<2>(prm);
          if (root)
            print_markdown(prm, std::cout);
          return 0;
        }
      if (qsmpm::Utils::read_dimension(filename) == 2)
        run<2>(filename, resume);
      else
        run<3>(filename, resume);
    }
  catch (std::exception &exc)
    {
      // The errors of qsmpm are collective: every rank reads the same
      // parameter file and checks the same values, and a load step that
      // fails, fails on every rank with the same message (the library
      // broadcasts it). So one rank, rank 0, prints it, as one line
      // written at once: lines written piece by piece by several ranks
      // interleave ("qsmpm stopped: qsmpm stopped: ...").
      if (rank == 0)
        std::cerr << "qsmpm stopped: " + qsmpm::Utils::error_message(exc) + "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "qsmpm stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
