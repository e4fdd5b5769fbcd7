#include "fitting/ceres_support.h"

#include <mutex>

#include <glog/logging.h>

namespace scatterlab::fitting {

ceres::Solver::Options denseSolverOptions(int maxIterations, double functionTolerance,
                                          double parameterTolerance, double gradientTolerance) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = maxIterations;
  options.function_tolerance = functionTolerance;
  options.parameter_tolerance = parameterTolerance;
  options.gradient_tolerance = gradientTolerance;
  options.logging_type = ceres::SILENT;
  return options;
}

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
