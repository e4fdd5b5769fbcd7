#include "materials/core/temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <map>

namespace scatterlab {

namespace fs = std::filesystem;

namespace {

// Never destroyed: an interruption may be handled while static objects are torn down at exit.
struct Registry {
  std::recursive_mutex mutex;     // a commit holds it while it unregisters what it renamed
  std::map<fs::path, int> paths;  // a path may be registered more than once (nested temporaries)
};
Registry& registry() {
  static Registry* instance = new Registry;
  return *instance;
}

void registerPath(const fs::path& path) {
  std::lock_guard lock(registry().mutex);
  ++registry().paths[path];
}

void unregisterPath(const fs::path& path) {
  std::lock_guard lock(registry().mutex);
  const auto found = registry().paths.find(path);
  if (found != registry().paths.end() && --found->second == 0) registry().paths.erase(found);
}

bool processIsGone(pid_t pid) { return pid > 0 && ::kill(pid, 0) == -1 && errno == ESRCH; }

// The PID in `rest` = "TAG-PID" (then nothing, or '.' or '-' and more) for TAG tmp or
// partial, else 0.
pid_t temporaryPid(std::string_view rest) {
  for (std::string_view tag : {"tmp-", "partial-"}) {
    if (!rest.starts_with(tag)) continue;
    rest.remove_prefix(tag.size());
    pid_t pid = 0;
    const char* last = rest.data() + rest.size();
    const auto [end, error] = std::from_chars(rest.data(), last, pid);
    if (error != std::errc() || end == rest.data() || (end != last && *end != '.' && *end != '-')) return 0;
    return pid;
  }
  return 0;
}

}  // namespace

void removeRegisteredTemporaries() {
  std::lock_guard lock(registry().mutex);
  for (const auto& [path, count] : registry().paths) {
    std::error_code error;
    if (!fs::is_directory(fs::symlink_status(path, error))) {
      fs::remove_all(path, error);
      continue;
    }
    // Other threads may go on writing into a staging directory. Renamed first, it can take no
    // new file under its old name; a file being created as it was renamed may still land in it,
    // which the next pass removes. The new name is a temporary of this process too
    // (NAME.partial-PID-removing), so a run after a crash here removes it as stale.
    fs::path doomed = path;
    doomed += "-removing";
    fs::rename(path, doomed, error);
    const fs::path& removed = error ? path : doomed;
    constexpr int Passes = 10;
    for (int pass = 0; pass < Passes; ++pass) {
      fs::remove_all(removed, error);
      if (!fs::exists(fs::symlink_status(removed, error))) break;
    }
  }
}

bool createDirectoriesUninterrupted(const fs::path& directory, std::error_code& error) {
  const auto lock = deferInterruptions();
  return fs::create_directories(directory, error);
}

void createDirectoriesUninterrupted(const fs::path& directory) {
  const auto lock = deferInterruptions();
  fs::create_directories(directory);
}

TemporaryPath::TemporaryPath(fs::path path) : path_(std::move(path)) { registerPath(path_); }

TemporaryPath::~TemporaryPath() { remove(); }

TemporaryPath::TemporaryPath(TemporaryPath&& other) noexcept : path_(std::move(other.path_)) {
  other.path_.clear();
}

TemporaryPath& TemporaryPath::operator=(TemporaryPath&& other) noexcept {
  if (this != &other) {
    remove();
    path_ = std::move(other.path_);
    other.path_.clear();
  }
  return *this;
}

void TemporaryPath::keep() {
  if (path_.empty()) return;
  unregisterPath(path_);
  path_.clear();
}

void TemporaryPath::remove() {
  if (path_.empty()) return;
  std::error_code ignored;
  fs::remove_all(path_, ignored);
  unregisterPath(path_);
  path_.clear();
}

TemporaryPath createTemporaryDirectory(const fs::path& path, std::error_code& error) {
  const auto lock = deferInterruptions();
  TemporaryPath directory(path);
  fs::remove_all(path, error);
  if (!fs::create_directory(path, error) && !error) error = std::make_error_code(std::errc::file_exists);
  return directory;
}

std::unique_lock<std::recursive_mutex> deferInterruptions() { return std::unique_lock(registry().mutex); }

std::string temporarySuffix() { return ".tmp-" + std::to_string(::getpid()); }

int removeStaleTemporaries(const fs::path& target) {
  const fs::path absolute = fs::absolute(target).lexically_normal();
  const std::string name = absolute.filename().string();
  if (name.empty()) return 0;
  int removed = 0;
  std::error_code error;
  for (fs::directory_iterator it(absolute.parent_path(), error), end; !error && it != end;
       it.increment(error)) {
    const std::string filename = it->path().filename().string();
    std::string_view entry = filename;
    if (entry.starts_with('.') && !name.starts_with('.')) entry.remove_prefix(1);
    if (!entry.starts_with(name) || entry.size() <= name.size() + 1 || entry[name.size()] != '.') continue;
    entry.remove_prefix(name.size() + 1);
    if (!processIsGone(temporaryPid(entry))) continue;
    std::error_code ignored;
    if (fs::remove_all(it->path(), ignored) > 0) ++removed;
  }
  return removed;
}

}  // namespace scatterlab
