#ifndef qsmpm_base_parameter_file_h
#define qsmpm_base_parameter_file_h

#include <string>

namespace qsmpm
{
  namespace Utils
  {
    /**
     * Throw an exception that names @p filename unless it is a readable
     * regular file. deal.II's ParameterHandler::parse_input() reports a
     * missing file, but opens a directory without complaint and reads it as
     * an empty file: a program would then run with the default of every
     * entry. The programs call this before they read a parameter file
     * (read_dimension() does too).
     */
    void
    check_parameter_file(const std::string &filename);
  } // namespace Utils
} // namespace qsmpm

#endif
