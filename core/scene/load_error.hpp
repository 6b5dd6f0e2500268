#pragma once
// The one exception type every scene loader throws for bad input. The message is a single
// line, "<file>: <what is wrong>", so the command line can print it as is (DESIGN.md: errors
// name the input and what is wrong).
#include <stdexcept>
#include <string>

namespace strata {

class LoadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace strata
