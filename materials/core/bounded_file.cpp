#include "materials/core/bounded_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "materials/core/quoted.h"

namespace scatterlab {

namespace {

// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string describeBytes(uintmax_t bytes) {
  if (bytes >= (uintmax_t(1) << 20) && bytes % (uintmax_t(1) << 20) == 0)
    return std::to_string(bytes >> 20) + " MB";
  if (bytes >= (uintmax_t(1) << 10) && bytes % (uintmax_t(1) << 10) == 0)
    return std::to_string(bytes >> 10) + " kB";
  return std::to_string(bytes) + " bytes";
}

std::string readFileBounded(const std::filesystem::path& path, uintmax_t maxBytes, const std::string& what) {
  const std::string name = what + " " + inQuotes(path.string());
  const auto fail = [&](const std::string& problem) -> std::string { throw InputFileError(name, problem); };
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0)
    fail(errno == ENOENT ? "not found" : std::string("not readable (") + std::strerror(errno) + ")");
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) fail(std::string("not readable (") + std::strerror(errno) + ")");
  if (S_ISDIR(status.st_mode)) fail("is a directory, not a file");
  const std::string limit = ", more than the " + describeBytes(maxBytes) + " allowed";
  if (S_ISREG(status.st_mode) && uintmax_t(status.st_size) > maxBytes)
    fail("is " + describeBytes(uintmax_t(status.st_size)) + limit);
  // Devices and pipes have no size: read, but never more than the limit.
  std::string contents;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t count = ::read(file.fd, buffer, sizeof buffer);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) fail(std::string("not readable (") + std::strerror(errno) + ")");
    if (count == 0) break;
    if (contents.size() + size_t(count) > maxBytes)
      fail("holds more than the " + describeBytes(maxBytes) + " allowed");
    contents.append(buffer, size_t(count));
  }
  return contents;
}

}  // namespace scatterlab
