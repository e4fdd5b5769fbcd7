// What the fitter's Ceres calls share: names of Ceres's outcomes, and its logging kept quiet.
#pragma once

#include <string>

#include <ceres/solver.h>
#include <ceres/types.h>

namespace scatterlab::fitting {

// Levenberg-Marquardt on a dense problem with few parameters (DENSE_QR), silent, with these
// limits: what every fit of this library runs.
ceres::Solver::Options denseSolverOptions(int maxIterations, double functionTolerance,
                                          double parameterTolerance, double gradientTolerance);

// "CONVERGENCE", "NO_CONVERGENCE", "FAILURE", ...
std::string terminationName(ceres::TerminationType type);

// Ceres reports through glog, to stderr; the fitter reports every outcome itself (a
// rank-deficient covariance is a warning of the fit, not a log line), so glog's messages below
// FATAL are turned off, once, for the process.
void quietCeresLogging();

}  // namespace scatterlab::fitting
