// A one-line progress display for long work, on stderr and only when stderr is a terminal:
// logs, pipes and CI output stay clean, and stdout (tables, JSON) is never touched.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

#include "validation/bsdf_check.h"
#include "validation/half_space_reference.h"

namespace scatterlab {

class ProgressLine {
 public:
  ProgressLine();
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool enabled() const { return enabled_; }
  // A callback for the kit that shows "<prefix> <stage> <percent>".
  ProgressCallback callback(std::string prefix);
  // A callback for the half-space walk (fraction only) that shows "<prefix> <percent>"; empty
  // when the line is disabled.
  WalkProgress walkCallback(std::string prefix);
  // Erases the line, so that what is printed next starts on a clean line.
  void clear();

 private:
  void draw(const std::string& text, double fraction);

  bool enabled_;
  std::mutex mutex_;  // the kit may report from worker threads
  bool visible_ = false;
  std::string lastText_;
  std::chrono::steady_clock::time_point lastDraw_{};
};

}  // namespace scatterlab
