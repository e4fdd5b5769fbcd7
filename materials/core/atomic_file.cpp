#include "materials/core/atomic_file.h"

#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace scatterlab {

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temporary)>& write) {
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid());
  try {
    write(temporary);
    std::filesystem::rename(temporary, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

void writeTextFileAtomically(const std::filesystem::path& path, std::string_view text) {
  writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out.write(text.data(), std::streamsize(text.size()));
    out.close();
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  });
}

}  // namespace scatterlab
