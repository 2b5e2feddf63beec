#include <deal.II/base/exceptions.h>
#include <dlfcn.h>
#include <qsmpm/materials/umat_library.h>

namespace qsmpm
{
  UmatFunction
  load_umat(const std::string &library, const std::string &symbol)
  {
    using dealii::ExcMessage;
    AssertThrow(!library.empty(),
                ExcMessage("Material/umat/UMAT library is empty: name the "
                           "shared library that contains the UMAT."));
    // A name without a slash would be searched for on the linker's path
    // only; a file in the working directory is what a user means by it.
    const std::string path =
      (library.find('/') == std::string::npos ? "./" : "") + library;
    void *handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr && path != library)
      handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
      {
        const char *reason = dlerror();
        AssertThrow(false,
                    ExcMessage(
                      "Material/umat/UMAT library: cannot load '" + library +
                      "' (" + (reason != nullptr ? reason : "unknown") + ")."));
      }
    dlerror();
    void *function = dlsym(handle, symbol.c_str());
    AssertThrow(function != nullptr,
                ExcMessage("Material/umat/Symbol: '" + library +
                           "' has no function '" + symbol +
                           "' (a Fortran SUBROUTINE UMAT compiled by "
                           "gfortran is umat_; see nm -D " +
                           library + ")."));
    return reinterpret_cast<UmatFunction>(function);
  }
} // namespace qsmpm
