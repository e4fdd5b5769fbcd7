#include "app/staged_outputs.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "app/exit_code.h"
#include "materials/core/quoted.h"
#include "materials/core/temporary_files.h"

namespace scatterlab {

namespace fs = std::filesystem;

namespace {

// The name inside a directory output under which its files are staged (.scatterlab.partial-PID).
constexpr const char* StagingStem = "scatterlab";

fs::path directoryOf(const fs::path& file) {
  return file.parent_path().empty() ? fs::path(".") : file.parent_path();
}

std::string errnoText() { return std::strerror(errno); }

// One rename of the commit, and the hard link that keeps the old file until all succeeded.
struct Move {
  const std::string* option;
  fs::path from, to, backup;
  bool existed = false;
};

}  // namespace

StagedOutputs::StagedOutputs(std::vector<InputPath> inputs) : inputs_(std::move(inputs)) {}

void StagedOutputs::addFile(const std::string& option, const fs::path& target, const std::string& example) {
  if (prepared_) throw std::logic_error("StagedOutputs::addFile after prepare()");
  const std::string allowed = "; allowed: a file path, e.g. " + example;
  const std::string text = target.string();
  if (text.empty()) throw InputError(option + ": missing" + allowed);
  if (text.back() == '/')
    throw InputError(option + ": " + inQuotes(text) + " ends in '/', which names a directory" + allowed);
  std::error_code error;
  const fs::file_status status = fs::status(target, error);
  if (fs::is_directory(status))
    throw InputError(option + ": " + inQuotes(text) + " is a directory" + allowed);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(option + ": " + inQuotes(text) +
                     " exists and is not a regular file (a device, pipe or socket)" + allowed);
  for (const Output& output : outputs_)
    if (!output.directory &&
        fs::absolute(output.target).lexically_normal() == fs::absolute(target).lexically_normal())
      throw InputError(option + ": " + inQuotes(text) + " is written twice" + allowed);
  refuseOutputOverInputs(option, target, OutputKind::File, inputs_);
  outputs_.push_back({option, target, false, {}});
}

void StagedOutputs::addDirectory(const std::string& option, const fs::path& target,
                                 std::vector<std::string> suffixes) {
  if (prepared_) throw std::logic_error("StagedOutputs::addDirectory after prepare()");
  const std::string allowed = "; allowed: a directory, or a path where one can be created";
  if (target.empty()) throw InputError(option + ": an empty path" + allowed);
  std::error_code error;
  const fs::file_status status = fs::status(target, error);
  if (fs::exists(status) && !fs::is_directory(status))
    throw InputError(option + ": " + inQuotes(target.string()) + " exists and is not a directory" + allowed);
  refuseOutputOverInputs(option, target, OutputKind::FilesInDirectory, inputs_, suffixes);
  outputs_.push_back({option, target, true, {}});
}

void StagedOutputs::prepare() {
  for (Output& output : outputs_) {
    const fs::path directory = output.directory ? output.target : directoryOf(output.target);
    createOutputDirectory(output.option, directory);
    if (output.directory) {
      removeStaleTemporaries(output.target / StagingStem);
      std::error_code error;
      output.staging = createTemporaryDirectory(
          output.target / ("." + std::string(StagingStem) + ".partial-" + std::to_string(getpid())), error);
      if (error)
        throw InputError(output.option + ": cannot write in the directory " + inQuotes(directory.string()) +
                         " (" + error.message() + "); allowed: a writable directory");
      continue;
    }
    removeStaleTemporaries(output.target);
    fs::path name = output.target;
    name += temporarySuffix();
    const auto interruptions = deferInterruptions();  // registered whenever it exists
    output.staging = TemporaryPath(name);
    ::unlink(name.c_str());
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0)
      throw InputError(output.option + ": cannot write in the directory " + inQuotes(directory.string()) +
                       " (" + errnoText() + "); allowed: a file path in a writable directory");
    ::close(fd);
  }
  prepared_ = true;
}

const StagedOutputs::Output& StagedOutputs::find(const fs::path& target) const {
  for (const Output& output : outputs_)
    if (output.target == target) return output;
  throw std::logic_error("StagedOutputs: " + target.string() + " was not added");
}

fs::path StagedOutputs::staged(const fs::path& target) const {
  if (!prepared_) throw std::logic_error("StagedOutputs::staged before prepare()");
  return find(target).staging.path();
}

void StagedOutputs::commit() {
  if (!prepared_) throw std::logic_error("StagedOutputs::commit before prepare()");
  const auto interruptions = deferInterruptions();
  std::vector<Move> moves;
  for (const Output& output : outputs_) {
    if (!output.directory) {
      moves.push_back({&output.option, output.staging.path(), output.target, {}});
      continue;
    }
    std::error_code error;
    for (fs::directory_iterator it(output.staging.path(), error), end; !error && it != end;
         it.increment(error))
      moves.push_back({&output.option, it->path(), output.target / it->path().filename(), {}});
  }
  // Keep every old file under a second name until the new set is complete.
  for (Move& move : moves) {
    fs::path backup = move.to;
    backup += temporarySuffix() + "-old";
    ::unlink(backup.c_str());
    move.existed = ::access(move.to.c_str(), F_OK) == 0;
    if (move.existed && ::link(move.to.c_str(), backup.c_str()) == 0) move.backup = backup;
  }
  for (size_t i = 0; i < moves.size(); ++i) {
    if (::rename(moves[i].from.c_str(), moves[i].to.c_str()) == 0) continue;
    const std::string reason = errnoText();
    for (size_t j = 0; j < i; ++j) {
      if (!moves[j].backup.empty())
        ::rename(moves[j].backup.c_str(), moves[j].to.c_str());
      else if (!moves[j].existed)
        ::unlink(moves[j].to.c_str());
      // (an old file that could not be linked is replaced already; the file system has no
      // hard links, which every Linux file system for home directories has)
    }
    for (const Move& move : moves)
      if (!move.backup.empty()) ::unlink(move.backup.c_str());
    throw InputError(*moves[i].option + ": cannot move the finished " + inQuotes(moves[i].to.string()) +
                     " into place (" + reason + "); the previous files are unchanged");
  }
  for (const Move& move : moves)
    if (!move.backup.empty()) ::unlink(move.backup.c_str());
  for (Output& output : outputs_) {
    if (output.directory)
      output.staging.remove();  // empty now
    else
      output.staging.keep();
  }
}

void createOutputDirectory(const std::string& option, const fs::path& directory, const std::string& allowed) {
  std::error_code error;
  createDirectoriesUninterrupted(directory, error);
  if (error || !fs::is_directory(directory))
    throw InputError(option + ": cannot create the directory " + inQuotes(directory.string()) + " (" +
                     (error ? error.message() : "a file is in the way") + ")" + allowed);
}

}  // namespace scatterlab
