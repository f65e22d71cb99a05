// The one exception type of ontile: a message that names the file (or option) and the problem.
// The CLI prints it as a single "error: ..." line and exits non-zero.
#pragma once
#include <stdexcept>
#include <string>

namespace ontile {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ontile
