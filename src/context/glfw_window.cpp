#include "shadelab/window.h"

#include <cstdlib>
#include <string>

#include <GLFW/glfw3.h>

#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"

namespace shadelab {

static_assert(kKeyEscape == GLFW_KEY_ESCAPE && kKeyF1 == GLFW_KEY_F1 &&
              kKeyKeypadSubtract == GLFW_KEY_KP_SUBTRACT && kKeyKeypadAdd == GLFW_KEY_KP_ADD);

namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    return code == GLFW_NO_ERROR ? "no GLFW error reported" : description ? description : "unknown";
}

} // namespace

struct Window::State {
    GLFWwindow* window = nullptr;
    std::function<void(int)> keyHandler;
};

bool Window::displayNamed() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

Window::Window(int width, int height, const std::string& title) : state_(std::make_unique<State>()) {
    if (!glfwInit()) throw RuntimeError("window: cannot open the display: " + lastGlfwError());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    state_->window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!state_->window) {
        const std::string error = lastGlfwError();
        glfwTerminate();
        throw RuntimeError("window: the display cannot give an OpenGL 3.3 core context: " + error);
    }
    glfwMakeContextCurrent(state_->window);
    glfwSwapInterval(1);
    gl::loadGl(glfwGetProcAddress, "glfw");
    glfwSetWindowUserPointer(state_->window, state_.get());
    glfwSetKeyCallback(state_->window, [](GLFWwindow* w, int key, int, int action, int) {
        auto* state = static_cast<State*>(glfwGetWindowUserPointer(w));
        if (action == GLFW_PRESS && state->keyHandler) state->keyHandler(key);
    });
}

Window::~Window() {
    glfwDestroyWindow(state_->window);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(state_->window); }
void Window::requestClose() { glfwSetWindowShouldClose(state_->window, GLFW_TRUE); }
void Window::setTitle(const std::string& title) { glfwSetWindowTitle(state_->window, title.c_str()); }
void Window::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(state_->window, &width, &height);
}
void Window::swapBuffers() { glfwSwapBuffers(state_->window); }
void Window::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }
void Window::onKeyPress(std::function<void(int)> handler) { state_->keyHandler = std::move(handler); }

} // namespace shadelab
