#include "window/x_session.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

// Last: Xlib defines macros (None, Status, True, False) that would rewrite names in the headers above.
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace shadelab::window_test {
namespace {

using Clock = std::chrono::steady_clock;

std::string firstLine(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

// Reads the display number Xvfb writes to its -displayfd when it is ready to accept clients.
std::string readDisplayNumber(int fd, Child& xvfb) {
    std::string text;
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(kWaitLimit);
    while (text.find('\n') == std::string::npos) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
        if (left.count() <= 0)
            throw std::runtime_error("Xvfb did not report a display within " + kWaitText + "\n" +
                                     xvfb.logs());
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, int(left.count())) < 0 && errno != EINTR)
            throw std::runtime_error(std::string("poll on Xvfb's -displayfd: ") + std::strerror(errno));
        if (p.revents == 0) continue;
        char buffer[64];
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n == 0)
            throw std::runtime_error("Xvfb closed -displayfd without a display number\n" + xvfb.logs());
        if (n > 0) text.append(buffer, std::size_t(n));
    }
    return firstLine(text);
}

} // namespace

bool pollUntil(const std::function<bool()>& ready, Seconds limit) {
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(limit);
    for (;;) {
        if (ready()) return true;
        if (Clock::now() >= deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

XTools XTools::find() {
    XTools tools;
    auto locate = [&](const char* name, const char* package, fs::path& out) {
        if (auto path = findOnPath(name))
            out = *path;
        else
            tools.missing.push_back(std::string(name) + " (Debian package " + package + ")");
    };
    locate("Xvfb", "xvfb", tools.xvfb);
    locate("xdotool", "xdotool", tools.xdotool);
    return tools;
}

XServer::XServer(const XTools& tools, const fs::path& scratch) {
    int pipeFds[2];
    if (::pipe2(pipeFds, O_CLOEXEC) != 0)
        throw std::runtime_error(std::string("pipe2: ") + std::strerror(errno));
    try {
        xvfb_ = std::make_unique<Child>(SpawnOptions{
            {tools.xvfb.string(), "-displayfd", "3", "-screen", "0", "1024x768x24", "-nolisten", "tcp"},
            childEnvironment(""),
            scratch / "xvfb.out",
            scratch / "xvfb.err",
            pipeFds[1]});
    } catch (...) {
        ::close(pipeFds[0]);
        ::close(pipeFds[1]);
        throw;
    }
    ::close(pipeFds[1]); // only Xvfb writes now, so its exit reads as end of file
    try {
        display_ = ":" + readDisplayNumber(pipeFds[0], *xvfb_);
    } catch (...) {
        ::close(pipeFds[0]);
        throw;
    }
    ::close(pipeFds[0]);
}

XWindow::XWindow(const XTools& tools, std::vector<std::string> env, fs::path scratch, std::string id)
    : tools_(tools), env_(std::move(env)), scratch_(std::move(scratch)), id_(std::move(id)) {}

XWindow XWindow::find(const XTools& tools, const XServer& server, const fs::path& scratch,
                      const std::string& nameRegex, const std::function<std::string()>& diedBecause) {
    // `search --sync` blocks until the window exists; run it in slices so a client that died is seen.
    const std::vector<std::string> argv = {tools.xdotool.string(), "search", "--sync", "--name", nameRegex};
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(kWaitLimit);
    ToolRun last;
    while (Clock::now() < deadline) {
        last = runTool(argv, server.environment(), scratch, Seconds(1));
        if (last.ok() && !firstLine(last.out).empty())
            return XWindow(tools, server.environment(), scratch, firstLine(last.out));
        if (const std::string why = diedBecause(); !why.empty())
            throw std::runtime_error("no window named /" + nameRegex + "/: " + why);
    }
    throw std::runtime_error("no window named /" + nameRegex + "/ appeared within " + kWaitText + "; last " +
                             last.describe(argv));
}

std::string XWindow::run(const std::vector<std::string>& argv) const {
    const ToolRun result = runTool(argv, env_, scratch_, kWaitLimit);
    if (!result.ok()) throw std::runtime_error(result.describe(argv));
    return result.out;
}

// A window found by its name may not be mapped yet: X refuses focus to an unviewable window (BadMatch in
// X_SetInputFocus, seen under load). Retried until it is viewable, within kWaitLimit; the last failure is
// thrown.
void XWindow::focus() const {
    std::string failure;
    const bool focused = pollUntil([&] {
        try {
            run({tools_.xdotool.string(), "windowfocus", "--sync", id_});
            return true;
        } catch (const std::exception& e) {
            failure = e.what();
            return false;
        }
    });
    if (!focused) throw std::runtime_error(failure);
}

void XWindow::key(const std::string& key) const {
    run({tools_.xdotool.string(), "key", "--window", id_, key});
}

void XWindow::click(int x, int y) const {
    run({tools_.xdotool.string(), "mousemove", "--window", id_, std::to_string(x), std::to_string(y), "click",
         "1"});
}

void XWindow::rightDrag(int x, int y, int dx, int dy, int steps) const {
    drag(3, x, y, dx, dy, steps);
}

void XWindow::drag(int button, int x, int y, int dx, int dy, int steps) const {
    const std::string which = std::to_string(button);
    run({tools_.xdotool.string(), "mousemove", "--window", id_, std::to_string(x), std::to_string(y),
         "mousedown", which});
    for (int i = 0; i < steps; ++i)
        run({tools_.xdotool.string(), "mousemove_relative", "--", std::to_string(dx / steps),
             std::to_string(dy / steps)});
    run({tools_.xdotool.string(), "mouseup", which});
}

void XWindow::move(int x, int y) const {
    run({tools_.xdotool.string(), "mousemove", "--window", id_, std::to_string(x), std::to_string(y)});
}

void XWindow::resize(int width, int height) const {
    run({tools_.xdotool.string(), "windowsize", "--sync", id_, std::to_string(width),
         std::to_string(height)});
}

std::string XWindow::title() const {
    return firstLine(run({tools_.xdotool.string(), "getwindowname", id_}));
}

std::string XWindow::waitForTitle(const std::string& prefix) const {
    std::string last;
    if (pollUntil([&] { return (last = title()).starts_with(prefix); })) return last;
    throw std::runtime_error("the title did not become \"" + prefix + "...\" within " + kWaitText +
                             "; it is \"" + last + "\"");
}

namespace {

// X reports a failed request (a window gone or not yet viewable) to an error handler whose default ends
// the process; this one records the error code for the request that caused it.
int lastXError = 0;
int recordXError(::Display*, XErrorEvent* event) {
    lastXError = event->error_code;
    return 0;
}

// Where `mask` (a visual's channel mask) keeps its 8 bits.
int shiftOf(unsigned long mask) {
    int shift = 0;
    while (mask && !(mask & 1)) {
        mask >>= 1;
        ++shift;
    }
    return shift;
}

// libX11's calls block until the server answers: a stopped or wedged Xvfb would hold the test forever. This
// ends the test process with a message naming the call when `limit` passes before it is destroyed.
class Watchdog {
public:
    Watchdog(Seconds limit, std::string what)
        : thread_([this, limit, what = std::move(what)] {
              std::unique_lock lock(mutex_);
              if (!done_.wait_for(lock, limit, [this] { return finished_; })) {
                  std::fprintf(stderr, "%s did not finish within %d s: the X server does not answer\n",
                               what.c_str(), int(limit.count()));
                  std::_Exit(1);
              }
          }) {}
    ~Watchdog() {
        {
            const std::lock_guard lock(mutex_);
            finished_ = true;
        }
        done_.notify_one();
        thread_.join();
    }
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

private:
    std::mutex mutex_;
    std::condition_variable done_;
    bool finished_ = false;
    std::thread thread_;
};

} // namespace

// libX11's XGetImage, what the xwd tool itself calls: the window's pixels as a ZPixmap, each pixel's
// channels picked out by the visual's masks. A 24-bit TrueColor window (what Xvfb -screen …x24 gives) is
// the only kind decoded; anything else is an error naming what it got.
Image XWindow::capture() const {
    std::string name;
    for (const std::string& entry : env_)
        if (entry.starts_with("DISPLAY=")) name = entry.substr(8);
    const Watchdog watchdog(kWaitLimit, "capturing window " + id_ + " on display " + name);
    ::Display* display = XOpenDisplay(name.c_str());
    if (!display) throw std::runtime_error("XOpenDisplay(\"" + name + "\") failed");
    const std::unique_ptr<::Display, int (*)(::Display*)> closer(display, XCloseDisplay);
    const auto previous = XSetErrorHandler(recordXError);
    lastXError = 0;
    const ::Window window = ::Window(std::stoul(id_));
    XWindowAttributes attributes{};
    XImage* image = nullptr;
    if (XGetWindowAttributes(display, window, &attributes))
        image = XGetImage(display, window, 0, 0, unsigned(attributes.width), unsigned(attributes.height),
                          AllPlanes, ZPixmap);
    XSync(display, False);
    XSetErrorHandler(previous);
    if (!image || lastXError)
        throw std::runtime_error("XGetImage of window " + id_ + " failed (X error " +
                                 std::to_string(lastXError) + ")");
    // XDestroyImage is a macro calling the image's own destroy function.
    const std::unique_ptr<XImage, int (*)(XImage*)> destroyer(image,
                                                              [](XImage* i) { return XDestroyImage(i); });
    if (image->depth != 24 || image->bits_per_pixel != 32 || attributes.visual->c_class != TrueColor)
        throw std::runtime_error("window " + id_ +
                                 ": expected a 24-bit TrueColor window at 32 bits per pixel, got depth " +
                                 std::to_string(image->depth) + " at " +
                                 std::to_string(image->bits_per_pixel) + " bits per pixel");
    const unsigned long masks[3] = {image->red_mask, image->green_mask, image->blue_mask};
    Image out(image->width, image->height);
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x) {
            const unsigned long pixel = XGetPixel(image, x, y);
            std::uint8_t* rgba = out.pixel(x, y);
            for (int c = 0; c < 3; ++c) rgba[c] = std::uint8_t((pixel & masks[c]) >> shiftOf(masks[c]));
            rgba[3] = 255;
        }
    return out;
}

} // namespace shadelab::window_test
