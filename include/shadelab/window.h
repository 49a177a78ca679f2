// The demo's window: a GLFW window with a current GL 3.3 core context, the loader fed by
// glfwGetProcAddress. Only the context and the render target differ from headless rendering.
#pragma once

#include <functional>
#include <memory>
#include <string>

namespace shadelab {

// Key codes are GLFW's (printable keys are their upper-case ASCII code); the few others used are here.
inline constexpr int kKeyEscape = 256;
inline constexpr int kKeyF1 = 290;
inline constexpr int kKeyKeypadSubtract = 333;
inline constexpr int kKeyKeypadAdd = 334;

class Window {
public:
    // True when an X11 or Wayland display is named in the environment.
    static bool displayNamed();

    // Throws RuntimeError naming the GLFW error when the display cannot give a window or a GL context.
    Window(int width, int height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    bool shouldClose() const;
    void requestClose();
    void setTitle(const std::string& title);
    void framebufferSize(int& width, int& height) const;
    void swapBuffers();
    void waitEvents(double timeoutSeconds);
    // Called once per key press (GLFW_PRESS only: a held key does not repeat).
    void onKeyPress(std::function<void(int key)> handler);

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace shadelab
