#include "app/progress.h"
#include "app/format_number.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>

namespace scatterlab {

namespace {

constexpr auto RedrawInterval = std::chrono::milliseconds(100);
// Often enough to show a job is alive, rarely enough that a log stays readable.
constexpr auto LineInterval = std::chrono::seconds(5);
constexpr double AnnounceAboveSeconds = 60.0;

std::atomic<ProgressMode> mode{ProgressMode::Automatic};

int terminalColumns() {
  winsize size{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

}  // namespace

void setProgressMode(ProgressMode m) { mode = m; }
bool progressIsQuiet() { return mode == ProgressMode::Quiet; }

std::string describeDuration(double seconds) {
  if (!std::isfinite(seconds)) return "forever";
  if (seconds < 90) return formatNumber("%.2g s", seconds);
  if (seconds < 90 * 60) return formatNumber("%.0f min", seconds / 60);
  if (seconds < 48 * 3600) return formatNumber("%.1f h", seconds / 3600);
  if (seconds < 3 * 365 * 86400.0) return formatNumber("%.0f days", seconds / 86400);
  return formatNumber("%.2g years", seconds / (365 * 86400.0));
}

std::string describeMemory(double bytes) {
  if (bytes >= 1e9) return formatNumber("%.3g GB", bytes / 1e9);
  if (bytes >= 1e6) return formatNumber("%.3g MB", bytes / 1e6);
  return formatNumber("%.3g kB", bytes / 1e3);
}

void announceWork(const WorkEstimate& estimate) {
  if (progressIsQuiet() || !(estimate.seconds > AnnounceAboveSeconds)) return;
  std::fprintf(stderr,
               "scatterlab: %s: about %s and %s of memory (an estimate for this machine); progress "
               "follows on stderr, Ctrl-C stops it and leaves no partial file\n",
               estimate.what.c_str(), describeDuration(estimate.seconds).c_str(),
               describeMemory(estimate.bytes).c_str());
  std::fflush(stderr);
}

ProgressLine::ProgressLine()
    : style_(progressIsQuiet()            ? Style::Off
             : isatty(STDERR_FILENO) == 1 ? Style::Terminal
                                          : Style::Lines) {
  start_ = lastDraw_ = stageStart_ = std::chrono::steady_clock::now();
}

ProgressLine::~ProgressLine() { clear(); }

ProgressCallback ProgressLine::callback(std::string prefix) {
  if (!enabled()) return {};
  return [this, prefix = std::move(prefix)](const std::string& stage, double fraction) {
    draw(stage.empty() ? prefix : prefix + " " + stage, fraction);
  };
}

WalkProgress ProgressLine::walkCallback(std::string prefix) {
  if (!enabled()) return {};
  return [this, prefix = std::move(prefix)](double fraction) { draw(prefix, fraction); };
}

void ProgressLine::draw(const std::string& text, double fraction) {
  const std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  // A stage is the text before its bar: the bar changes with every call, the stage does not.
  if (const std::string stage = text.substr(0, text.find(" [")); stage != stage_) {
    stage_ = stage;
    stageStart_ = now;
  }
  const int percent = static_cast<int>(std::lround(100.0 * std::clamp(fraction, 0.0, 1.0)));
  if (style_ == Style::Lines) {
    // A log line every few seconds: how far, how long so far, about how long still.
    lastText_ = text;
    if (now - lastDraw_ < LineInterval) return;
    lastDraw_ = now;
    const double stage = std::chrono::duration<double>(now - stageStart_).count();
    std::string line = text + " " + std::to_string(percent) + "% (" +
                       describeDuration(std::chrono::duration<double>(now - start_).count()) + " so far";
    // Time left in this stage, once it has run long enough to extrapolate.
    if (stage >= 1.0 && fraction > 0.02 && fraction < 1.0)
      line += ", about " + describeDuration(stage * (1.0 - fraction) / fraction) + " left";
    std::fprintf(stderr, "%s)\n", line.c_str());
    std::fflush(stderr);
    return;
  }
  // Redrawing on every call would make the terminal, not the work, the bottleneck.
  if (text == lastText_ && now - lastDraw_ < RedrawInterval) return;
  lastText_ = text;
  lastDraw_ = now;
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
