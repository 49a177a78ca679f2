// The flags that override a scene (--shading, --lighting, --term, --normal-matrix, --perspective-matrix,
// --subdivisions, --tolerance-px, --depth, --overlay, --view, --size):
// one parser for the command line, the demo and the browser page, so a flag means the same everywhere.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadelab/scene/scene.h"

namespace shadelab {

// Flags that override the scene file. Unset flags leave the scene's values.
struct SceneOverrides {
    std::optional<std::string> shading, lighting, size;
    std::optional<std::string> term;              // all | ambient | diffuse | specular
    std::optional<std::string> normalMatrix;      // inverse-transpose | model
    std::optional<std::string> perspectiveMatrix; // webgl | unnegated
    std::optional<std::string> subdivisions;      // a level or "auto"
    std::optional<std::string> tolerancePx;       // a decimal number, parsed by composeScene
    std::optional<std::string> depth;             // standard | reversed | reversed-infinite
    std::optional<std::string> overlay;           // none | wireframe | normals | lights
    std::optional<std::string> view;              // scene | error | profile | split:A,B (view.h)
};

// The one table of these flags: each flag's name (the command line's --NAME, the page's ?NAME= and the key
// of the page's flags object), the override it sets, and its help, whose spellings come from the
// vocabulary its value is parsed with. The command line, the page and the browser's render script all read
// it.
struct SceneFlag {
    std::string_view name;
    std::optional<std::string> SceneOverrides::*value;
    std::string help;
};
const std::vector<SceneFlag>& sceneFlags(); // in the order --help lists them
// The override of the flag named `name`, or nullptr for a name no flag has.
std::optional<std::string>* overrideNamed(SceneOverrides& overrides, std::string_view name);
// "--shading, --lighting, …, --size": every flag, for messages.
std::string flagList();

// The scene file (or the DESIGN §4 defaults when `path` is empty) with the overrides applied and the
// result validated. Errors name the argument (e.g. "--size") or the JSON path.
Scene composeScene(const std::string& path, const SceneOverrides& overrides);
// The overrides applied to `scene` and the result validated; a validation error is prefixed with `path`
// (the file the values came from) unless it is empty or "-".
Scene applyOverrides(Scene scene, const SceneOverrides& overrides, const std::string& path);

// Applies "--size WxH" to the scene; InputError naming --size for anything else.
void composeSize(Scene& scene, const std::string& text);

} // namespace shadelab
