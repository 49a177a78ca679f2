// libFuzzer target for the command-line parser (src/app/shells/cli.h). The input, split on NUL bytes, is the
// argument vector after argv[0]. parseCommandLine either returns what to run or throws InputError (CLI11's
// parse errors surface as InputError); anything else is a crash. It reads no scene file and renders
// nothing, so the only files it touches are the stat()s of --screenshot-dir and a mistyped subcommand.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "app/shells/cli.h"
#include "shadelab/errors.h"

namespace {

using namespace shadelab;

// A command line longer than this is not a command line; the bound keeps each run fast.
constexpr std::size_t kMaxArguments = 64;

[[noreturn]] void crash(std::string_view what, std::string_view detail) {
    std::fprintf(stderr, "cli_fuzzer: %.*s: %.*s\n", int(what.size()), what.data(), int(detail.size()),
                 detail.data());
    std::abort();
}

std::vector<std::string> splitOnNul(std::string_view bytes) {
    std::vector<std::string> arguments{"shadelab"};
    while (!bytes.empty() && arguments.size() <= kMaxArguments) {
        const std::size_t end = bytes.find('\0');
        arguments.emplace_back(bytes.substr(0, end));
        if (end == std::string_view::npos) break;
        bytes.remove_prefix(end + 1);
    }
    return arguments;
}

// What parseCommandLine returns is one of its forms, each with what main.cpp needs to run it.
void check(const app::ExitArgs& exit) {
    if (exit.exitCode != kExitOk) crash("an Exit that is not a success", std::to_string(exit.exitCode));
    if (exit.text.empty()) crash("an Exit with no text to print", "");
}
void check(const app::RenderArgs& render) {
    // --out is required (parseCommandLine) unless the matrices alone are printed; an empty value given is
    // left to checkOutputPath.
    if (render.printMatrices && render.out == "-") crash("--print-matrices with --out -", "");
}
void check(const app::CompareOptions& compare) {
    if (compare.actual.empty() || compare.expected.empty()) crash("compare without its two images", "");
}
void check(const app::ReviewOptions& review) {
    if (review.actualDir.empty() || review.expectedDir.empty()) crash("review without its two folders", "");
}
void check(const app::EglDevicesArgs&) {}
void check(const app::BenchArgs& bench) {
    if (bench.bench.frames < 3 || bench.bench.warmupFrames < 0)
        crash("bench frames outside their CLI11 range", std::to_string(bench.bench.frames));
    if (bench.context.eglDevice == "list") crash("a device listing run as bench", "");
}
// The files are required by CLI11 where a command needs one; an empty or missing one is the loader's to
// refuse.
void check(const app::DemoArgs&) {}
void check(const app::ReferenceArgs&) {}
void check(const app::ReportArgs& report) {
    if (report.context.eglDevice == "list") crash("a device listing run as report", "");
}
void check(const app::CheckArgs&) {}
void check(const app::SlidesArgs& slides) {
    if (slides.context.eglDevice == "list") crash("a device listing run as slides", "");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> arguments = splitOnNul({reinterpret_cast<const char*>(data), size});
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    argv.push_back(nullptr);
    try {
        std::visit([](const auto& command) { check(command); },
                   app::parseCommandLine(int(arguments.size()), argv.data()));
    } catch (const InputError& e) {
        if (std::string_view(e.what()).empty()) crash("an InputError with no message", "");
    } catch (const std::exception& e) {
        crash("parseCommandLine threw something other than InputError", e.what());
    }
    return 0;
}
