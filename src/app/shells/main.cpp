// shadelab's entry point: the demo window (default) and the commands (`render`, `reference`, `bench`,
// `compare`, `review`, `report`, `check`, `slides`; DESIGN §5, README), and the exit codes: 0 success, 2 bad
// input, 1 run-time failure.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <variant>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "app/bench/bench.h"
#include "app/demo/matrices_text.h"
#include "app/measure/bundled_scenes.h"
#include "app/report/report.h"
#include "app/shells/cli.h"
#include "app/shells/commands.h"
#include "shadelab/errors.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/scene_file.h"

namespace {

using namespace shadelab;

// Valid values that are probably a mistake (scene.h sceneWarnings), on standard error; the run goes on.
void warnAbout(const Scene& scene, const std::string& file) {
    for (const std::string& warning : sceneWarnings(scene))
        std::fprintf(stderr, "shadelab: warning: %s%s\n", file.empty() ? "" : printable(file + ": ").c_str(),
                     printable(warning).c_str());
}

// render --print-matrices: the camera's matrices, then each object's.
void printMatrices(const Scene& scene) {
    std::string text = app::cameraMatricesText(scene);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) text += app::objectMatricesText(scene, i);
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
}

// llvmpipe allocates each frame's binned scene on the heap, in blocks, and frees it when the frame is
// rasterized. When those blocks end up at the top of glibc's heap, free() hands the pages back to the kernel
// (the default trim threshold is 128 KiB, and it only rises if mmap-sized blocks are freed) and the next
// frame faults them in again: 150 page faults a frame, 1.8 ms of the main thread's time at 800×600 on the
// 2-vCPU VM where it was measured (72,136 faults for 400 phong frames against 11,809 — bench/README.md "The
// frame-time tail, and pinned threads"). Whether the blocks land at the top depends on what was allocated
// before, so a fixed threshold is set instead: up to 64 MiB of freed heap is kept for the next frame, and
// blocks below 32 MiB come from the heap rather than from mmap (setting either turns glibc's dynamic
// thresholds off). A request glibc refuses leaves its defaults, as does a sanitizer's own allocator: only
// speed depends on it.
void keepFreedHeapForTheNextFrame() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

// What each form of the command line runs (its parsing lives in app/shells/cli.cpp, where the fuzzer
// reaches it).
int run(const app::ExitArgs& exit) {
    std::fputs(exit.text.c_str(), stdout);
    return exit.exitCode;
}

ContextRequest contextOf(const app::ContextArgs& context) {
    return app::contextFromArguments(context.backend, context.api, context.eglDevice);
}

int run(const app::RenderArgs& render) {
    if (!render.out.empty()) {
        app::checkOutputPath(render.out);
        refuseOverwritingInput(render.out, "--out", render.scene); // before anything is rendered
        if (render.printMatrices)
            refuseStandardOutputAlias(render.out, "--out", "the matrices of --print-matrices");
    }
    const Scene scene = app::composeSceneWithModels(render.scene, render.overrides);
    warnAbout(scene, render.scene);
    if (render.printMatrices) {
        printMatrices(scene);
        if (render.out.empty()) return kExitOk;
    }
    return app::runRender(scene, contextOf(render.context), render.out, render.specialize, render.verbose);
}

int run(const app::ReferenceArgs& reference) {
    (void)app::contextFromArguments(reference.context.backend, reference.context.api, ""); // as render would
    app::checkOutputPath(reference.out);
    refuseOverwritingInput(reference.out, "--out", reference.scene);
    const Scene scene = app::composeSceneWithModels(reference.scene, reference.overrides);
    warnAbout(scene, reference.scene);
    return app::runReference(scene, reference.out);
}

int run(const app::BenchArgs& args) {
    app::BenchOptions bench = args.bench;
    Scene sized;
    composeSize(sized, args.size);
    bench.width = sized.width;
    bench.height = sized.height;
    bench.context = contextOf(args.context);
    if (!args.json.empty()) {
        app::checkOutputPath(args.json, "--json");
        if (args.json == "-")
            throw InputError("--json: - is not accepted; bench prints its table on standard output, so "
                             "give a file name such as bench.json");
        bench.json = args.json;
    }
    return app::runBench(bench);
}

int run(const app::ReportArgs& args) {
    app::ReportOptions report;
    if (!args.scene.empty()) report.scene = args.scene;
    report.outDir = args.out;
    app::parseLevels(args.levels, report);
    report.includeAuto = !args.noAuto;
    report.plot = !args.noPlot;
    report.context = contextOf(args.context);
    report.frames = args.frames;
    report.warmup = args.warmup;
    return app::runReport(report);
}

int run(const app::CompareOptions& compare) {
    if (!compare.diff.empty()) app::checkOutputPath(compare.diff, "--diff");
    return app::runCompare(compare);
}

int run(const app::ReviewOptions& review) {
    return app::runReview(review);
}

int run(const app::EglDevicesArgs& list) {
    return app::runListEglDevices(app::apiFromArgument(list.api));
}

int run(const app::CheckArgs& check) {
    return app::runCheck(check.file);
}

int run(const app::SlidesArgs& args) {
    app::SlidesOptions slides;
    slides.lesson = args.lesson;
    if (args.outDir.empty() && args.deck.empty())
        throw InputError(
            "slides: nothing to write: give --out-dir DIR (a PNG per step), --deck FILE.html (one "
            "page of every slide, with the steps' notes), or both");
    slides.outDir = args.outDir;
    if (!args.deck.empty()) slides.deck = args.deck;
    slides.size = args.size;
    slides.captions = args.captions;
    slides.context = contextOf(args.context);
    return app::runSlides(slides);
}

int run(const app::DemoArgs& args) {
    app::checkOutputPath(args.demo.showcaseOut, "--showcase-out");
    if (std::error_code error; !std::filesystem::is_directory(args.demo.screenshotDir, error))
        throw InputError("--screenshot-dir: " + printable(args.demo.screenshotDir.string()) +
                         (std::filesystem::exists(args.demo.screenshotDir, error)
                              ? " is not a folder; name the folder S saves its screenshots in"
                              : " does not exist; create it (mkdir -p) or name an existing folder"));
    refuseOverwritingInput(args.demo.showcaseOut, "--showcase-out", args.scene);
    app::DemoOptions demo = args.demo;
    Scene scene;
    std::variant<Scene, Lesson> read =
        args.scene.empty() ? Scene{} : app::loadSceneOrLessonWithModels(args.scene);
    if (Lesson* readLesson = std::get_if<Lesson>(&read)) {
        // A lesson: the scene flags apply to every step, as they would to each step's scene file.
        Lesson lesson = std::move(*readLesson);
        for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
            LessonStep& step = lesson.steps[i];
            step.scene = applyOverrides(std::move(step.scene), args.overrides, args.scene);
            warnAbout(step.scene, args.scene + ": steps[" + std::to_string(i) + "]");
        }
        scene = lesson.steps.front().scene;
        demo.lesson = std::make_shared<const Lesson>(std::move(lesson));
    } else {
        scene = applyOverrides(std::get<Scene>(std::move(read)), args.overrides, args.scene);
        warnAbout(scene, args.scene);
    }
    demo.api = app::apiFromArgument(args.api);
    if (args.overrides.size) { // the window takes --size when given, never the scene's image size
        demo.windowWidth = scene.width;
        demo.windowHeight = scene.height;
    }
    return app::runDemo(scene, demo);
}

// Messages carry file names and scene text: control characters and invalid UTF-8 in them are shown as
// \xNN, never sent raw to the terminal.
void printError(const std::exception& e) {
    std::fprintf(stderr, "shadelab: %s\n", printable(e.what(), true).c_str());
}

// Standard output is checked when it is closed: `shadelab --help >/dev/full` must not report success.
int closeStdout(int status) {
    if (std::fflush(stdout) != 0 || std::ferror(stdout) || std::fclose(stdout) != 0) {
        if (errno == EBADF) return status; // closed by the caller: nothing was lost
        std::fprintf(stderr, "shadelab: cannot write to standard output: %s\n", std::strerror(errno));
        return status == kExitOk ? kExitRuntimeError : status;
    }
    return status;
}

} // namespace

int main(int argc, char** argv) {
    installOutputSignalHandlers();
    keepFreedHeapForTheNextFrame();
    int status = kExitOk;
    try {
        status =
            std::visit([](const auto& command) { return run(command); }, app::parseCommandLine(argc, argv));
    } catch (const InputError& e) {
        printError(e);
        status = kExitInputError;
    } catch (const std::exception& e) {
        printError(e);
        status = kExitRuntimeError;
    }
    return closeStdout(status);
}
