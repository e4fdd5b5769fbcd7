// Progress of long work, on stderr (stdout, with its tables and JSON, is never touched):
//  - on a terminal, one line redrawn in place ("check [1/2] gold chi2 45%");
//  - elsewhere (a log, a pipe, CI), a full line every few seconds with the time spent and
//    the time left, so that a long run in a batch job is not silent;
//  - with --quiet, nothing.
// Work expected to last more than a minute is announced before it starts (announceWork):
// what it is, about how long it takes and how much memory it needs.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

#include "validation/bsdf_check.h"
#include "validation/half_space_reference.h"

namespace scatterlab {

enum class ProgressMode { Automatic, Quiet };
// Set once from the command line (--quiet) before any work.
void setProgressMode(ProgressMode mode);
bool progressIsQuiet();

class ProgressLine {
 public:
  ProgressLine();
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool enabled() const { return style_ != Style::Off; }
  // A callback for the kit that shows "<prefix> <stage> <percent>"; empty with --quiet.
  ProgressCallback callback(std::string prefix);
  // A callback for the half-space walk (fraction only) that shows "<prefix> <percent>";
  // empty with --quiet.
  WalkProgress walkCallback(std::string prefix);
  // Erases the terminal line, so that what is printed next starts on a clean line.
  void clear();

 private:
  enum class Style { Off, Terminal, Lines };
  void draw(const std::string& text, double fraction);

  Style style_;
  std::mutex mutex_;  // the kit may report from worker threads
  bool visible_ = false;
  std::string lastText_;
  std::string stage_;  // the text without its bar (" [###...]"): a new stage restarts the estimate
  std::chrono::steady_clock::time_point start_{}, lastDraw_{}, stageStart_{};
};

// Work about to start: `what` it is ("render: 4 x 4096x4096 px x 1048576 spp"), the
// estimated wall time and peak memory. Printed on stderr (unless --quiet) when the time
// exceeds a minute, with how to follow and stop it.
struct WorkEstimate {
  std::string what;
  double seconds = 0.0;
  double bytes = 0.0;
};
void announceWork(const WorkEstimate& estimate);

// "3.2 s", "14 min", "2.5 h", "12 days"; "1.2 GB", "35 MB".
std::string describeDuration(double seconds);
std::string describeMemory(double bytes);

}  // namespace scatterlab
