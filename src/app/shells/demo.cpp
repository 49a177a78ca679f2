// The demo window: every mode on a key, an orbit camera, a live control panel. It draws through the same
// Renderer and Scene as `shadelab render`, so a screenshot (S) is the picture `render` gives for the
// scene JSON saved beside it.
#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>

#include <unistd.h>

#include "app/demo/demo_draw.h"
#include "app/demo/demo_state.h"
#include "app/shells/commands.h"
#include "app/shells/panel.h"
#include "shadelab/context/window.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/io/numbered_files.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/model.h"

namespace shadelab::app {
namespace {

// The scene as saved beside a screenshot in `folder`: each model's path made relative to that folder (a
// scene's mesh paths are relative to its own file, DESIGN §4), so the saved JSON renders where it lies.
Scene savedBeside(Scene scene, const std::filesystem::path& folder) {
    std::error_code error;
    const std::filesystem::path base = std::filesystem::absolute(folder, error).lexically_normal();
    for (SceneObject& object : scene.objects) {
        if (object.shape != Shape::Mesh || !object.model || error) continue;
        const std::filesystem::path model =
            std::filesystem::absolute(object.model->path, error).lexically_normal();
        const std::filesystem::path relative = model.lexically_relative(base);
        if (!error && !relative.empty()) object.mesh = relative.generic_string();
    }
    return scene;
}

using Clock = std::chrono::steady_clock;

// Caps the frame rate where nothing else does (Xvfb has no vsync), so a test machine is not saturated.
constexpr auto kFramePeriod = std::chrono::microseconds(1'000'000 / 60);

// Exponential moving average of the GPU-synchronized draw time.
class FrameTimer {
public:
    void add(double ms) { average_ = average_ == 0 ? ms : 0.9 * average_ + 0.1 * ms; }
    double ms() const { return average_; }

private:
    double average_ = 0;
};

class Demo {
public:
    Demo(const Scene& scene, const DemoOptions& options)
        : options_(options), state_(scene), window_(options.windowWidth, options.windowHeight,
                                                    windowTitle(state_, 0), options.glDebug, options.api),
          uiScale_(options.uiScale > 0 ? options.uiScale
                   : options.present   ? 1.75
                                       : 1.0),
          panel_(window_, uiScale_) {
        // Presenting starts with the whole window for the picture (C shows the panel).
        state_.setShowPanel(!options.hidePanel && !options.present);
        state_.setPresenting(options.present);
        panelBeforePresenting_ = !options.hidePanel;
        if (options.lesson) state_.openLesson(options.lesson);
        // Specialized to the lights only: the panel's colour and shininess sliders then recompile nothing
        // (a program per value would cost ~50 ms on llvmpipe at every step of a slider).
        renderer_.setSpecialization(gl::Specialization::Lights);
        if (options.glDebug && !gl::enableDebugOutput(&debugSink_))
            std::fprintf(stderr,
                         "shadelab: --gl-debug: the context has no KHR_debug; no GL messages will show\n");
        window_.onKeyPress([this](int key) {
            inputCame();
            onKey(key);
        });
        window_.onDrag([this](double dx, double dy) {
            inputCame();
            if (!panel_.wantsMouse()) state_.drag(dx, dy);
        });
        window_.onRightDrag([this](double dx, double dy) {
            inputCame();
            if (!panel_.wantsMouse()) state_.dragLight(dx, dy);
        });
        window_.onClick([this](double x, double y) {
            inputCame();
            onClick(x, y);
        });
        window_.onPointer([this](double x, double y, bool leftHeld) {
            inputCame();
            if (panel_.wantsMouse()) return;
            const PictureRect picture = shownPicture();
            state_.pointer(x - picture.x, y - picture.y, leftHeld);
        });
        window_.onScroll([this](double steps) {
            inputCame();
            if (!panel_.wantsMouse()) state_.zoom(steps);
        });
    }

    int run() {
        while (!window_.shouldClose()) {
            const auto start = Clock::now();
            drawFrame(start);
            window_.swapBuffers();
            window_.waitEvents(0.001);
            std::this_thread::sleep_until(start + kFramePeriod);
        }
        if (options_.glDebug && panelMessages_ > 0)
            std::fprintf(
                stderr,
                "shadelab: %d GL debug message(s) from Dear ImGui's desktop-only GL backend on OpenGL "
                "ES not shown (see src/app/shells/panel.cpp)\n",
                panelMessages_);
        if (options_.glDebug) std::fprintf(stderr, "shadelab: %d GL debug message(s)\n", debugMessages_);
        return kExitOk;
    }

private:
    // Where the picture goes in the window (pixels from the top left): the panel is a column on the left,
    // and the picture the largest rectangle of the scene's own aspect in the rest, centred, so the window
    // frames the scene as `render` does (a wide scene gets bars above and below, never a cropped side).
    PictureRect pictureRect() const {
        int width = 0, height = 0;
        window_.framebufferSize(width, height);
        return pictureRect(width, height);
    }
    PictureRect pictureRect(int width, int height) const {
        const int column = panelColumnWidth(width, state_.showPanel(), uiScale_);
        PictureRect rect = fitPicture(state_.sceneWidth(), state_.sceneHeight(), width - column, height);
        rect.x += column;
        return rect;
    }

    // Where the last frame drew the picture (above a presented lesson's band), what the pointer points in.
    PictureRect shownPicture() const { return picture_.shown().width > 0 ? picture_.shown() : pictureRect(); }

    void drawFrame(Clock::time_point now) {
        int width = 0, height = 0;
        window_.framebufferSize(width, height);
        if (width <= 0 || height <= 0) return; // minimized: nothing to draw, no NaN aspect
        drawPicture(pictureRect(width, height), width, height);
        remakeTexts(now);
        insidePanel_ = true;
        panel_.draw(state_, status_, panelColumnWidth(width, state_.showPanel(), uiScale_));
        insidePanel_ = false;
    }

    // The title (what is drawn, and the frame time) and the panel's status lines are made again in the two
    // frames after any input — the first draws what a key or the mouse changed, the second what the panel
    // changed while drawing the first — and twice a second for the time and for what changes without input
    // (a resized window's auto level); not every frame.
    void remakeTexts(Clock::time_point now) {
        if (textFramesDue_ == 0 && now < nextTexts_) return;
        textFramesDue_ = std::max(0, textFramesDue_ - 1);
        nextTexts_ = now + std::chrono::milliseconds(500);
        status_ = statusText(state_);
        std::string title = windowTitle(state_, timer_.ms());
        if (title != shownTitle_) window_.setTitle(shownTitle_ = std::move(title));
    }
    void inputCame() { textFramesDue_ = 2; }

    // The bars and the picture (FramedPicture: drawn as `render` draws, copied into its place). A target
    // that cannot be made (a huge window under a memory limit) is said once and the bars stay; the demo
    // goes on.
    void drawPicture(const PictureRect& picture, int windowWidth, int windowHeight) {
        try {
            const auto start = Clock::now();
            picture_.draw(renderer_, state_, picture, windowWidth, windowHeight);
            gl::finish();
            timer_.add(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
            pictureError_.clear();
        } catch (const std::exception& e) {
            if (e.what() != pictureError_)
                std::fprintf(stderr, "shadelab: picture not drawn: %s\n", printable(e.what()).c_str());
            pictureError_ = e.what();
        }
    }

    Scene sized(int width, int height) const { return state_.current(width, height); }

    // A click on the picture probes the surface point there (on the panel it belongs to the panel).
    void onClick(double x, double y) {
        try {
            if (panel_.wantsMouse()) return;
            const PictureRect picture = shownPicture();
            if (!picture.contains(x, y)) return; // a bar: nothing to probe
            state_.probeAt(x - picture.x, y - picture.y);
            std::printf("%s", probeText(state_).c_str());
            std::fflush(stdout);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "shadelab: click not handled: %s\n", printable(e.what()).c_str());
        }
    }

    // Called from GLFW's C callback: nothing may escape it (it would end the demo), so a failure is
    // reported and the demo goes on.
    void onKey(int key) {
        try {
            if (panel_.wantsKeyboard()) return;
            const auto command = commandForKey(key);
            if (!command) return;
            const bool wasPresenting = state_.presenting();
            if (state_.apply(*command)) {
                if (state_.presenting() != wasPresenting) presentingChanged();
                return;
            }
            if (*command == Command::Quit) window_.requestClose();
            if (*command == Command::ToggleFullScreen) window_.toggleFullScreen();
            if (*command == Command::Screenshot) saveScreenshot();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "shadelab: key not handled: %s\n", printable(e.what()).c_str());
        }
    }

    // F2 into presentation hides the panel, so the picture has the whole window for the class; F2 out of
    // it brings the panel back if it was shown before (or was shown with C meanwhile).
    void presentingChanged() {
        if (state_.presenting()) {
            panelBeforePresenting_ = state_.showPanel();
            state_.setShowPanel(false);
        } else {
            state_.setShowPanel(state_.showPanel() || panelBeforePresenting_);
        }
    }

    // The picture and its scene, each written to a temporary file of a name nobody can predict (mkstemp:
    // O_CREAT | O_EXCL, so a link or a FIFO planted in the folder is never opened), then given the first
    // free shadelab-NNN names; nothing already in the folder is ever opened or replaced.
    void saveScreenshot() {
        const PictureRect picture = pictureRect();
        const int width = picture.width, height = picture.height;
        if (width <= 0 || height <= 0) return;
        const Scene scene = sized(width, height);
        // Out of memory (a big window under a limit) or a write error: say so and keep the demo running.
        try {
            // The capture may compile programs (below), and Mesa's compiler does not survive an allocation
            // that fails: first make sure of the headroom — the picture read back and encoded, and what a
            // compile takes — so that a tight memory limit ends in "out of memory", never in a crash.
            // (operator new called itself, through a volatile pointer: a new-expression whose memory is
            // never used may be left out by the compiler.)
            constexpr std::size_t kCompileHeadroom = std::size_t(64) << 20;
            void* volatile headroom =
                ::operator new(std::size_t(width) * std::size_t(height) * 12 + kCompileHeadroom);
            ::operator delete(headroom);
            // With each object's values compiled in, as `render` draws: the window's own programs take
            // them as uniforms (a slider then recompiles nothing), which may round a highlight pixel the
            // other way; the saved picture is the one `render` gives for the saved scene, pixel for pixel.
            const gl::RenderTarget target(width, height, gl::ColorFormat::Rgba8,
                                          gl::depthFormatFor(scene.depth));
            target.bind();
            // Back to the window's own programs however the render ends (a throw too: otherwise every later
            // slider step would compile a program).
            struct WindowPrograms {
                gl::Renderer& renderer;
                ~WindowPrograms() { renderer.setSpecialization(gl::Specialization::Lights); }
            } restore{renderer_};
            renderer_.setSpecialization(gl::Specialization::Values);
            renderer_.render(scene, width, height);
            const Image image = target.readRgba8();
            gl::bindDefaultFramebuffer();
            // The scene first, the picture last: a reader that sees the PNG finds its scene beside it.
            const std::string stem =
                writeNumberedFiles(options_.screenshotDir, "shadelab-", screenshots_,
                                   {{".json", sceneToJson(savedBeside(scene, options_.screenshotDir))},
                                    {".png", encodePng(image)}});
            std::printf("%s.png\n", stem.c_str());
            std::fflush(stdout);
        } catch (const std::bad_alloc&) {
            gl::bindDefaultFramebuffer();
            std::fprintf(stderr, "shadelab: screenshot not saved: out of memory for a %dx%d capture\n", width,
                         height);
        } catch (const std::exception& e) {
            gl::bindDefaultFramebuffer();
            std::fprintf(stderr, "shadelab: screenshot not saved: %s\n", printable(e.what()).c_str());
        }
    }

    DemoOptions options_;
    // Before the window: the context may report messages until it is destroyed.
    int debugMessages_ = 0;
    // On OpenGL ES, Debian's Dear ImGui backend makes desktop-only calls every frame (panel.cpp): counted
    // apart, so --gl-debug still shows every message of shadelab's own.
    bool insidePanel_ = false;
    int panelMessages_ = 0;
    std::function<void(const std::string&)> debugSink_ = [this](const std::string& message) {
        if (insidePanel_ && options_.api == Api::Gles) {
            ++panelMessages_;
            return;
        }
        ++debugMessages_;
        std::fprintf(stderr, "shadelab: GL debug: %s\n", message.c_str());
    };
    DemoState state_;
    Window window_;
    double uiScale_; // before the panel, which is made with it
    Panel panel_;
    gl::Renderer renderer_; // after the window: its GL objects go while the context lives
    FramedPicture picture_;
    std::string pictureError_;        // the last reason the picture could not be drawn, said once
    std::string status_, shownTitle_; // remakeTexts'
    int textFramesDue_ = 2;           // frames whose texts are to be made again (the first two)
    Clock::time_point nextTexts_;
    FrameTimer timer_;
    int screenshots_ = 0;
    bool panelBeforePresenting_ = true; // whether the panel was shown when presentation mode began
};

constexpr double kDisplayAnswerSeconds = 5;

int showcaseInstead(const Scene& scene, const DemoOptions& options, const std::string& why) {
    std::fprintf(stderr, "shadelab: %s; rendering the showcase headless instead\n", why.c_str());
    return runShowcase(scene, ContextRequest{Backend::Egl, options.api, std::nullopt}, options.showcaseOut);
}

} // namespace

int runDemo(const Scene& scene, const DemoOptions& options) {
    if (!Window::displayNamed())
        return showcaseInstead(scene, options, "no display (DISPLAY and WAYLAND_DISPLAY are unset)");
    // An X server that accepts the connection but never answers (a stopped Xvfb) would hang the window
    // forever inside XOpenDisplay: ask it first, in a child we can give up on.
    if (const std::optional<std::string> silent = Window::unresponsiveDisplay(kDisplayAnswerSeconds))
        return showcaseInstead(scene, options, *silent);
    std::unique_ptr<Demo> demo;
    try {
        demo = std::make_unique<Demo>(scene, options);
    } catch (const DisplayUnavailable& e) {
        return showcaseInstead(scene, options, e.what());
    }
    return demo->run();
}

} // namespace shadelab::app
