// The CLI11 setup of shadelab's command line, moved out of main.cpp's run() so it can be fuzzed without
// rendering (fuzz/cli_fuzzer.cpp). Output that CLI11 would print goes into the result or the InputError.
#include "app/shells/cli.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/check/check_cli.h"
#include "app/demo/demo_state.h"
#include "app/demo/view_explanations.h"
#include "app/shells/cli_hints.h"
#include "shadelab/geometry/sphere.h"
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

std::string withoutTrailingNewlines(std::string text) {
    while (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
}

// Each form of the command line is a struct of its own: add() declares its options, bound to the fields
// of its arguments (cli.h), which are what parseCommandLine returns when it is the form parsed.

// Without a subcommand: the demo window (its scene, the scene flags, its own options).
struct DemoCommand {
    DemoArgs args;
    void add(CLI::App& cli) {
        DemoOptions& demo = args.demo;
        cli.add_option("scene", args.scene, "Scene file (JSON) for the demo; the defaults if omitted");
        addSceneFlags(cli, args.overrides);
        cli.add_option("--showcase-out", demo.showcaseOut, "Where the showcase goes when there is no display")
            ->capture_default_str();
        cli.add_option("--screenshot-dir", demo.screenshotDir, "Where S saves shadelab-NNN.png and .json")
            ->capture_default_str(); // checked in main.cpp, with a message as helpful as --out's
        cli.add_flag("--hide-panel", demo.hidePanel, "Start with the control panel hidden (C shows it)");
        cli.add_flag("--present", demo.present,
                     "For a class: the large label of mode, lighting, level and exponent (F2), larger "
                     "text, the panel hidden (C shows it)");
        cli.add_option("--ui-scale", demo.uiScale, "Scale of the panel, help and label text, 0.5..4")
            ->check(CLI::Range(0.5, 4.0));
        cli.add_flag("--gl-debug", demo.glDebug, "Ask for a KHR_debug context and print every GL message");
        addApiFlag(cli, args.api);
    }
};

struct RenderCommand {
    RenderArgs args;
    CLI::App* add(CLI::App& cli) {
        CLI::App* render = cli.add_subcommand("render", "Render a scene headless to a PNG");
        render->add_option("scene", args.scene, "Scene file (JSON); the defaults of DESIGN §4 if omitted");
        addSceneFlags(*render, args.overrides);
        addHeadlessFlags(*render, args.context);
        render->add_flag("--verbose", args.verbose,
                         "Say which context and renderer drew the picture (standard error)");
        render
            ->add_option("--specialize", args.specialize,
                         "on: programs specialized to the scene's lights and terms, each object's values "
                         "compiled in; off: the uber program")
            ->transform(CLI::IsMember({"on", "off", "true", "false", "1", "0"}, CLI::ignore_case))
            ->capture_default_str();
        render->add_option("--out", args.out,
                           "Output PNG, or - for standard output (required unless --print-matrices)");
        render->add_flag(
            "--print-matrices", args.printMatrices,
            "Print the camera frame e, u, v, w, M_cam, the projection matrix and each object's M "
            "and normal matrix (standard output); with --out FILE it renders too");
        return render;
    }
    // What CLI11 cannot say: --out is required unless the matrices are printed, and the two cannot share
    // standard output.
    const RenderArgs& parsed() const {
        if (args.out.empty() && !args.printMatrices)
            throw InputError("--out is required: the PNG to write, or - for standard output (or "
                             "--print-matrices alone to print the matrices)\nRun with --help for more "
                             "information.");
        if (args.printMatrices && args.out == "-")
            throw InputError(
                "--print-matrices: the matrices go to standard output, and so would the PNG of --out "
                "-; write the PNG to a file (--out FILE.png) or leave --out out");
        return args;
    }
};

struct ReferenceCommand {
    ReferenceArgs args;
    bool specialize = true; // accepted, no effect
    CLI::App* add(CLI::App& cli) {
        CLI::App* reference = cli.add_subcommand(
            "reference",
            "Ray-cast the exact surfaces (spheres, teapot patches; a model's own mesh) on the CPU to a PNG");
        reference->add_option("scene", args.scene, "Scene file (JSON)");
        addSceneFlags(*reference, args.overrides);
        reference->add_option("--out", args.out, "Output PNG, or - for standard output")->required();
        // render's context flags, so one command line switches between the two: checked, then unused (the
        // reference is computed on the CPU).
        reference->add_option("--backend", args.context.backend,
                              "Accepted as render takes it; no effect (CPU)");
        reference->add_option("--api", args.context.api, "Accepted as render takes it; no effect (CPU)");
        reference->add_option("--specialize", specialize, "Accepted as render takes it; no effect (CPU)")
            ->transform(CLI::IsMember({"on", "off", "true", "false", "1", "0"}, CLI::ignore_case));
        return reference;
    }
};

struct BenchCommand {
    BenchArgs args;
    CLI::App* add(CLI::App& cli) {
        CLI::App* command = cli.add_subcommand("bench", "Benchmarks, reported as ratios measured in one run");
        addHeadlessFlags(*command, args.context);
        command->add_option("--size", args.size, "Frame size WxH")->capture_default_str();
        command->add_option("--frames", args.bench.frames, "Timed frames per configuration")
            ->capture_default_str()
            ->check(CLI::Range(3, 100000));
        command->add_option("--warmup", args.bench.warmupFrames, "Untimed frames first")
            ->capture_default_str()
            ->check(CLI::Range(0, 1000));
        command->add_option("--filter", args.bench.filter,
                            "Regular expression: run only matching benchmarks");
        command->add_option("--json", args.json, "Also write every figure and ratio to this JSON file");
        return command;
    }
    const BenchArgs& parsed() const { return args; }
};

struct ReportCommand {
    ReportArgs args;
    CLI::App* add(CLI::App& cli) {
        CLI::App* report = cli.add_subcommand(
            "report",
            "Error against run time of every shading mode, lighting model and level: CSV, JSON, a plot");
        report->add_option("scene", args.scene,
                           "Scene file (JSON); the bundled scenes/report.json if omitted");
        report->add_option("--out", args.out, "Output folder (created if missing)")->capture_default_str();
        report
            ->add_option("--levels", args.levels,
                         "Levels N or A..B within 0.." + std::to_string(kMaxSubdivisions))
            ->capture_default_str();
        report->add_flag("--no-auto", args.noAuto, "Leave out the auto-subdivision rows");
        report->add_flag("--no-plot", args.noPlot,
                         "Write report.csv and report.json only (no gnuplot needed)");
        addHeadlessFlags(*report, args.context);
        report->add_option("--frames", args.frames, "Timed frames per configuration")
            ->capture_default_str()
            ->check(CLI::Range(1, 100000));
        report->add_option("--warmup", args.warmup, "Untimed frames first")
            ->capture_default_str()
            ->check(CLI::Range(1, 1000));
        return report;
    }
    const ReportArgs& parsed() const { return args; }
};

struct CheckCommand {
    CheckArgs args;
    CLI::App* add(CLI::App& cli) {
        CLI::App* check = cli.add_subcommand("check", "Read a lesson or a scene file as the other commands "
                                                      "would and say what is wrong, drawing nothing");
        check->add_option("file", args.file, "Lesson or scene file (JSON)")->required();
        return check;
    }
};

struct SlidesCommand {
    SlidesArgs args;
    CLI::App* add(CLI::App& cli) {
        CLI::App* slides = cli.add_subcommand(
            "slides",
            "Export a lesson as slides: one PNG per step, its title and caption in a band at the bottom");
        slides->add_option("lesson", args.lesson, "Lesson file (JSON)")->required();
        slides->add_option(
            "--out-dir", args.outDir,
            "Folder for 01-title.png, 02-... (created if missing; not the lesson's own folder)");
        slides->add_option(
            "--deck", args.deck,
            "One HTML file with every slide in order and each step's \"notes\" (N shows them)");
        slides->add_option("--size", args.size,
                           "Slide size WxH for every step, e.g. 1920x1080 (default: each step's image size)");
        slides->add_flag(
            "--no-captions", [this](std::int64_t) { args.captions = false; },
            "No band: each slide is exactly what render makes of the step's scene");
        addHeadlessFlags(*slides, args.context);
        return slides;
    }
    const SlidesArgs& parsed() const { return args; }
};

// A headless command as parsed; with --egl-device list, the device listing instead (before the command's
// own checks: `render --egl-device list` needs no --out).
template <class Command> ParsedCommand headless(const Command& command) {
    const ContextArgs& context = command.args.context;
    if (context.eglDevice == "list") return EglDevicesArgs{context.api};
    return command.parsed();
}

} // namespace

ParsedCommand parseCommandLine(int argc, char** argv) {
    CLI::App cli{
        "shadelab: flat, Gouraud, Phong and toon shading under Phong and Blinn-Phong lighting, on a "
        "sphere subdivided from a tetrahedron, Newell's teapot or a model file (mesh paths relative to the "
        "scene file).\nWithout a subcommand: the demo window (or, with no "
        "display, the showcase PNG).",
        "shadelab"};
    cli.set_help_all_flag("--help-all", "Help for every subcommand");
    DemoCommand demo;
    demo.add(cli);
    // In --help's order.
    RenderCommand render;
    ReferenceCommand reference;
    BenchCommand bench;
    CompareOptions compare;
    ReviewOptions review;
    ReportCommand report;
    CheckCommand check;
    SlidesCommand slides;
    CLI::App* const renderApp = render.add(cli);
    CLI::App* const referenceApp = reference.add(cli);
    CLI::App* const benchApp = bench.add(cli);
    CLI::App* const compareApp = addCompareCommand(cli, compare);
    CLI::App* const reviewApp = addReviewCommand(cli, review);
    CLI::App* const reportApp = report.add(cli);
    CLI::App* const checkApp = check.add(cli);
    CLI::App* const slidesApp = slides.add(cli);

    // Set last: subcommands made before it would inherit it, and their --help is not about the demo's keys.
    cli.footer("Demo keys:\n" + keyHelpText() + "\nViews (what each shows):\n" + viewHelpText());
    try {
        cli.parse(argc, argv);
    } catch (const CLI::Success& e) {
        std::ostringstream out, err;
        ExitArgs exit;
        exit.exitCode = cli.exit(e, out, err);
        exit.text = out.str();
        return exit;
    } catch (const CLI::ParseError& e) {
        // A mistyped subcommand lands in the demo's scene argument; name it rather than the flags after it.
        // The error_code overload: a name too long to stat is not a scene file either, not a run-time error.
        const std::string hints = didYouMean(cli, argc, argv);
        const std::string& scene = demo.args.scene;
        std::error_code ec;
        if (hints.empty() && !scene.empty() && !std::filesystem::exists(scene, ec))
            throw InputError("\"" + scene +
                             "\" is neither a subcommand (render, reference, report, bench, compare, review, "
                             "check, slides) nor a "
                             "scene or lesson file");
        std::ostringstream out, err;
        cli.exit(e, out, err); // CLI11's message naming the argument, and its "Run with --help" hint
        throw InputError(withoutTrailingNewlines(err.str()) + hints);
    }

    if (*renderApp) return headless(render);
    if (*referenceApp) return reference.args;
    if (*benchApp) return headless(bench);
    if (*compareApp) return compare;
    if (*reviewApp) return review;
    if (*reportApp) return headless(report);
    if (*checkApp) return check.args;
    if (*slidesApp) return headless(slides);
    return demo.args;
}

} // namespace shadelab::app
