// Atomic file output (docs/design.md, "Atomic writes"): write to a temporary name in the same directory,
// then rename over the target, so a crash or an error never leaves a half-written file.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace scatterlab {

// Calls write(temporaryPath); on success renames it to `path`, on any exception removes it
// and rethrows. The directory of `path` must exist.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temporary)>& write);

// Convenience: the whole file from a string.
void writeTextFileAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace scatterlab
