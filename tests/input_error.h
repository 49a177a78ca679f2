// What a bad value is refused with: the tests' one way to catch an InputError and read its message.
#pragma once

#include <string>

#include "shadelab/errors.h"

namespace shadelab::test {

// The message of the InputError `attempt` throws, or "" when it throws none (any other exception goes on,
// and fails the test that called it).
template <typename F> std::string inputErrorOf(F&& attempt) {
    try {
        attempt();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace shadelab::test
