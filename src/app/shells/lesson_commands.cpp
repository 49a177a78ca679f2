// `shadelab check` and `shadelab slides` (commands.h): a lesson file read, checked and exported.
#include <cstdio>
#include <system_error>
#include <variant>

#include "app/demo/demo_state.h"
#include "app/measure/memory_budget.h"
#include "app/shells/commands.h"
#include "shadelab/context/headless.h"
#include "shadelab/errors.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/image/image_file.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab::app {
namespace {

namespace fs = std::filesystem;

void printWarnings(const Scene& scene, const std::string& where) {
    for (const std::string& warning : sceneWarnings(scene))
        std::printf("  warning: %s%s\n", where.c_str(), printable(warning).c_str());
}

} // namespace

int runCheck(const fs::path& file) {
    const std::string shown = printable(file.string());
    const std::variant<Scene, Lesson> read = loadSceneOrLesson(file);
    if (const Scene* scene = std::get_if<Scene>(&read)) {
        std::printf("%s: a scene, valid: %zu object%s, %zu light%s, %dx%d\n", shown.c_str(),
                    scene->objects.size(), scene->objects.size() == 1 ? "" : "s", scene->lights.size(),
                    scene->lights.size() == 1 ? "" : "s", scene->width, scene->height);
        printWarnings(*scene, "");
        return kExitOk;
    }
    const Lesson& lesson = std::get<Lesson>(read);
    std::printf("%s: a lesson, valid: \"%s\", %zu step%s\n", shown.c_str(), printable(lesson.title).c_str(),
                lesson.steps.size(), lesson.steps.size() == 1 ? "" : "s");
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        std::printf("  %zu. %s\n", i + 1, printable(step.title).c_str());
        printWarnings(step.scene, "steps[" + std::to_string(i) + "]: ");
    }
    return kExitOk;
}

int runSlides(const SlidesOptions& options) {
    Lesson lesson = loadLesson(options.lesson);
    const std::size_t count = lesson.steps.size();
    std::vector<std::string> names;
    double largest = 0;
    for (std::size_t i = 0; i < count; ++i) {
        LessonStep& step = lesson.steps[i];
        if (options.size) composeSize(step.scene, *options.size);
        names.push_back(slideFileName(i, count, step.title));
        largest = std::max(largest, renderBytes(step.scene));
    }
    checkMemoryBudget("the slides", kGlBaselineBytes + largest, "--size (or the steps' image size)");
    // The lesson's own folder holds its scenes: slides are written beside the lesson only if asked for
    // plainly elsewhere.
    std::error_code error;
    const fs::path lessonFolder = options.lesson.parent_path().empty() ? "." : options.lesson.parent_path();
    if (fs::exists(options.outDir, error) && fs::equivalent(options.outDir, lessonFolder, error))
        throw InputError("--out-dir: \"" + printable(options.outDir.string()) +
                         "\" is the lesson's own folder; give a folder for the slides, such as slides");
    prepareOutputFolder(options.outDir, "--out-dir", names, {options.lesson});

    HeadlessRenderer renderer(options.context);
    const std::string folder = printable(options.outDir.string());
    for (std::size_t i = 0; i < count; ++i) {
        const LessonStep& step = lesson.steps[i];
        const Scene& scene = step.scene;
        const Image picture = renderer.render(scene, [&](gl::Renderer& drawing) {
            if (!options.captions) return;
            const Image band = lessonBandImage(step.title, step.caption, scene.width, scene.height);
            drawing.drawImageOver(band, 0, scene.height - band.height, scene.width, scene.height);
        });
        writePng(picture, options.outDir / names[i]);
        std::printf("slide %zu of %zu: %s\n", i + 1, count, (fs::path(folder) / names[i]).c_str());
        std::fflush(stdout);
    }
    std::printf("wrote %zu slides in %s\n", count, folder.c_str());
    return kExitOk;
}

} // namespace shadelab::app
