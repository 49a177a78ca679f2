// The command-line entry points (DESIGN §5). Each returns the process exit code; bad input throws
// InputError (exit 2) and run-time failures throw RuntimeError (exit 1), mapped in main.cpp.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/check/compare_command.h" // CompareOptions, runCompare: `shadelab compare`
#include "shadelab/context/context.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_flags.h"

namespace shadelab::app {

// Throws InputError naming `argument` if `out` cannot be a PNG output path (its folder missing, or it is a
// folder itself), before any work is done.
void checkOutputPath(const std::filesystem::path& out, const char* argument = "--out");

// --backend egl|osmesa, --api gl|gles and --egl-device N (empty: none given); InputError naming the option.
ContextRequest contextFromArguments(const std::string& backend, const std::string& api,
                                    const std::string& eglDevice);
Api apiFromArgument(const std::string& name);

// `verbose`: where the context comes from and its renderer string, on standard error.
int runRender(const Scene& scene, const ContextRequest& context, const std::filesystem::path& out,
              bool specialize = true, bool verbose = false);
// --egl-device list: one line per EGL device and what a context of `api` on it reports.
int runListEglDevices(Api api);

int runReference(const Scene& scene, const std::filesystem::path& out);
struct DemoOptions {
    std::filesystem::path showcaseOut = "shadelab-showcase.png"; // where the showcase goes without a display
    std::filesystem::path screenshotDir = ".";                   // where S saves PNG + scene JSON
    bool hidePanel = false;                // start with the control panel hidden (C shows it)
    bool glDebug = false;                  // a KHR_debug context; every GL message is printed and counted
    Api api = Api::Gl;                     // --api: desktop OpenGL 3.3 core or OpenGL ES 3.0
    bool present = false;                  // --present: the presentation label on, and larger text
    double uiScale = 0;                    // --ui-scale; 0: 1, or 1.75 with --present
    int windowWidth = 0, windowHeight = 0; // --size; 0: a size fit for the screen, not the scene's image
    std::shared_ptr<const Lesson> lesson;  // `shadelab LESSON.json`: stepped through from its first step
};

// `shadelab check FILE`: reads a lesson or a scene as the other commands would, draws nothing, and says what
// it is (each step's scene warnings included); bad input throws InputError as the other commands' does.
int runCheck(const std::filesystem::path& file);

// `shadelab slides LESSON --out-dir DIR`: one PNG per step, NN-title.png (slideFileName), each the step's
// render with its title and caption band over the bottom (lessonBandImage), or without it (`captions`
// false) pixel for pixel what `shadelab render` makes of the step's scene. DIR is created if missing and
// must not be the lesson's own folder; every name in it is checked with --out's rules before anything is
// drawn, and each file is written atomically as its step is done, with a line of progress.
struct SlidesOptions {
    std::filesystem::path lesson, outDir;      // outDir empty: no PNG files
    std::optional<std::filesystem::path> deck; // --deck FILE.html (deck.h)
    std::optional<std::string> size;           // --size WxH for every step; each step's own size without it
    bool captions = true;                      // false: --no-captions
    ContextRequest context;
};
int runSlides(const SlidesOptions& options);

// The window; without a display, the showcase rendered headless to options.showcaseOut. With a lesson,
// `scene` is its first step's.
int runDemo(const Scene& scene, const DemoOptions& options);
int runShowcase(const Scene& scene, const ContextRequest& context, const std::filesystem::path& out);

} // namespace shadelab::app
