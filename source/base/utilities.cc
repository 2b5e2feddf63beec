#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <qsmpm/base/mpi_transport.h>
#include <qsmpm/base/parameter_file.h>
#include <qsmpm/base/utilities.h>

#ifdef __GLIBC__
#  include <malloc.h>
#endif

namespace qsmpm
{
  namespace
  {
    /// Open MPI's start-up settings, before main() and with it MPI_Init().
    [[maybe_unused]] const Utils::MpiStartup mpi_startup_chosen =
      Utils::choose_mpi_startup();
  } // namespace



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
      // Drop separator lines of dashes.
      for (auto dashes = text.find("---"); dashes != std::string::npos;
           dashes      = text.find("---"))
        text.erase(dashes, text.find_first_not_of('-', dashes) - dashes);

      // The message may quote the text of a file: ParameterHandler quotes
      // a line it cannot parse, or the value or name of an entry, and a
      // binary file would send its bytes to the terminal. What the user
      // sees is a printable excerpt on one line: white space folded into
      // single blanks, every byte that is neither printable ASCII nor part
      // of a printable UTF-8 character (code point U+00A0 or higher; the
      // C1 controls U+0080-U+009F are terminal commands) replaced by '?',
      // each quotation <...> longer than 80 characters cut to its start
      // and end, and a message still longer than 600 characters (a quoted
      // line may itself hold '<' and '>') to its first 330 and last 220
      // characters, which keep where the error is and what it is.
      std::string printable;
      bool        space = false;
      for (std::size_t i = 0; i < text.size();)
        {
          const unsigned char c = text[i];
          if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
              c == '\f')
            {
              space = !printable.empty();
              ++i;
              continue;
            }
          if (space)
            printable += ' ';
          space = false;
          if (c >= 0x21 && c < 0x7f)
            {
              printable += static_cast<char>(c);
              ++i;
              continue;
            }
          // A UTF-8 sequence: the length from its first byte, then the
          // continuation bytes and the code point (shortest form only).
          const std::size_t length = (c >= 0xc2 && c <= 0xdf) ? 2 :
                                     (c >= 0xe0 && c <= 0xef) ? 3 :
                                     (c >= 0xf0 && c <= 0xf4) ? 4 :
                                                                0;
          unsigned long     code   = length == 2 ? (c & 0x1f) :
                                     length == 3 ? (c & 0x0f) :
                                                   (c & 0x07);
          bool              valid  = length > 0 && i + length <= text.size();
          for (std::size_t k = 1; valid && k < length; ++k)
            {
              const unsigned char next = text[i + k];
              valid                    = (next & 0xc0) == 0x80;
              code                     = (code << 6) | (next & 0x3f);
            }
          valid = valid && code >= 0xa0 && (length < 3 || code >= 0x800) &&
                  (code < 0xd800 || code > 0xdfff) &&
                  (length < 4 || (code >= 0x10000 && code <= 0x10ffff));
          if (valid)
            {
              printable += text.substr(i, length);
              i += length;
            }
          else
            {
              printable += '?';
              ++i;
            }
        }

      // Long quotations: the first 50 and the last 25 characters (bytes;
      // a cut is moved off UTF-8 continuation bytes).
      const auto boundary = [](const std::string &s, std::size_t i) {
        while (i < s.size() &&
               (static_cast<unsigned char>(s[i]) & 0xc0) == 0x80)
          ++i;
        return i;
      };
      std::string result;
      for (std::size_t i = 0; i < printable.size();)
        {
          const std::size_t open  = printable.find('<', i);
          const std::size_t close = open == std::string::npos ?
                                      std::string::npos :
                                      printable.find('>', open + 1);
          if (close == std::string::npos)
            {
              result += printable.substr(i);
              break;
            }
          result += printable.substr(i, open + 1 - i);
          const std::string quote =
            printable.substr(open + 1, close - open - 1);
          if (quote.size() > 80)
            {
              const std::size_t head = boundary(quote, 50),
                                tail = boundary(quote, quote.size() - 25);
              result += quote.substr(0, head) + " ... " + quote.substr(tail);
            }
          else
            result += quote;
          result += '>';
          i = close + 1;
        }
      if (result.size() > 600)
        result = result.substr(0, boundary(result, 330)) + " ... " +
                 result.substr(boundary(result, result.size() - 220));
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


    bool
    run_gnuplot(const std::string &script)
    {
      return std::system("command -v gnuplot > /dev/null 2>&1") == 0 &&
             std::system(("gnuplot " + script).c_str()) == 0;
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



    void
    release_free_heap()
    {
#ifdef __GLIBC__
      malloc_trim(0);
#endif
    }
  } // namespace Utils
} // namespace qsmpm
