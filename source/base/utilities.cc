#include <algorithm>
#include <cctype>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <qsmpm/base/parameter_file.h>
#include <qsmpm/base/utilities.h>

#ifdef __GLIBC__
#  include <malloc.h>
#endif

namespace qsmpm
{
  namespace Utils
  {
    std::vector<std::string>
    split(const std::string &text, const char delimiter)
    {
      std::vector<std::string> out;
      for (const auto &piece :
           dealii::Utilities::split_string_list(text, delimiter))
        if (!piece.empty())
          out.push_back(piece);
      return out;
    }



    template <int dim>
    Point<dim>
    parse_point(const std::string &text, const std::string &what)
    {
      const auto pieces = split(text, ',');
      AssertThrow(pieces.size() == dim,
                  ExcMessage("The entry <" + what + "> = <" + text +
                             "> must have exactly " + std::to_string(dim) +
                             " comma-separated coordinates."));
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = dealii::Utilities::string_to_double(pieces[d]);
      return p;
    }



    template <int dim>
    std::array<bool, dim>
    parse_components(const std::string &text,
                     const std::string &what,
                     bool              &normal_only)
    {
      static const char     letters[3] = {'x', 'y', 'z'};
      std::array<bool, dim> mask;
      mask.fill(false);
      normal_only = (text == "n");
      if (normal_only)
        return mask;
      AssertThrow(!text.empty(),
                  ExcMessage("Empty component list in <" + what + ">."));
      for (const char c : text)
        {
          bool found = false;
          for (unsigned int d = 0; d < dim; ++d)
            if (c == letters[d])
              {
                mask[d] = true;
                found   = true;
              }
          AssertThrow(found,
                      ExcMessage("Unknown component <" + std::string(1, c) +
                                 "> in <" + what + "> = <" + text +
                                 ">: use letters from " +
                                 std::string(letters, dim) +
                                 ", or n for the normal component."));
        }
      return mask;
    }



    template <int dim>
    std::vector<std::string>
    symmetric_component_names()
    {
      static const char        letters[3] = {'x', 'y', 'z'};
      std::vector<std::string> names(n_symmetric_components<dim>);
      for (unsigned int i = 0; i < names.size(); ++i)
        {
          const auto ij =
            SymmetricTensor<2, dim>::unrolled_to_component_indices(i);
          names[i] = std::string(1, letters[ij[0]]) + letters[ij[1]];
        }
      return names;
    }



#define QSMPM_INSTANTIATE(dim)                                                 \
  template Point<dim>               parse_point<dim>(const std::string &,      \
                                       const std::string &);     \
  template std::array<bool, dim>    parse_components<dim>(const std::string &, \
                                                       const std::string &, \
                                                       bool &);             \
  template std::vector<std::string> symmetric_component_names<dim>();

    QSMPM_INSTANTIATE(2)
    QSMPM_INSTANTIATE(3)
#undef QSMPM_INSTANTIATE


    std::string
    error_message(const std::exception &exc)
    {
      std::string text = exc.what();
      const auto  pos  = text.find("Additional information:");
      if (pos != std::string::npos)
        text = text.substr(pos + 23);
      const auto end = text.find("Stacktrace:");
      if (end != std::string::npos)
        text = text.substr(0, end);
      // Drop separator lines of dashes, fold white space.
      for (auto dashes = text.find("---"); dashes != std::string::npos;
           dashes      = text.find("---"))
        text.erase(dashes, text.find_first_not_of('-', dashes) - dashes);
      std::string result;
      bool        space = false;
      for (const char c : text)
        if (std::isspace(static_cast<unsigned char>(c)))
          space = !result.empty();
        else
          {
            if (space)
              result += ' ';
            result += c;
            space = false;
          }
      return result;
    }



    void
    throw_if_any_rank(const std::string &message, const MPI_Comm communicator)
    {
      const unsigned int n_ranks =
        dealii::Utilities::MPI::n_mpi_processes(communicator);
      const unsigned int first =
        dealii::Utilities::MPI::min(message.empty() ?
                                      n_ranks :
                                      dealii::Utilities::MPI::this_mpi_process(
                                        communicator),
                                    communicator);
      if (first == n_ranks)
        return;
      const std::string text =
        dealii::Utilities::MPI::broadcast(communicator, message, first);
      AssertThrow(false, dealii::ExcMessage(text));
    }


    void
    check_parameter_file(const std::string &filename)
    {
      AssertThrow(std::filesystem::exists(filename),
                  ExcMessage("Cannot find the parameter file <" + filename +
                             ">."));
      AssertThrow(!std::filesystem::is_directory(filename),
                  ExcMessage("The parameter file <" + filename +
                             "> is a directory."));
      AssertThrow(std::ifstream(filename).good(),
                  ExcMessage("Cannot read the parameter file <" + filename +
                             ">."));
    }


    unsigned int
    read_dimension(const std::string &filename)
    {
      check_parameter_file(filename);
      unsigned int     dimension = 2;
      ParameterHandler prm;
      prm.add_parameter("Dimension",
                        dimension,
                        "Space dimension of the problem: 2 or 3.",
                        Patterns::Integer(2, 3));
      prm.parse_input(filename, "", /*skip_undefined=*/true);
      return dimension;
    }



    void
    return_large_blocks_to_system(const std::size_t smallest_block)
    {
#ifdef __GLIBC__
      // Setting a threshold also switches off glibc's own adjustment of it
      // (which would move every block of up to 32 MiB back to the heap
      // after the first one has been freed).
      const std::size_t threshold =
        std::clamp<std::size_t>(smallest_block, 128 << 10, 32 << 20);
      mallopt(M_MMAP_MAX, 65536); // glibc's default
      mallopt(M_MMAP_THRESHOLD, static_cast<int>(threshold));
      mallopt(M_TRIM_THRESHOLD, static_cast<int>(2 * threshold));
#else
      (void)smallest_block;
#endif
    }
  } // namespace Utils
} // namespace qsmpm
