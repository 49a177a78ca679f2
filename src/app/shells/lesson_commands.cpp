// `shadelab check` and `shadelab slides` (commands.h): a lesson file read, checked and exported.
#include <array>
#include <cstdio>
#include <system_error>
#include <variant>

#include "app/demo/demo_draw.h"
#include "app/demo/presentation_images.h"
#include "app/measure/bundled_scenes.h"
#include "app/measure/memory_budget.h"
#include "app/shells/commands.h"
#include "app/shells/deck.h"
#include "shadelab/context/headless.h"
#include "shadelab/errors.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/image/image.h"
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

// Everything `render` checks before it draws a scene (validateScene: its values, its work, the outside
// view's float range; then the memory a render needs), so that `check` says valid only what `render` and
// `slides` draw.
void checkDrawable(const Scene& scene) {
    validateScene(scene);
    checkMemoryBudget("a render of " + sizeText(scene), kGlBaselineBytes + renderBytes(scene),
                      "--size (or the scene's image)");
}

// Where a step's message comes from: the lesson, the step and the scene file its scene starts from.
std::string stepWhere(const fs::path& lesson, std::size_t index, const LessonStep& step) {
    std::string where =
        printable(lesson.string()) + ": steps[" + std::to_string(index) + "] (" + quotedValue(step.title);
    if (!step.file.empty()) where += ", scene file " + quotedValue(step.file);
    return where + ")";
}

// Every step drawable, checked before anything is drawn: a refusal names the lesson, the step and its file.
void checkSteps(const fs::path& file, const Lesson& lesson) {
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        try {
            checkDrawable(lesson.steps[i].scene);
        } catch (const InputError& e) {
            throw InputError(stepWhere(file, i, lesson.steps[i]) + ": " + e.what());
        } catch (const RuntimeError& e) {
            throw RuntimeError(stepWhere(file, i, lesson.steps[i]) + ": " + e.what());
        }
    }
}

// The characters of a step's title and caption that the band's font cannot draw (each a box on the slide).
std::vector<std::string> glyphWarnings(const LessonStep& step, std::size_t index) {
    std::vector<std::string> warnings;
    const std::pair<const char*, const std::string*> texts[] = {{"title", &step.title},
                                                                {"caption", &step.caption}};
    for (const auto& [field, text] : texts) {
        const std::vector<char32_t> missing = missingGlyphs(*text);
        if (missing.empty()) continue;
        std::string codes;
        for (std::size_t k = 0; k < missing.size() && k < 8; ++k) {
            std::array<char, 16> code{};
            std::snprintf(code.data(), code.size(), "U+%04X", unsigned(missing[k]));
            codes += (k ? ", " : "") + std::string(code.data());
        }
        if (missing.size() > 8) codes += " and " + std::to_string(missing.size() - 8) + " more";
        warnings.push_back("steps[" + std::to_string(index) + "]." + field + ": the band's font (" +
                           fontName() + ") has no glyph for " + codes + "; each is drawn as a box");
    }
    return warnings;
}

} // namespace

int runCheck(const fs::path& file) {
    const std::string shown = printable(file.string());
    const std::variant<Scene, Lesson> read = loadSceneOrLessonWithModels(file);
    if (const Scene* scene = std::get_if<Scene>(&read)) {
        try {
            checkDrawable(*scene);
        } catch (const InputError& e) {
            throw InputError(shown + ": " + e.what());
        }
        std::printf("%s: a scene, valid: %zu object%s, %zu light%s, %dx%d\n", shown.c_str(),
                    scene->objects.size(), scene->objects.size() == 1 ? "" : "s", scene->lights.size(),
                    scene->lights.size() == 1 ? "" : "s", scene->width, scene->height);
        printWarnings(*scene, "");
        return kExitOk;
    }
    const Lesson& lesson = std::get<Lesson>(read);
    checkSteps(file, lesson);
    std::printf("%s: a lesson, valid: \"%s\", %zu step%s\n", shown.c_str(), printable(lesson.title).c_str(),
                lesson.steps.size(), lesson.steps.size() == 1 ? "" : "s");
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        std::string changes;
        for (const std::size_t object : step.changedObjects)
            changes += (changes.empty() ? " (changes objects[" : ", objects[") + std::to_string(object) + "]";
        std::printf("  %zu. %s%s\n", i + 1, printable(step.title).c_str(),
                    changes.empty() ? "" : (changes + ")").c_str());
        printWarnings(step.scene, "steps[" + std::to_string(i) + "]: ");
        for (const std::string& warning : glyphWarnings(step, i))
            std::printf("  warning: %s\n", printable(warning).c_str());
    }
    return kExitOk;
}

namespace {

// The lesson `slides` exports; a scene is refused with what takes it.
Lesson slidesLesson(const fs::path& file) {
    std::variant<Scene, Lesson> read = loadSceneOrLessonWithModels(file);
    if (std::holds_alternative<Scene>(read))
        throw InputError(printable(file.string()) +
                         ": a scene, not a lesson (it has no \"steps\"): `shadelab slides` exports a "
                         "lesson's steps; `shadelab render SCENE --out FILE.png` draws a scene");
    return std::get<Lesson>(std::move(read));
}

// What the slides must never replace: the lesson and every scene file its steps name.
std::vector<fs::path> lessonInputs(const fs::path& file, const Lesson& lesson) {
    const fs::path folder = file.parent_path();
    std::vector<fs::path> inputs{file};
    for (const std::string& scene : lesson.sceneFiles) inputs.push_back(folder / scene);
    return inputs;
}

} // namespace

int runSlides(const SlidesOptions& options) {
    Lesson lesson = slidesLesson(options.lesson);
    const std::size_t count = lesson.steps.size();
    std::vector<std::string> names;
    for (std::size_t i = 0; i < count; ++i) {
        LessonStep& step = lesson.steps[i];
        if (options.size) composeSize(step.scene, *options.size);
        names.push_back(slideFileName(i, count, step.title));
    }
    checkSteps(options.lesson, lesson); // every step before the first slide: no export stops half-way
    if (options.captions)
        for (std::size_t i = 0; i < count; ++i)
            for (const std::string& warning : glyphWarnings(lesson.steps[i], i))
                std::fprintf(stderr, "shadelab: warning: %s\n", printable(warning).c_str());
    // The lesson's own folder holds its scenes: slides are written beside the lesson only if asked for
    // plainly elsewhere.
    std::error_code error;
    const fs::path lessonFolder = options.lesson.parent_path().empty() ? "." : options.lesson.parent_path();
    const bool files = !options.outDir.empty();
    if (files && fs::exists(options.outDir, error) && fs::equivalent(options.outDir, lessonFolder, error))
        throw InputError("--out-dir: \"" + printable(options.outDir.string()) +
                         "\" is the lesson's own folder; give a folder for the slides, such as slides");
    if (files) prepareOutputFolder(options.outDir, "--out-dir", names, lessonInputs(options.lesson, lesson));
    std::optional<Deck> deck;
    if (options.deck) deck.emplace(*options.deck, lessonInputs(options.lesson, lesson));

    HeadlessRenderer renderer(options.context);
    const std::string folder = printable(options.outDir.string());
    for (std::size_t i = 0; i < count; ++i) {
        const LessonStep& step = lesson.steps[i];
        const Scene& scene = step.scene;
        // With captions, as the window and the page present the step: the picture above the band
        // (pictureAboveBand), made opaque, then the band, over a bare scene of the bars' colour.
        const Image band = options.captions
                               ? lessonBandImage(step.title, step.caption, scene.width, scene.height)
                               : Image(0, 0);
        const PictureRect place =
            pictureAboveBand(scene.width, scene.height, scene.width, scene.height, band.height);
        // (A band as tall as the slide leaves no picture: a slide of a few pixels.)
        Image picture = place.width > 0 && place.height > 0
                            ? renderer.render(atSize(scene, place.width, place.height))
                            : Image(0, 0);
        if (options.captions) {
            for (std::size_t k = 3; k < picture.rgba.size(); k += 4) picture.rgba[k] = 255;
            Scene bars = atSize(Scene{}, scene.width, scene.height);
            bars.objects.clear();
            bars.background = glm::dvec3(kBarColour);
            picture = renderer.render(bars, [&](gl::Renderer& drawing) {
                if (picture.width > 0)
                    drawing.drawImageOver(picture, place.x, place.y, scene.width, scene.height);
                drawing.drawImageOver(band, 0, scene.height - band.height, scene.width, scene.height);
            });
        }
        if (deck) deck->add(encodePng(picture));
        if (!files) continue;
        writePng(picture, options.outDir / names[i], /*inFolder=*/true);
        std::printf("slide %zu of %zu: %s\n", i + 1, count, (fs::path(folder) / names[i]).c_str());
        std::fflush(stdout);
    }
    if (files) std::printf("wrote %zu slides in %s\n", count, folder.c_str());
    if (deck) {
        deck->write(lesson);
        std::printf("wrote the deck of %zu slides: %s\n", count, printable(options.deck->string()).c_str());
    }
    return kExitOk;
}

} // namespace shadelab::app
