// How `scatterlab` ends (docs/design.md, "The command line"). Scripts and CI rely on these.
#pragma once

#include <stdexcept>

namespace scatterlab {

enum class ExitCode : int {
  Success = 0,
  CheckFailed = 1,    // the input was fine, a material failed a test
  BadInput = 2,       // the user can fix it: the message names the key/option, value, allowed
  InternalError = 3,  // a bug in scatterlab
};

// Bad input that is not a material description (an option value, an output path): exit 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace scatterlab
