// "Did you mean …?" for the command line: an option no command has, named with the nearest one some
// command has.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace CLI {
class App;
}

namespace shadelab::app {

// The Levenshtein distance between two names.
std::size_t editDistance(std::string_view a, std::string_view b);

// "\n--shadding: did you mean --shading?" for each --option on the command line that no command has and
// that is at most two edits from one that some command has; "" otherwise.
std::string didYouMean(CLI::App& cli, int argc, char** argv);

} // namespace shadelab::app
