#include "app/interrupt_cleanup.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <mutex>
#include <thread>

#include "materials/core/temporary_files.h"

namespace scatterlab {

namespace {

constexpr std::array<int, 3> HandledSignals{SIGINT, SIGTERM, SIGHUP};

sigset_t handledSet() {
  sigset_t set;
  sigemptyset(&set);
  for (int signal : HandledSignals) sigaddset(&set, signal);
  return set;
}

[[noreturn]] void handleSignals() {
  const sigset_t set = handledSet();
  int signal = 0;
  while (sigwait(&set, &signal) != 0) {}
  // Held to the end: a commit in progress finishes first, and nothing registers anew.
  const auto lock = deferInterruptions();
  removeRegisteredTemporaries();
  // End the process the way the signal would have: the default action, unblocked here.
  ::signal(signal, SIG_DFL);
  sigset_t one;
  sigemptyset(&one);
  sigaddset(&one, signal);
  pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
  raise(signal);
  _exit(128 + signal);
}

}  // namespace

void installInterruptCleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    ::signal(SIGXFSZ, SIG_IGN);
    const sigset_t set = handledSet();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread(handleSignals).detach();
  });
}

}  // namespace scatterlab
