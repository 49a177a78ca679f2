// libFuzzer target for the lesson parser (shadelab/scene/lesson.h). For any bytes, parseLesson either
// returns a lesson or throws InputError; anything else (another exception, a sanitizer report, a hang) is a
// crash. A lesson it returns keeps the limits lesson.h promises (1..kMaxLessonSteps steps, a one-line title
// of at most kMaxStepTitleBytes, a caption of at most kMaxCaptionBytes and kMaxCaptionLines lines), every
// step's scene passes validateScene, and every slide's file name is safe: two or more digits, '-', lower-case
// ASCII letters, digits and '-', ".png". A step naming a scene file gets a small fixed scene; a path with
// "missing" in it cannot be read, as a missing file.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "shadelab/errors.h"
#include "shadelab/scene/lesson.h"

namespace {

using namespace shadelab;

[[noreturn]] void crash(std::string_view what, std::string_view detail) {
    std::fprintf(stderr, "lesson_fuzzer: %.*s: %.*s\n", int(what.size()), what.data(), int(detail.size()),
                 detail.data());
    std::abort();
}

std::string readScene(const std::string& path) {
    if (path.find("missing") != std::string::npos) throw InputError("cannot read scene file: no such file");
    return R"({"image": {"width": 64, "height": 48}, "shading": "gouraud", "objects": [{"subdivisions": 2}]})";
}

bool safeSlideName(const std::string& name, std::size_t count) {
    const std::size_t dash = name.find('-');
    if (dash == std::string::npos || dash < 2 || dash < std::to_string(count).size()) return false;
    if (name.size() < 5 || name.substr(name.size() - 4) != ".png") return false;
    for (std::size_t i = 0; i < name.size() - 4; ++i) {
        const char c = name[i];
        const bool ok =
            (c >= '0' && c <= '9') || (i > dash && ((c >= 'a' && c <= 'z') || c == '-')) || i == dash;
        if (!ok) return false;
    }
    return name.size() - 4 - dash - 1 <= 64; // the title part: at most 64 bytes (slide_name.cpp)
}

void checkLesson(const Lesson& lesson) {
    if (lesson.steps.empty() || lesson.steps.size() > kMaxLessonSteps)
        crash("a lesson with a step count outside 1..kMaxLessonSteps", std::to_string(lesson.steps.size()));
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        if (step.title.size() > kMaxStepTitleBytes || step.title.find('\n') != std::string::npos)
            crash("a step title that is too long or not one line", step.title);
        if (step.caption.size() > kMaxCaptionBytes) crash("a caption over kMaxCaptionBytes", step.caption);
        int lines = step.caption.empty() ? 0 : 1;
        for (const char c : step.caption) lines += c == '\n' ? 1 : 0;
        if (lines > kMaxCaptionLines) crash("a caption over kMaxCaptionLines lines", step.caption);
        try {
            // From text no model file is read (loadSceneModels needs the lesson's folder): a mesh object's
            // scene passes the values' check, and only a loaded one the limits'.
            const bool hasMesh = std::any_of(step.scene.objects.begin(), step.scene.objects.end(),
                                             [](const SceneObject& o) { return o.shape == Shape::Mesh; });
            if (hasMesh)
                validateSceneValues(step.scene);
            else
                validateScene(step.scene);
        } catch (const InputError& e) {
            crash("an accepted step whose scene validateScene refuses", e.what());
        }
        const std::string name = slideFileName(i, lesson.steps.size(), step.title);
        if (!safeSlideName(name, lesson.steps.size())) crash("an unsafe slide file name", name);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        (void)isLessonText(text);
        checkLesson(parseLesson(text, "lesson.json", readScene));
    } catch (const InputError&) {
        // a refusal with its message: the expected outcome for hostile text
    } catch (const std::exception& e) {
        crash("an exception other than InputError", e.what());
    }
    return 0;
}
