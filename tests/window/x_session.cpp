#include "window/x_session.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "window/xwd.h"

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
    locate("xwd", "x11-apps", tools.xwd);
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

Image XWindow::capture() const {
    const fs::path file = scratch_ / ("capture-" + id_ + ".xwd");
    run({tools_.xwd.string(), "-id", id_, "-silent", "-out", file.string()});
    return readXwd(file);
}

} // namespace shadelab::window_test
