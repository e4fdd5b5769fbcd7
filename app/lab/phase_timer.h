// What each phase of `scatterlab lab` costs: wall time (and the process's CPU time, which
// shows how well the phase used the cores), one line per phase and material on stderr as it
// ends, and the whole list in the report's JSON and its timings table.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace scatterlab {

struct PhaseTiming {
  std::string phase;     // "check", "plots", "fit", "render", ...
  std::string material;  // empty for phases of the whole run
  double wallSeconds = 0, cpuSeconds = 0;
};

class PhaseTimer {
 public:
  // log: print a line to stderr when a phase ends, after calling beforeLog (which may clear
  // a progress line).
  explicit PhaseTimer(bool log = true, std::function<void()> beforeLog = {})
      : log_(log), beforeLog_(std::move(beforeLog)) {}

  // Times fn() as `phase` of `material` and returns what fn returns.
  template <typename Fn> auto time(const std::string& phase, const std::string& material, Fn&& fn) {
    const Mark start = now();
    struct Stop {
      PhaseTimer& timer;
      const std::string& phase;
      const std::string& material;
      Mark start;
      ~Stop() { timer.record(phase, material, start); }
    } stop{*this, phase, material, start};
    return fn();
  }

  const std::vector<PhaseTiming>& timings() const { return timings_; }
  // Total wall and CPU seconds of every phase of this name.
  PhaseTiming total(const std::string& phase) const;
  // Phase names in the order they first ran.
  std::vector<std::string> phases() const;
  nlohmann::json toJson() const;

 private:
  struct Mark {
    std::chrono::steady_clock::time_point wall;
    double cpu;
  };
  static Mark now();
  void record(const std::string& phase, const std::string& material, const Mark& start);

  bool log_;
  std::function<void()> beforeLog_;
  std::vector<PhaseTiming> timings_;
};

}  // namespace scatterlab
