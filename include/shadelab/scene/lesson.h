// A lesson: the views a lecturer steps through in front of a class, prepared as one JSON file (README
// "Lessons", DESIGN §4). Each step has a title, a short caption and a scene: written inline, named by a path
// relative to the lesson file, or the previous step's scene, with the scene values the step changes.
//
//   {"title": "Lighting", "steps": [
//     {"title": "Flat shading", "caption": "One normal per face.", "scene": "../scenes/default.json",
//      "shading": "flat"},
//     {"title": "Gouraud shading", "caption": "Lit at the vertices, interpolated.", "shading": "gouraud"}]}
//
// A step's changes use the scene's own names ("shading", "camera", "lights", ...): an object value is merged
// into the scene's (RFC 7386: "camera": {"eye": [0, 0, 6]} changes only the eye), any other value replaces
// it. "subdivisions" (a level or "auto") sets every object's level, as --subdivisions does. "objects" written
// as an object patches objects of the scene's list by index, {"1": {"material": {"shininess": 200}}}, and
// "all_objects": {…} patches every object, the list kept (an array still replaces it). Every value goes
// through parseScene, so a lesson refuses what a scene refuses, in the same words, with the step's JSON path.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "shadelab/scene/scene.h"

namespace shadelab {

struct LessonStep {
    std::string title;   // one line
    std::string caption; // plain text, at most kMaxCaptionLines lines ("" for none)
    std::string notes;   // the speaker's notes: plain text, never drawn on the slide ("" for none)
    Scene scene;         // as the step is written: its scene with its changes
    std::string file;    // the scene file its scene starts from (its own or an earlier step's), as the
                         // lesson writes it; "" for an inline scene or the defaults
    std::vector<std::size_t> changedObjects; // the objects its "objects": {"i": …} or "all_objects" change
};

struct Lesson {
    std::string title;
    std::vector<LessonStep> steps;       // at least one
    std::vector<std::string> sceneFiles; // the scene files its steps name, each once, as written
};

inline constexpr std::size_t kMaxLessonSteps = 500;
inline constexpr std::size_t kMaxStepTitleBytes = 120;
inline constexpr std::size_t kMaxCaptionBytes = 800;
inline constexpr int kMaxCaptionLines = 8;
inline constexpr std::size_t kMaxNotesBytes = 8000; // a page of speaker's notes
inline constexpr int kMaxNotesLines = 100;
// A lesson's work is bounded as a scene's is (kMaxSceneBytes): its scene files are read and parsed once
// each, and its steps parse at most four of the largest scenes' text in all, each step counting its whole
// scene (a step that names a large file parses all of it again). The page fetches at most as much.
inline constexpr std::size_t kMaxLessonSceneBytes = 4 * kMaxSceneBytes;

// The text of the scene file a step names ("scene": "path"), the path as written in the lesson; throws
// InputError saying why it cannot be read. The command line reads the file beside the lesson; the page, the
// copy it fetched or was given.
using SceneTextReader = std::function<std::string(const std::string& path)>;

// Whether parsed JSON text is a lesson rather than a scene: an object with a "steps" key. False for text
// that is not JSON (the scene parser then says what is wrong with it).
bool isLessonText(std::string_view jsonText);

// Throws InputError "<source>: <JSON path>: <reason>", e.g. "lighting.json: steps[3].shading: must be one of
// flat, gouraud, phong, toon, exact, got \"glossy\"", or for a scene file a step names, "lighting.json:
// steps[1].scene: cannot read scene file ...".
Lesson parseLesson(std::string_view jsonText, std::string_view source, const SceneTextReader& readScene);

// The name of step `index` (0-based) of `count` as `shadelab slides` writes it: its number, zero-padded so
// that sorting the names gives the steps' order, and its title made safe for any file system: lower-case
// ASCII words joined by '-', the lecture's symbols spelled out (src/scene/slide_name.cpp: α "alpha", ⁻¹
// "inverse", ᵀ "transpose", ² "squared", a minus before a digit "minus"), any other run of bytes one '-', at
// most 64 bytes cut at a word's end: "03-the-view-volume.png",
// "18-normals-transformed-by-m-inverse-transpose.png".
std::string slideFileName(std::size_t index, std::size_t count, std::string_view title);

} // namespace shadelab
