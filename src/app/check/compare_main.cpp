// `shadelab-compare`: the regression kit without the renderer (docs/ci-engineers.md "A light install"):
// `compare` and `review` exactly as `shadelab compare` and `shadelab review` take them, linked against
// libpng and nothing of the GL stack. Exit codes as shadelab's: 0 pass, 1 a failure, 2 bad input.
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/check/check_cli.h"
#include "shadelab/errors.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"

namespace {

using namespace shadelab;

int compareMain(int argc, char** argv) {
    CLI::App cli{
        "shadelab-compare: judge PNGs against approved ones (the regression kit of shadelab, without "
        "its renderer)",
        "shadelab-compare"};
    cli.require_subcommand(1);
    app::CompareOptions compare;
    app::ReviewOptions review;
    CLI::App* const compareApp = app::addCompareCommand(cli, compare);
    CLI::App* const reviewApp = app::addReviewCommand(cli, review);
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::ostringstream out, err;
        const int status = cli.exit(e, out, err);
        std::fputs(out.str().c_str(), stdout);
        if (!err.str().empty())
            std::fprintf(stderr, "shadelab-compare: %s", printable(err.str(), true).c_str());
        return status == 0 ? kExitOk : kExitInputError;
    }
    if (*compareApp) return app::runCompare(compare);
    if (*reviewApp) return app::runReview(review);
    return kExitInputError;
}

} // namespace

int main(int argc, char** argv) {
    installOutputSignalHandlers();
    int status = kExitOk;
    try {
        status = compareMain(argc, argv);
    } catch (const InputError& e) {
        std::fprintf(stderr, "shadelab-compare: %s\n", printable(e.what(), true).c_str());
        status = kExitInputError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "shadelab-compare: %s\n", printable(e.what(), true).c_str());
        status = kExitRuntimeError;
    }
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fprintf(stderr, "shadelab-compare: cannot write to standard output\n");
        if (status == kExitOk) status = kExitRuntimeError;
    }
    return status;
}
