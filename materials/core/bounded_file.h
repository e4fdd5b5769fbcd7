// Reading a whole input file with a size limit (docs/reliability.md, "Limits"): the size is checked
// before anything is read, and the read stops at the limit, so /dev/zero, /dev/urandom or a
// huge file given by mistake costs at most `maxBytes` of memory, never the machine's.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace scatterlab {

// A file that cannot be read as an input; the message names it (`what` "PATH") and the
// problem: not found, a directory, not readable, larger than the limit. Callers add what is
// allowed.
class InputFileError : public std::runtime_error {
 public:
  InputFileError(const std::string& name, std::string problem)
      : std::runtime_error(name + ": " + problem), problem_(std::move(problem)) {}
  // The problem alone ("not found"), for callers that name the file their own way.
  const std::string& problem() const { return problem_; }

 private:
  std::string problem_;
};

// The file's contents, at most `maxBytes` of them; throws InputFileError otherwise. `what`
// names the kind of file in messages ("material file").
std::string readFileBounded(const std::filesystem::path& path, uintmax_t maxBytes, const std::string& what);

// "4 MB", "35 MB", "512 bytes": a size for messages.
std::string describeBytes(uintmax_t bytes);

}  // namespace scatterlab
