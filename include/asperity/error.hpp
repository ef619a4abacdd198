// The one exception type of the C++ API (never thrown on the query hot path).
#pragma once
#include <stdexcept>
#include <string>

namespace asperity {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace asperity
