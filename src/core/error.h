#pragma once
// The one exception type of homesh: every user-facing failure (bad input, bad
// option, invalid result) is reported through it, with a message that names the
// input at fault. The CLI turns it into a message on stderr and a non-zero exit.
#include <stdexcept>
#include <string>

namespace homesh {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace homesh
