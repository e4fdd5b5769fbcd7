#include "fitting/ceres_support.h"

#include <mutex>

#include <glog/logging.h>

namespace scatterlab::fitting {

std::string terminationName(ceres::TerminationType type) {
  switch (type) {
    case ceres::CONVERGENCE: return "CONVERGENCE";
    case ceres::NO_CONVERGENCE: return "NO_CONVERGENCE";
    case ceres::FAILURE: return "FAILURE";
    case ceres::USER_SUCCESS: return "USER_SUCCESS";
    case ceres::USER_FAILURE: return "USER_FAILURE";
  }
  return "UNKNOWN";
}

void quietCeresLogging() {
  static std::once_flag once;
  std::call_once(once, [] { FLAGS_minloglevel = google::GLOG_FATAL; });
}

}  // namespace scatterlab::fitting
