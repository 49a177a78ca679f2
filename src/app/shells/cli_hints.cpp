#include "app/shells/cli_hints.h"

#include <algorithm>
#include <vector>

#include <CLI/CLI.hpp>

#include "shadelab/io/text.h"

namespace shadelab::app {

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// "\n--shadding: did you mean --shading?" for each --option on the command line that no command has and
// that is at most two edits from one that some command has; "" otherwise.
std::string didYouMean(CLI::App& cli, int argc, char** argv) {
    std::vector<std::string> known;
    auto collect = [&](CLI::App* app) {
        for (const CLI::Option* option : app->get_options())
            for (const std::string& name : option->get_lnames()) known.push_back("--" + name);
    };
    collect(&cli);
    for (CLI::App* sub : cli.get_subcommands({})) collect(sub);
    std::string hints;
    for (int i = 1; i < argc; ++i) {
        const std::string_view argument(argv[i]);
        if (!argument.starts_with("--") || argument.size() > 64) continue;
        const std::string name(argument.substr(0, argument.find('=')));
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        std::string best;
        std::size_t bestDistance = 3;
        for (const std::string& candidate : known)
            if (const std::size_t d = editDistance(name, candidate); d < bestDistance) {
                best = candidate;
                bestDistance = d;
            }
        if (!best.empty()) hints += "\n" + printable(name) + ": did you mean " + best + "?";
    }
    return hints;
}

} // namespace shadelab::app
