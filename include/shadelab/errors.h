// The two kinds of failure shadelab reports, and the exit codes they map to (DESIGN §5).
#pragma once

#include <stdexcept>

namespace shadelab {

// Bad input from the user: an argument, a scene file, a path, a size, a level. Exit code 2.
// The message names the field or argument, the value, and what would be accepted.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Something failed at run time: no GL context, a shader that does not compile, an I/O error. Exit 1.
class RuntimeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline constexpr int kExitOk = 0;
inline constexpr int kExitRuntimeError = 1;
inline constexpr int kExitInputError = 2;

} // namespace shadelab
