// The demo window. Its full key set and control panel come later; here: every shading mode on a key,
// Phong ↔ Blinn-Phong, quit. It draws through the same Renderer and Scene as `shadelab render`.
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "app/commands.h"
#include "shadelab/errors.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/window.h"

namespace shadelab::app {
namespace {

constexpr double kFrameSeconds = 1.0 / 60; // caps the frame rate where there is no vsync (Xvfb)

std::string title(const Scene& scene) {
    return "shadelab — " + std::string(toString(scene.shading)) + " shading, " +
           std::string(toString(scene.lighting)) + " lighting   [1-4 / F G P T: shading, B: lighting, Esc]";
}

void handleKey(int key, Scene& scene, Window& window) {
    switch (key) {
    case '1': case 'F': scene.shading = ShadingMode::Flat; break;
    case '2': case 'G': scene.shading = ShadingMode::Gouraud; break;
    case '3': case 'P': scene.shading = ShadingMode::Phong; break;
    case '4': case 'T': scene.shading = ShadingMode::Toon; break;
    case 'B':
        scene.lighting =
            scene.lighting == LightingModel::Phong ? LightingModel::BlinnPhong : LightingModel::Phong;
        break;
    case kKeyEscape: window.requestClose(); break;
    default: return;
    }
    window.setTitle(title(scene));
}

} // namespace

int runDemo(const Scene& initial, const std::filesystem::path& showcaseOut) {
    if (!Window::displayNamed()) {
        std::fprintf(stderr, "shadelab: no display (DISPLAY and WAYLAND_DISPLAY are unset); rendering the "
                             "showcase headless instead\n");
        return runShowcase(initial, Backend::Egl, showcaseOut);
    }
    Scene scene = initial;
    Window window(scene.width, scene.height, title(scene));
    window.onKeyPress([&](int key) { handleKey(key, scene, window); });
    gl::Renderer renderer;
    while (!window.shouldClose()) {
        const auto start = std::chrono::steady_clock::now();
        int width = 0, height = 0;
        window.framebufferSize(width, height);
        renderer.render(scene, width, height); // 0×0 when minimized: draws nothing
        window.swapBuffers();
        window.waitEvents(kFrameSeconds);
        std::this_thread::sleep_until(start + std::chrono::duration<double>(kFrameSeconds));
    }
    return kExitOk;
}

} // namespace shadelab::app
