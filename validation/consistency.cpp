#include "validation/consistency.h"

#include <sstream>

namespace scatterlab::detail {

void ConsistencyAccumulator::join(const ConsistencyAccumulator& other) {
  inconsistent += other.inconsistent;
  maxWeightError = std::max(maxWeightError, other.maxWeightError);
  maxPdfError = std::max(maxPdfError, other.maxPdfError);
  if (other.firstFailureIndex < firstFailureIndex) {
    firstFailureIndex = other.firstFailureIndex;
    firstFailure = other.firstFailure;
  }
  for (size_t i = 0; i < cellError.size(); ++i) cellError[i] = std::max(cellError[i], other.cellError[i]);
  sum += other.sum;
  sumSquares += other.sumSquares;
  supportViolations += other.supportViolations;
}

void describeInconsistency(std::string& out, size_t index, const Vec3d& wo, const char* what, double sampled,
                           double recomputed) {
  std::ostringstream msg;
  msg.precision(9);
  msg << "sample " << index << " wo=(" << wo.x << ", " << wo.y << ", " << wo.z << "): " << what
      << " from sample() = " << sampled << " but from eval/pdf = " << recomputed;
  out = msg.str();
}

}  // namespace scatterlab::detail
