// The CLI11 setup of shadelab's command line, moved out of main.cpp's run() so it can be fuzzed without
// rendering (fuzz/cli_fuzzer.cpp). Output that CLI11 would print goes into the result or the InputError.
#include "app/shells/cli.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/demo/demo_state.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/scene.h"
#include "shadelab/shading/lighting.h"
#include "shadelab/vocabulary.h"

namespace shadelab::app {
namespace {

// The scene flags, from their one table (scene_flags.h): the help lists exactly what is accepted.
void addSceneFlags(CLI::App& command, SceneOverrides& o) {
    for (const SceneFlag& flag : sceneFlags())
        command.add_option("--" + std::string(flag.name), o.*flag.value, flag.help);
}

// The context a command asks for: --backend, --api, --egl-device (each command has its own copy).
struct ContextArgs {
    std::string backend = "egl", api = "gl", eglDevice;
};

void addApiFlag(CLI::App& command, std::string& api) {
    command
        .add_option("--api", api,
                    joinNames(kApis) + ": " + std::string(displayName(Api::Gl)) + " or " +
                        std::string(displayName(Api::Gles)))
        ->capture_default_str();
}

// The headless commands' --backend, --api and --egl-device (a number, or list).
void addHeadlessFlags(CLI::App& command, ContextArgs& context) {
    command.add_option("--backend", context.backend, "Headless context: " + joinNames(kBackends))
        ->capture_default_str();
    addApiFlag(command, context.api);
    command.add_option("--egl-device", context.eglDevice,
                       "EGL device number (see list), or list: print the devices and exit; default: the "
                       "first device that gives a context, else the surfaceless platform");
}

void setContext(ParsedCommand& command, const ContextArgs& context) {
    command.backend = context.backend;
    command.api = context.api;
    command.eglDevice = context.eglDevice;
}

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

std::string withoutTrailingNewlines(std::string text) {
    while (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
}

} // namespace

ParsedCommand parseCommandLine(int argc, char** argv) {
    CLI::App cli{"shadelab: flat, Gouraud, Phong and toon shading under Phong and Blinn-Phong lighting, on a "
                 "sphere subdivided from a tetrahedron.\nWithout a subcommand: the demo window (or, with no "
                 "display, the showcase PNG).",
                 "shadelab"};
    cli.set_help_all_flag("--help-all", "Help for every subcommand");
    std::string demoScene;
    DemoOptions demo;
    SceneOverrides demoFlags;
    cli.add_option("scene", demoScene, "Scene file (JSON) for the demo; the defaults if omitted");
    addSceneFlags(cli, demoFlags);
    cli.add_option("--showcase-out", demo.showcaseOut, "Where the showcase goes when there is no display")
        ->capture_default_str();
    cli.add_option("--screenshot-dir", demo.screenshotDir, "Where S saves shadelab-NNN.png and .json")
        ->capture_default_str(); // checked in main.cpp, with a message as helpful as --out's
    cli.add_flag("--hide-panel", demo.hidePanel, "Start with the control panel hidden (C shows it)");
    cli.add_flag("--present", demo.present,
                 "For a class: the large label of mode, lighting, level and exponent (F2), larger text");
    cli.add_option("--ui-scale", demo.uiScale, "Scale of the panel, help and label text, 0.5..4")
        ->check(CLI::Range(0.5, 4.0));
    cli.add_flag("--gl-debug", demo.glDebug, "Ask for a KHR_debug context and print every GL message");
    std::string demoApi = "gl";
    addApiFlag(cli, demoApi);

    SceneOverrides renderFlags;
    std::string renderScene, renderOut;
    ContextArgs renderContext;
    CLI::App* render = cli.add_subcommand("render", "Render a scene headless to a PNG");
    render->add_option("scene", renderScene, "Scene file (JSON); the defaults of DESIGN §4 if omitted");
    addSceneFlags(*render, renderFlags);
    addHeadlessFlags(*render, renderContext);
    bool verbose = false;
    render->add_flag("--verbose", verbose,
                     "Say which context and renderer drew the picture (standard error)");
    bool specialize = true;
    render
        ->add_option("--specialize", specialize,
                     "on: programs specialized to the scene's lights and terms, each object's values "
                     "compiled in; off: the uber program")
        ->transform(CLI::IsMember({"on", "off", "true", "false", "1", "0"}, CLI::ignore_case))
        ->capture_default_str();
    render->add_option("--out", renderOut,
                       "Output PNG, or - for standard output (required unless --print-matrices)");
    bool printMatrices = false;
    render->add_flag(
        "--print-matrices", printMatrices,
        "Print the camera frame e, u, v, w, M_cam, the projection matrix and each object's M and "
        "normal matrix (standard output); with --out FILE it renders too");

    std::string referenceScene, referenceOut;
    SceneOverrides referenceFlags;
    CLI::App* reference = cli.add_subcommand("reference", "Ray-cast the exact spheres on the CPU to a PNG");
    reference->add_option("scene", referenceScene, "Scene file (JSON)");
    addSceneFlags(*reference, referenceFlags);
    reference->add_option("--out", referenceOut, "Output PNG, or - for standard output")->required();
    // render's context flags, so one command line switches between the two: checked, then unused (the
    // reference is computed on the CPU).
    std::string referenceBackend = "egl", referenceApi = "gl";
    bool referenceSpecialize = true;
    reference->add_option("--backend", referenceBackend, "Accepted as render takes it; no effect (CPU)");
    reference->add_option("--api", referenceApi, "Accepted as render takes it; no effect (CPU)");
    reference->add_option("--specialize", referenceSpecialize, "Accepted as render takes it; no effect (CPU)")
        ->transform(CLI::IsMember({"on", "off", "true", "false", "1", "0"}, CLI::ignore_case));

    BenchOptions bench;
    std::string benchSize = "800x600", benchJson;
    ContextArgs benchContext;
    CLI::App* benchCommand =
        cli.add_subcommand("bench", "Benchmarks, reported as ratios measured in one run");
    addHeadlessFlags(*benchCommand, benchContext);
    benchCommand->add_option("--size", benchSize, "Frame size WxH")->capture_default_str();
    benchCommand->add_option("--frames", bench.frames, "Timed frames per configuration")
        ->capture_default_str()
        ->check(CLI::Range(3, 100000));
    benchCommand->add_option("--warmup", bench.warmupFrames, "Untimed frames first")
        ->capture_default_str()
        ->check(CLI::Range(0, 1000));
    benchCommand->add_option("--filter", bench.filter, "Regular expression: run only matching benchmarks");
    benchCommand->add_option("--json", benchJson, "Also write every figure and ratio to this JSON file");

    ParsedCommand command;
    CLI::App* compareCommand = cli.add_subcommand(
        "compare", "Compare two PNGs as the image tests do: exit 0 within the tolerance, 1 beyond it");
    compareCommand->add_option("actual", command.compare.actual, "The image under test (PNG)")->required();
    compareCommand->add_option("expected", command.compare.expected, "The reference (PNG)")->required();
    compareCommand->add_option("--max", command.compare.maxDelta, "Largest per-channel difference, 0..255")
        ->capture_default_str();
    compareCommand
        ->add_option("--mean", command.compare.meanDelta,
                     "Largest mean per-channel difference, over the compared pixels")
        ->capture_default_str();
    compareCommand->add_option("--outliers", command.compare.outliers, "Pixels allowed over --max")
        ->capture_default_str();
    compareCommand->add_option(
        "--mask", command.compare.mask,
        "PNG of ACTUAL's size: black pixels are not compared, nor counted in the mean");
    compareCommand->add_option("--diff", command.compare.diff,
                               "Where to write the difference ×8 on failure (a file; never an input)");
    compareCommand->add_flag(
        "--json", command.compare.json,
        "Print the result as one JSON object (sizes, max, mean over the compared pixels, "
        "outliers, limits, passed, diff) instead of the summary line");

    std::string reportScene;
    ContextArgs reportContext;
    CLI::App* reportCommand = cli.add_subcommand(
        "report",
        "Error against run time of every shading mode, lighting model and level: CSV, JSON, a plot");
    reportCommand->add_option("scene", reportScene,
                              "Scene file (JSON); the bundled scenes/report.json if omitted");
    reportCommand->add_option("--out", command.reportOut, "Output folder (created if missing)")
        ->capture_default_str();
    reportCommand->add_option("--levels", command.reportLevels, "Levels N or A..B within 0..10")
        ->capture_default_str();
    reportCommand->add_flag("--no-auto", command.reportNoAuto, "Leave out the auto-subdivision rows");
    reportCommand->add_flag("--no-plot", command.reportNoPlot,
                            "Write report.csv and report.json only (no gnuplot needed)");
    addHeadlessFlags(*reportCommand, reportContext);
    reportCommand->add_option("--frames", command.reportFrames, "Timed frames per configuration")
        ->capture_default_str()
        ->check(CLI::Range(1, 100000));
    reportCommand->add_option("--warmup", command.reportWarmup, "Untimed frames first")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));

    std::string checkFile;
    CLI::App* checkCommand = cli.add_subcommand(
        "check",
        "Read a lesson or a scene file as the other commands would and say what is wrong, drawing nothing");
    checkCommand->add_option("file", checkFile, "Lesson or scene file (JSON)")->required();

    std::string slidesLesson;
    ContextArgs slidesContext;
    CLI::App* slidesCommand = cli.add_subcommand(
        "slides",
        "Export a lesson as slides: one PNG per step, its title and caption in a band at the bottom");
    slidesCommand->add_option("lesson", slidesLesson, "Lesson file (JSON)")->required();
    slidesCommand
        ->add_option("--out-dir", command.slidesOutDir,
                     "Folder for 01-title.png, 02-... (created if missing; not the lesson's own folder)")
        ->required();
    slidesCommand->add_option(
        "--size", command.slidesSize,
        "Slide size WxH for every step, e.g. 1920x1080 (default: each step's image size)");
    slidesCommand->add_flag(
        "--no-captions", [&command](std::int64_t) { command.slidesCaptions = false; },
        "No band: each slide is exactly what render makes of the step's scene");
    addHeadlessFlags(*slidesCommand, slidesContext);

    // Set last: subcommands made before it would inherit it, and their --help is not about the demo's keys.
    cli.footer("Demo keys:\n" + keyHelpText());
    try {
        cli.parse(argc, argv);
    } catch (const CLI::Success& e) {
        std::ostringstream out, err;
        command.kind = ParsedCommand::Kind::Exit;
        command.exitCode = cli.exit(e, out, err);
        command.text = out.str();
        return command;
    } catch (const CLI::ParseError& e) {
        // A mistyped subcommand lands in the demo's scene argument; name it rather than the flags after it.
        // The error_code overload: a name too long to stat is not a scene file either, not a run-time error.
        const std::string hints = didYouMean(cli, argc, argv);
        std::error_code ec;
        if (hints.empty() && !demoScene.empty() && !std::filesystem::exists(demoScene, ec))
            throw InputError(
                "\"" + demoScene +
                "\" is neither a subcommand (render, reference, report, bench, compare, check, slides) nor a "
                "scene or lesson file");
        std::ostringstream out, err;
        cli.exit(e, out, err); // CLI11's message naming the argument, and its "Run with --help" hint
        throw InputError(withoutTrailingNewlines(err.str()) + hints);
    }

    if (*render) {
        command.kind = ParsedCommand::Kind::Render;
        command.scene = renderScene;
        command.overrides = renderFlags;
        command.out = renderOut;
        setContext(command, renderContext);
        command.verbose = verbose;
        command.specialize = specialize;
        command.printMatrices = printMatrices;
    } else if (*benchCommand) {
        command.kind = ParsedCommand::Kind::Bench;
        command.bench = bench;
        setContext(command, benchContext);
        command.benchSize = benchSize;
        command.benchJson = benchJson;
    } else if (*reportCommand) {
        command.kind = ParsedCommand::Kind::Report;
        command.scene = reportScene;
        setContext(command, reportContext);
    } else if (*compareCommand) {
        command.kind = ParsedCommand::Kind::Compare;
    } else if (*checkCommand) {
        command.kind = ParsedCommand::Kind::Check;
        command.scene = checkFile;
    } else if (*slidesCommand) {
        command.kind = ParsedCommand::Kind::Slides;
        command.scene = slidesLesson;
        setContext(command, slidesContext);
    } else if (*reference) {
        command.kind = ParsedCommand::Kind::Reference;
        setContext(command, {referenceBackend, referenceApi, ""});
        command.scene = referenceScene;
        command.overrides = referenceFlags;
        command.out = referenceOut;
    } else {
        command.kind = ParsedCommand::Kind::Demo;
        command.scene = demoScene;
        command.overrides = demoFlags;
        command.demo = demo;
        command.api = demoApi;
    }
    if (command.eglDevice == "list") {
        command.kind = ParsedCommand::Kind::EglDevices;
        return command;
    }
    if (command.kind == ParsedCommand::Kind::Render && renderOut.empty() && !printMatrices)
        throw InputError("--out is required: the PNG to write, or - for standard output (or --print-matrices "
                         "alone to print the matrices)\nRun with --help for more information.");
    if (command.kind == ParsedCommand::Kind::Render && printMatrices && renderOut == "-")
        throw InputError(
            "--print-matrices: the matrices go to standard output, and so would the PNG of --out "
            "-; write the PNG to a file (--out FILE.png) or leave --out out");
    return command;
}

} // namespace shadelab::app
