// shadelab's command line parsed but not run (DESIGN §5): main.cpp runs what parseCommandLine returns, and
// fuzz/cli_fuzzer.cpp feeds it hostile argument vectors. Parsing reads no scene file, makes no GL context
// and writes nothing; the values it returns are checked by the entry points of commands.h.
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "app/bench/bench.h"
#include "app/check/review.h"
#include "app/shells/commands.h"
#include "shadelab/errors.h"

namespace shadelab::app {

// The context a headless command asks for (--backend, --api, --egl-device), checked by
// contextFromArguments when the command runs.
struct ContextArgs {
    std::string backend = "egl", api = "gl", eglDevice;
};

// Each form of the command line, with the values main.cpp runs it with. Files are named as given; an
// empty scene is the defaults (DESIGN §4), or for report the bundled scenes/report.json.
struct ExitArgs { // --help, --help-all: print `text` to stdout and exit with `exitCode`
    std::string text;
    int exitCode = kExitOk;
};
struct DemoArgs { // no subcommand: the window, with a scene or a lesson
    std::string scene;
    SceneOverrides overrides;
    DemoOptions demo;
    std::string api = "gl";
};
struct RenderArgs {
    std::string scene, out; // out: a PNG, or - for standard output; empty only with printMatrices
    SceneOverrides overrides;
    ContextArgs context;
    bool verbose = false, specialize = true, printMatrices = false;
};
struct ReferenceArgs {
    std::string scene, out;
    SceneOverrides overrides;
    ContextArgs context; // render's --backend and --api, checked and unused (the CPU draws)
};
struct BenchArgs {
    BenchOptions bench; // frames, warm-up and filter; the size, context and JSON file below
    std::string size = "800x600", json;
    ContextArgs context;
};
struct ReportArgs { // app/report/report.h's options, built by main.cpp
    std::string scene, out = "report", levels = "0..8";
    bool noAuto = false, noPlot = false;
    int frames = 20, warmup = 3;
    ContextArgs context;
};
struct EglDevicesArgs { // --egl-device list, on any command that takes it
    std::string api = "gl";
};
struct CheckArgs {
    std::string file; // a lesson or a scene
};
struct SlidesArgs {                   // the scene's other flags do not apply to a lesson
    std::string lesson, outDir, deck; // at least one of outDir and deck
    std::optional<std::string> size;
    bool captions = true;
    ContextArgs context;
};
using ParsedCommand = std::variant<ExitArgs, DemoArgs, RenderArgs, ReferenceArgs, BenchArgs, ReportArgs,
                                   EglDevicesArgs, CompareOptions, ReviewOptions, CheckArgs, SlidesArgs>;

// Throws InputError for anything CLI11 rejects, with CLI11's message (naming the argument) and its
// "Run with --help" hint; a mistyped subcommand is named as such.
ParsedCommand parseCommandLine(int argc, char** argv);

} // namespace shadelab::app
