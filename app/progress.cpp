#include "app/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace scatterlab {

namespace {

constexpr auto RedrawInterval = std::chrono::milliseconds(100);

int terminalColumns() {
  winsize size{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

}  // namespace

ProgressLine::ProgressLine() : enabled_(isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() { clear(); }

ProgressCallback ProgressLine::callback(std::string prefix) {
  if (!enabled_) return {};
  return [this, prefix = std::move(prefix)](const std::string& stage, double fraction) {
    draw(prefix + " " + stage, fraction);
  };
}

WalkProgress ProgressLine::walkCallback(std::string prefix) {
  if (!enabled_) return {};
  return [this, prefix = std::move(prefix)](double fraction) { draw(prefix, fraction); };
}

void ProgressLine::draw(const std::string& text, double fraction) {
  const std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  // Redrawing on every call would make the terminal, not the work, the bottleneck.
  if (text == lastText_ && now - lastDraw_ < RedrawInterval) return;
  lastText_ = text;
  lastDraw_ = now;
  const int percent = static_cast<int>(std::lround(100.0 * std::clamp(fraction, 0.0, 1.0)));
  constexpr size_t SuffixWidth = 5;  // " 100%"
  // Longer than the terminal, the line would wrap and \r could no longer overwrite it.
  const size_t room = static_cast<size_t>(std::max(terminalColumns() - 1, 10)) - SuffixWidth;
  const std::string shown = text.size() > room ? text.substr(0, room - 3) + "..." : text;
  std::fprintf(stderr, "\r\033[K%s %d%%", shown.c_str(), percent);
  std::fflush(stderr);
  visible_ = true;
}

void ProgressLine::clear() {
  const std::lock_guard lock(mutex_);
  if (!visible_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  visible_ = false;
  lastText_.clear();
}

}  // namespace scatterlab
