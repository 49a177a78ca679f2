// The demo window under test: `shadelab [args] --screenshot-dir DIR` in a private X server, its window,
// its S screenshots, and `shadelab render` for the picture each saved state should give.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shadelab/image/image.h"
#include "window/x_session.h"

namespace shadelab::window_test {

class DemoProcess {
public:
    // Starts the demo and waits (bounded) for its window; `name` labels its log files. `environment`
    // ("NAME=value") is added to the X server's, replacing any inherited NAME.
    DemoProcess(const XTools& tools, const XServer& server, const fs::path& scratch, const std::string& name,
                std::vector<std::string> args, const std::vector<std::string>& environment = {});

    const XWindow& window() const { return *window_; }
    // Presses S and waits (bounded) for the next shadelab-NNN.png; returns the path without extension,
    // where NNN.json (written first) is the exact state the PNG shows.
    fs::path screenshot();
    const fs::path& screenshotDir() const { return screenshotDir_; }
    // Presses Escape and waits (bounded) for the exit; throws if it does not exit.
    ExitStatus quit();
    std::string err() const { return child_->err(); }
    pid_t pid() const { return child_->pid(); }
    std::string logs() const { return child_->logs(); }

private:
    fs::path screenshotDir_;
    int screenshots_ = 0;
    std::unique_ptr<Child> child_;
    std::optional<XWindow> window_;
};

// `shadelab render <scene> --out <png>` headless, read back; throws with the command's output if it fails.
// `api`: gl or gles (render --api).
Image renderWithCli(const fs::path& scene, const fs::path& png, const fs::path& scratch,
                    const std::string& api = "gl");

} // namespace shadelab::window_test
