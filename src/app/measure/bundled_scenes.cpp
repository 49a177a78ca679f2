#include "app/measure/bundled_scenes.h"

#include "shadelab/errors.h"

namespace shadelab::app {

Scene bundledScene(std::string_view fileName) {
    const auto text = bundledSceneText(fileName);
    if (!text) throw RuntimeError("scene " + std::string(fileName) + " is not bundled in this binary");
    return parseScene(*text, fileName);
}

} // namespace shadelab::app
