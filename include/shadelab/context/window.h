// The demo's window: a GLFW window with a current GL 3.3 core context, the loader fed by
// glfwGetProcAddress. Only the context and the render target differ from headless rendering.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "shadelab/errors.h"
#include "shadelab/gl/api.h"

namespace shadelab {

// The display named in the environment could not be opened (a stale DISPLAY, over ssh or in a container):
// the demo falls back to the headless showcase. A display that opens but gives no GL context is a plain
// RuntimeError.
class DisplayUnavailable : public RuntimeError {
public:
    using RuntimeError::RuntimeError;
};

class Window {
public:
    // True when an X11 or Wayland display is named in the environment.
    static bool displayNamed();
    // Connects to the display in a child process and waits at most `seconds` for it to answer. Returns a
    // message naming the display when it does not answer in time (a stopped X server accepts connections
    // and never replies: opening a window would hang forever), nullopt when it answered or refused.
    static std::optional<std::string> unresponsiveDisplay(double seconds);

    // Throws RuntimeError naming the GLFW error when the display cannot give a window or a GL context.
    // `debugContext` asks for a KHR_debug context (see gl::enableDebugOutput). A width or height of 0 asks
    // for the default size: kDefaultWidth × kDefaultHeight, each at most 90 % of the primary monitor's
    // work area. `api` picks a desktop OpenGL 3.3 core or an OpenGL ES 3.0 context.
    Window(int width, int height, const std::string& title, bool debugContext = false, Api api = Api::Gl);
    static constexpr int kDefaultWidth = 1280, kDefaultHeight = 800;
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    bool shouldClose() const;
    void requestClose();
    void setTitle(const std::string& title);
    // Full screen on the primary monitor at its current mode, and back to the window it was.
    void toggleFullScreen();
    void framebufferSize(int& width, int& height) const;
    void swapBuffers();
    void waitEvents(double timeoutSeconds);
    // Called once per key press (GLFW_PRESS only: a held key does not repeat).
    void onKeyPress(std::function<void(int key)> handler);
    // Cursor movement in window pixels while the left button is held.
    void onDrag(std::function<void(double dx, double dy)> handler);
    // Cursor movement in window pixels while the right button is held.
    void onRightDrag(std::function<void(double dx, double dy)> handler);
    // A left press and release in (nearly) the same place, at framebuffer pixels from the top left.
    void onClick(std::function<void(double x, double y)> handler);
    // Every cursor move and left-button change: the position in framebuffer pixels from the top left, and
    // whether the left button is held (before the drag handler of the same move).
    void onPointer(std::function<void(double x, double y, bool leftHeld)> handler);
    // Wheel steps: positive away from the user.
    void onScroll(std::function<void(double steps)> handler);
    Api api() const { return api_; }
    // The GLFWwindow*, for Dear ImGui's GLFW backend.
    void* nativeHandle() const;

private:
    struct State;
    std::unique_ptr<State> state_;
    Api api_;
};

} // namespace shadelab
