#include "app/data_directory.h"

#include "app/exit_code.h"

#ifndef SCATTERLAB_DATA_FROM_EXECUTABLE
#error "SCATTERLAB_DATA_FROM_EXECUTABLE must name the data directory relative to the executable's"
#endif

namespace scatterlab {

namespace fs = std::filesystem;

fs::path runtimeDataDirectory(const std::string& neededFor) {
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (error)
    throw InputError("cannot find the running executable's path (/proc/self/exe: " + error.message() +
                     "), which locates " + neededFor);
  const fs::path directory = (executable.parent_path() / SCATTERLAB_DATA_FROM_EXECUTABLE).lexically_normal();
  if (!fs::is_directory(directory, error))
    throw InputError("the data directory \"" + directory.string() +
                     "\" (" SCATTERLAB_DATA_FROM_EXECUTABLE " from the executable " + executable.string() +
                     ") does not exist; it holds " + neededFor +
                     "; allowed: scatterlab run as installed (cmake --install) or from its build tree");
  return directory;
}

}  // namespace scatterlab
