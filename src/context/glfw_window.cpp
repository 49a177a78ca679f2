#include "shadelab/context/window.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <utility>

#include <sys/wait.h>
#include <unistd.h>

#include <GLFW/glfw3.h>

#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"
#include "shadelab/io/text.h"
#include "shadelab/key_codes.h"

namespace shadelab {

static_assert(kKeyEscape == GLFW_KEY_ESCAPE && kKeyF1 == GLFW_KEY_F1 &&
              kKeyKeypadSubtract == GLFW_KEY_KP_SUBTRACT && kKeyKeypadAdd == GLFW_KEY_KP_ADD);
static_assert(kKeySpace == GLFW_KEY_SPACE && kKeyBackspace == GLFW_KEY_BACKSPACE &&
              kKeyRight == GLFW_KEY_RIGHT && kKeyLeft == GLFW_KEY_LEFT && kKeyPageUp == GLFW_KEY_PAGE_UP &&
              kKeyPageDown == GLFW_KEY_PAGE_DOWN && kKeyHome == GLFW_KEY_HOME && kKeyEnd == GLFW_KEY_END);

namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    return code == GLFW_NO_ERROR ? "no GLFW error reported" : description ? description : "unknown";
}

} // namespace

// Where the window was before full screen, to go back to.
struct WindowedGeometry {
    int x = 0, y = 0, width = 0, height = 0;
};

// A press and release of the left button that moved less than this (in window coordinates) is a click,
// not the start of an orbit.
constexpr double kClickSlopPixels = 3;

struct Window::State {
    GLFWwindow* window = nullptr;
    WindowedGeometry windowed;
    std::function<void(int)> keyHandler;
    std::function<void(double, double)> dragHandler, rightDragHandler, clickHandler;
    std::function<void(double, double, bool)> pointerHandler;
    std::function<void(double)> scrollHandler;
    bool dragging = false, rightDragging = false;
    // Where the pointer was at the last event handled, in window coordinates: from the cursor callback,
    // in event order. glfwGetCursorPos asks the X server where the pointer is now, which under load is
    // already further along a fast drag than the press being handled (a press on the split's divider then
    // missed it: window.DemoWindow.ExactErrorSplitProfileOutsideAndNdcShowWhatRenderGives failed once in CI).
    // It is asked only when no motion has been seen since the pointer entered.
    double lastX = 0, lastY = 0;
    bool cursorKnown = false;
    double pressX = 0, pressY = 0, travelled = 0; // the left button's press, and how far it moved since

    // Window coordinates (x, y) in framebuffer pixels, which differ from them on a scaled display.
    std::pair<double, double> toFramebuffer(double x, double y) const {
        int windowWidth = 0, windowHeight = 0, width = 0, height = 0;
        glfwGetWindowSize(window, &windowWidth, &windowHeight);
        glfwGetFramebufferSize(window, &width, &height);
        const double sx = windowWidth > 0 ? double(width) / windowWidth : 1;
        const double sy = windowHeight > 0 ? double(height) / windowHeight : 1;
        return {x * sx, y * sy};
    }
    // The cursor (lastX, lastY) to the pointer handler.
    void reportPointer() const {
        if (!pointerHandler) return;
        const auto [x, y] = toFramebuffer(lastX, lastY);
        pointerHandler(x, y, dragging);
    }
    // A button pressed or released: the left one drags, or clicks where it was pressed if it moved less
    // than kClickSlopPixels; the right one drags the light.
    void buttonChanged(int button, int action) {
        if (!cursorKnown) glfwGetCursorPos(window, &lastX, &lastY);
        if (button == GLFW_MOUSE_BUTTON_RIGHT) rightDragging = action == GLFW_PRESS;
        if (button != GLFW_MOUSE_BUTTON_LEFT) return;
        dragging = action == GLFW_PRESS;
        reportPointer();
        if (action == GLFW_PRESS) {
            pressX = lastX;
            pressY = lastY;
            travelled = 0;
        } else if (travelled < kClickSlopPixels && clickHandler) {
            const auto [x, y] = toFramebuffer(pressX, pressY);
            clickHandler(x, y);
        }
    }
    void cursorMoved(double x, double y) {
        const double fromX = lastX, fromY = lastY;
        lastX = x; // the pointer handler sees the new position before the drag handler moves
        lastY = y;
        reportPointer();
        lastX = fromX;
        lastY = fromY;
        if (dragging) travelled += std::abs(x - lastX) + std::abs(y - lastY);
        if (dragging && dragHandler) dragHandler(x - lastX, y - lastY);
        if (rightDragging && rightDragHandler) rightDragHandler(x - lastX, y - lastY);
        lastX = x;
        lastY = y;
        cursorKnown = true;
    }
};

namespace {

// OpenGL 3.3 core (forward-compatible) or OpenGL ES 3.0, a 24-bit depth buffer, KHR_debug if asked.
void requestContext(Api api, bool debugContext) {
    if (api == Api::Gles) {
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    } else {
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    }
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debugContext ? GLFW_TRUE : GLFW_FALSE);
}

// Not the scene's image size (often 256×256, too small for the panel): a size fit for the screen, at most
// nine tenths of its work area.
void fitToScreen(int& width, int& height) {
    width = Window::kDefaultWidth;
    height = Window::kDefaultHeight;
    int x = 0, y = 0, areaWidth = 0, areaHeight = 0;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        glfwGetMonitorWorkarea(monitor, &x, &y, &areaWidth, &areaHeight);
        if (areaWidth > 0) width = std::min(width, areaWidth * 9 / 10);
        if (areaHeight > 0) height = std::min(height, areaHeight * 9 / 10);
    }
}

} // namespace

bool Window::displayNamed() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

std::optional<std::string> Window::unresponsiveDisplay(double seconds) {
    const pid_t child = ::fork();
    if (child < 0) return std::nullopt; // cannot ask: go on and let GLFW try
    if (child == 0) {
        // glfwInit opens the display: it returns (true or false) once the server has answered.
        const int ok = glfwInit() ? 0 : 1;
        ::_exit(ok);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        int status = 0;
        const pid_t done = ::waitpid(child, &status, WNOHANG);
        if (done == child || (done < 0 && errno != EINTR)) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(child, SIGKILL);
    while (::waitpid(child, nullptr, 0) < 0 && errno == EINTR) {
    }
    const char* display = std::getenv("DISPLAY");
    char text[512];
    std::snprintf(text, sizeof text,
                  "the display %s accepted the connection but did not answer within %.0f s "
                  "(a stopped X server?)",
                  display ? printable(display).c_str() : "(unset)", seconds);
    return std::string(text);
}

Window::Window(int width, int height, const std::string& title, bool debugContext, Api api)
    : state_(std::make_unique<State>()), api_(api) {
    if (!glfwInit()) throw DisplayUnavailable("window: cannot open the display: " + lastGlfwError());
    requestContext(api, debugContext);
    if (width <= 0 || height <= 0) fitToScreen(width, height);
    state_->window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!state_->window) {
        const std::string error = lastGlfwError();
        glfwTerminate();
        throw RuntimeError("window: the display cannot give an " + std::string(displayName(api)) +
                           " context: " + error);
    }
    glfwMakeContextCurrent(state_->window);
    glfwSwapInterval(1);
    gl::loadGl(glfwGetProcAddress, "glfw", api);
    glfwSetWindowUserPointer(state_->window, state_.get());
    // Each callback finds the window's state through the user pointer (a C callback captures nothing).
    static constexpr auto stateOf = [](GLFWwindow* w) -> State& {
        return *static_cast<State*>(glfwGetWindowUserPointer(w));
    };
    glfwSetKeyCallback(state_->window, [](GLFWwindow* w, int key, int, int action, int) {
        const State& state = stateOf(w);
        if (action == GLFW_PRESS && state.keyHandler) state.keyHandler(key);
    });
    glfwSetMouseButtonCallback(state_->window, [](GLFWwindow* w, int button, int action, int) {
        stateOf(w).buttonChanged(button, action);
    });
    glfwSetCursorPosCallback(state_->window,
                             [](GLFWwindow* w, double x, double y) { stateOf(w).cursorMoved(x, y); });
    glfwSetCursorEnterCallback(state_->window, [](GLFWwindow* w, int) {
        stateOf(w).cursorKnown = false; // moved outside meanwhile
    });
    glfwSetScrollCallback(state_->window, [](GLFWwindow* w, double, double steps) {
        const State& state = stateOf(w);
        if (state.scrollHandler) state.scrollHandler(steps);
    });
}

// No glfwTerminate: it would dlclose libGL and with it Mesa's GLX driver, whose few allocations kept until
// exit LeakSanitizer could then no longer attribute to a library (they show as "<unknown module>"); the
// demo's process ends right after its window. (The same reason keeps eglTerminate out of egl_context.cpp.)
Window::~Window() {
    glfwDestroyWindow(state_->window);
}

bool Window::shouldClose() const {
    return glfwWindowShouldClose(state_->window);
}
void Window::requestClose() {
    glfwSetWindowShouldClose(state_->window, GLFW_TRUE);
}
void Window::toggleFullScreen() {
    GLFWwindow* window = state_->window;
    if (glfwGetWindowMonitor(window)) {
        const WindowedGeometry& g = state_->windowed;
        glfwSetWindowMonitor(window, nullptr, g.x, g.y, g.width, g.height, GLFW_DONT_CARE);
        return;
    }
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!mode) return; // no monitor to fill: stay a window
    WindowedGeometry& g = state_->windowed;
    glfwGetWindowPos(window, &g.x, &g.y);
    glfwGetWindowSize(window, &g.width, &g.height);
    glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(state_->window, title.c_str());
}
void Window::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(state_->window, &width, &height);
}
void Window::swapBuffers() {
    glfwSwapBuffers(state_->window);
}
void Window::waitEvents(double timeoutSeconds) {
    glfwWaitEventsTimeout(timeoutSeconds);
}
void Window::onKeyPress(std::function<void(int)> handler) {
    state_->keyHandler = std::move(handler);
}
void Window::onDrag(std::function<void(double, double)> handler) {
    state_->dragHandler = std::move(handler);
}
void Window::onRightDrag(std::function<void(double, double)> handler) {
    state_->rightDragHandler = std::move(handler);
}
void Window::onClick(std::function<void(double, double)> handler) {
    state_->clickHandler = std::move(handler);
}
void Window::onPointer(std::function<void(double, double, bool)> handler) {
    state_->pointerHandler = std::move(handler);
}
void Window::onScroll(std::function<void(double)> handler) {
    state_->scrollHandler = std::move(handler);
}
void* Window::nativeHandle() const {
    return state_->window;
}

} // namespace shadelab
