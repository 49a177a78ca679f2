// shadelab's command line parsed but not run (DESIGN §5): main.cpp runs what parseCommandLine returns, and
// fuzz/cli_fuzzer.cpp feeds it hostile argument vectors. Parsing reads no scene file, makes no GL context
// and writes nothing; the values it returns are checked by the entry points of commands.h.
#pragma once

#include <optional>
#include <string>

#include "app/bench/bench.h"
#include "app/shells/commands.h"
#include "shadelab/errors.h"

namespace shadelab::app {

struct ParsedCommand {
    enum class Kind { Exit, Demo, Render, Reference, Bench, Report, EglDevices, Compare, Check, Slides };
    Kind kind = Kind::Demo;

    // Kind::Exit (--help, --help-all): print `text` to stdout and exit with `exitCode`.
    std::string text;
    int exitCode = kExitOk;

    std::string scene; // Demo, Render, Reference, Report: the scene file (Demo: or a lesson); empty for the
                       // defaults Check: the lesson or scene file; Slides: the lesson file
    SceneOverrides overrides;    // Demo, Render, Reference
    std::string out;             // Render, Reference: --out
    std::string backend = "egl"; // Render, Bench, Report: --backend, checked by contextFromArguments
    std::string api = "gl";      // Demo, Render, Bench, Report: --api
    std::string eglDevice;       // Render, Bench, Report: --egl-device N; "list" gives Kind::EglDevices
    bool verbose = false;        // Render: --verbose
    bool specialize = true;      // Render: --specialize
    bool printMatrices = false;  // Render: --print-matrices
    DemoOptions demo;            // Demo
    BenchOptions bench;          // Bench: frames, warm-up and filter; size, backend and JSON are below
    std::string benchSize = "800x600", benchJson; // Bench: --size (checked by composeSize), --json
    // Report (app/report/report.h, whose options main.cpp builds): scene and backend as above.
    std::string reportOut = "report", reportLevels = "0..8";
    bool reportNoAuto = false;
    bool reportNoPlot = false;
    int reportFrames = 20, reportWarmup = 3;
    CompareOptions compare; // Compare
    // Slides: --out-dir, --no-captions, --size (the scene's other flags do not apply to a lesson)
    std::string slidesOutDir;
    bool slidesCaptions = true;
    std::optional<std::string> slidesSize;
};

// Throws InputError for anything CLI11 rejects, with CLI11's message (naming the argument) and its
// "Run with --help" hint; a mistyped subcommand is named as such.
ParsedCommand parseCommandLine(int argc, char** argv);

} // namespace shadelab::app
