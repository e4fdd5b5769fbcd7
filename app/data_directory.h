// Where the executable finds the data it reads at run time (the lab's default environment maps):
// beside itself, never in the source tree, so an installed scatterlab works anywhere.
#pragma once

#include <filesystem>
#include <string>

namespace scatterlab {

// The data directory: PREFIX/share/scatterlab for an executable installed as PREFIX/bin (the
// relative path comes from the install layout, app/CMakeLists.txt), found from the path of the
// running executable (/proc/self/exe). The build tree mirrors that layout. Throws InputError
// naming the directory and `neededFor` when it does not exist.
std::filesystem::path runtimeDataDirectory(const std::string& neededFor);

}  // namespace scatterlab
