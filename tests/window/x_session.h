// A private X server for one test and the X tools that drive a window in it: Xvfb on a display number it
// picks itself (-displayfd), xdotool to find, focus and type into a window and read its title, and libX11's
// XGetImage to capture it. DISPLAY is set only in the children's environment. Every wait is bounded and says
// what it waited for when it gives up.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shadelab/image/image.h"
#include "window/process.h"

namespace shadelab::window_test {

// The bound on every single wait: a window appearing, a title changing, a file appearing, an exit.
inline constexpr Seconds kWaitLimit{10};
inline const std::string kWaitText = std::to_string(int(kWaitLimit.count())) + " s"; // for messages

// The programs the window tests need, found on PATH; `missing` lists those that are not.
struct XTools {
    fs::path xvfb, xdotool;
    std::vector<std::string> missing;
    static XTools find();
};

// Xvfb on a free display, killed (with everything it serves) when this goes.
class XServer {
public:
    XServer(const XTools& tools, const fs::path& scratch); // throws with Xvfb's log if it does not start
    const std::string& display() const { return display_; }
    std::vector<std::string> environment() const { return childEnvironment(display_); }

private:
    std::unique_ptr<Child> xvfb_;
    std::string display_;
};

// One top-level window of the X server, driven with xdotool and captured with XGetImage.
class XWindow {
public:
    // Waits (bounded) for a window whose name matches `nameRegex`. `diedBecause` returns why the client
    // is gone (empty while it runs), so a client that died is reported at once with its logs.
    static XWindow find(const XTools& tools, const XServer& server, const fs::path& scratch,
                        const std::string& nameRegex, const std::function<std::string()>& diedBecause);

    const std::string& id() const { return id_; }
    void focus() const;                       // xdotool windowfocus --sync (no window manager needed)
    void key(const std::string& key) const;   // xdotool key --window W <key>
    void resize(int width, int height) const; // xdotool windowsize --sync
    void click(int x, int y) const;           // left button at (x, y) of the window
    // Right button held from (x, y) while the pointer moves by (dx, dy) in `steps` steps.
    void rightDrag(int x, int y, int dx, int dy, int steps = 8) const;
    // Button `button` (1 left, 3 right) pressed at (x, y), moved by (dx, dy) in `steps`, released.
    void drag(int button, int x, int y, int dx, int dy, int steps = 8) const;
    void move(int x, int y) const; // the pointer to (x, y) of the window, no button
    std::string title() const;
    // Polls the title until it starts with `prefix`; throws with the last title after kWaitLimit.
    std::string waitForTitle(const std::string& prefix) const;
    Image capture() const; // XGetImage of the window, as RGBA rows top first

private:
    XWindow(const XTools& tools, std::vector<std::string> env, fs::path scratch, std::string id);
    std::string run(const std::vector<std::string>& argv) const; // its stdout; throws when it fails

    XTools tools_;
    std::vector<std::string> env_;
    fs::path scratch_;
    std::string id_;
};

// Polls `ready` every few milliseconds until it is true or `limit` has passed; returns whether it became
// true.
bool pollUntil(const std::function<bool()>& ready, Seconds limit = kWaitLimit);

} // namespace shadelab::window_test
