// shadelab's entry point: the demo window (default), `render`, `reference` and `bench` (DESIGN §5), and the
// exit codes: 0 success, 2 bad input, 1 run-time failure.
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

// Runs what the command line asks for (its parsing lives in app/shells/cli.cpp, where the fuzzer reaches it).
int run(int argc, char** argv) {
    const app::ParsedCommand command = app::parseCommandLine(argc, argv);
    using Kind = app::ParsedCommand::Kind;
    switch (command.kind) {
    case Kind::Exit:
        std::fputs(command.text.c_str(), stdout);
        return command.exitCode;
    case Kind::Render: {
        if (!command.out.empty()) {
            app::checkOutputPath(command.out);
            refuseOverwritingInput(command.out, "--out", command.scene); // before anything is rendered
        }
        const Scene scene = app::composeScene(command.scene, command.overrides);
        warnAbout(scene, command.scene);
        if (command.printMatrices) {
            printMatrices(scene);
            if (command.out.empty()) return kExitOk;
        }
        const ContextRequest context =
            app::contextFromArguments(command.backend, command.api, command.eglDevice);
        return app::runRender(scene, context, command.out, command.specialize, command.verbose);
    }
    case Kind::Bench: {
        app::BenchOptions bench = command.bench;
        Scene sized;
        app::composeSize(sized, command.benchSize);
        bench.width = sized.width;
        bench.height = sized.height;
        bench.context = app::contextFromArguments(command.backend, command.api, command.eglDevice);
        if (!command.benchJson.empty()) {
            app::checkOutputPath(command.benchJson, "--json");
            if (command.benchJson == "-")
                throw InputError("--json: - is not accepted; bench prints its table on standard output, so "
                                 "give a file name such as bench.json");
            bench.json = command.benchJson;
        }
        return app::runBench(bench);
    }
    case Kind::Reference: {
        (void)app::contextFromArguments(command.backend, command.api, ""); // validated, as render would
        app::checkOutputPath(command.out);
        refuseOverwritingInput(command.out, "--out", command.scene);
        const Scene scene = app::composeScene(command.scene, command.overrides);
        warnAbout(scene, command.scene);
        return app::runReference(scene, command.out);
    }
    case Kind::Report: {
        app::ReportOptions report;
        if (!command.scene.empty()) report.scene = command.scene;
        report.outDir = command.reportOut;
        app::parseLevels(command.reportLevels, report);
        report.includeAuto = !command.reportNoAuto;
        report.plot = !command.reportNoPlot;
        report.context = app::contextFromArguments(command.backend, command.api, command.eglDevice);
        report.frames = command.reportFrames;
        report.warmup = command.reportWarmup;
        return app::runReport(report);
    }
    case Kind::Compare:
        if (!command.compare.diff.empty()) app::checkOutputPath(command.compare.diff, "--diff");
        return app::runCompare(command.compare);
    case Kind::EglDevices:
        return app::runListEglDevices(app::apiFromArgument(command.api));
    case Kind::Check:
        return app::runCheck(command.scene);
    case Kind::Slides: {
        app::SlidesOptions slides;
        slides.lesson = command.scene;
        slides.outDir = command.slidesOutDir;
        slides.size = command.slidesSize;
        slides.captions = command.slidesCaptions;
        slides.context = app::contextFromArguments(command.backend, command.api, command.eglDevice);
        return app::runSlides(slides);
    }
    case Kind::Demo:
        break;
    }
    app::checkOutputPath(command.demo.showcaseOut, "--showcase-out");
    if (std::error_code error; !std::filesystem::is_directory(command.demo.screenshotDir, error))
        throw InputError("--screenshot-dir: " + printable(command.demo.screenshotDir.string()) +
                         (std::filesystem::exists(command.demo.screenshotDir, error)
                              ? " is not a folder; name the folder S saves its screenshots in"
                              : " does not exist; create it (mkdir -p) or name an existing folder"));
    refuseOverwritingInput(command.demo.showcaseOut, "--showcase-out", command.scene);
    app::DemoOptions demo = command.demo;
    Scene scene;
    std::variant<Scene, Lesson> read = command.scene.empty() ? Scene{} : loadSceneOrLesson(command.scene);
    if (Lesson* readLesson = std::get_if<Lesson>(&read)) {
        // A lesson: the scene flags apply to every step, as they would to each step's scene file.
        Lesson lesson = std::move(*readLesson);
        for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
            LessonStep& step = lesson.steps[i];
            step.scene = app::applyOverrides(std::move(step.scene), command.overrides, command.scene);
            warnAbout(step.scene, command.scene + ": steps[" + std::to_string(i) + "]");
        }
        scene = lesson.steps.front().scene;
        demo.lesson = std::make_shared<const Lesson>(std::move(lesson));
    } else {
        scene = app::applyOverrides(std::get<Scene>(std::move(read)), command.overrides, command.scene);
        warnAbout(scene, command.scene);
    }
    demo.api = app::apiFromArgument(command.api);
    if (command.overrides.size) { // the window takes --size when given, never the scene's image size
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
        status = run(argc, argv);
    } catch (const InputError& e) {
        printError(e);
        status = kExitInputError;
    } catch (const std::exception& e) {
        printError(e);
        status = kExitRuntimeError;
    }
    return closeStdout(status);
}
