#include "materials/core/atomic_file.h"

#include <fstream>
#include <stdexcept>
#include <string>

#include "materials/core/temporary_files.h"

namespace scatterlab {

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temporary)>& write) {
  std::filesystem::path name = path;
  name += temporarySuffix();
  TemporaryPath temporary(name);  // removed on an exception or an interruption
  write(temporary.path());
  std::filesystem::rename(temporary.path(), path);
  temporary.keep();
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
