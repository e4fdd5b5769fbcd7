#include "app/lab/phase_timer.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace scatterlab {

PhaseTimer::Mark PhaseTimer::now() {
  timespec cpu{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu);
  return {std::chrono::steady_clock::now(), double(cpu.tv_sec) + 1e-9 * double(cpu.tv_nsec)};
}

void PhaseTimer::record(const std::string& phase, const std::string& material, const Mark& start) {
  const Mark end = now();
  PhaseTiming timing{phase, material, std::chrono::duration<double>(end.wall - start.wall).count(),
                     end.cpu - start.cpu};
  if (log_ && beforeLog_) beforeLog_();
  if (log_)
    std::fprintf(stderr, "lab: %-10s %-28s %7.2f s wall %7.2f s cpu\n", phase.c_str(),
                 material.empty() ? "(all)" : material.c_str(), timing.wallSeconds, timing.cpuSeconds);
  timings_.push_back(std::move(timing));
}

PhaseTiming PhaseTimer::total(const std::string& phase) const {
  PhaseTiming sum{phase, "", 0, 0};
  for (const PhaseTiming& t : timings_)
    if (t.phase == phase) {
      sum.wallSeconds += t.wallSeconds;
      sum.cpuSeconds += t.cpuSeconds;
    }
  return sum;
}

std::vector<std::string> PhaseTimer::phases() const {
  std::vector<std::string> names;
  for (const PhaseTiming& t : timings_)
    if (std::find(names.begin(), names.end(), t.phase) == names.end()) names.push_back(t.phase);
  return names;
}

nlohmann::json PhaseTimer::toJson() const {
  nlohmann::json entries = nlohmann::json::array(), totals = nlohmann::json::array();
  for (const PhaseTiming& t : timings_)
    entries.push_back({{"phase", t.phase},
                       {"material", t.material},
                       {"wall_seconds", t.wallSeconds},
                       {"cpu_seconds", t.cpuSeconds}});
  for (const std::string& phase : phases()) {
    const PhaseTiming sum = total(phase);
    totals.push_back({{"phase", phase}, {"wall_seconds", sum.wallSeconds}, {"cpu_seconds", sum.cpuSeconds}});
  }
  return {{"phases", std::move(entries)}, {"totals", std::move(totals)}};
}

}  // namespace scatterlab
