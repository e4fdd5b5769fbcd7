// Bad input to the renderer that the user can fix: a missing or corrupt environment map, a
// map that is not equirectangular, a negative or NaN radiance, an impossible setting, an
// output that cannot be written. The message names the file, option or value and says what is
// allowed, so the command line shows it as it is (exit 2, app/exit_code.h).
#pragma once

#include <stdexcept>

namespace scatterlab {

class RenderInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace scatterlab
