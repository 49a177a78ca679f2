#include "window/demo_process.h"
#include "shadelab/image/image_file.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace shadelab::window_test {

DemoProcess::DemoProcess(const XTools& tools, const XServer& server, const fs::path& scratch,
                         const std::string& name, std::vector<std::string> args,
                         const std::vector<std::string>& environment)
    : screenshotDir_(scratch / (name + "-screenshots")) {
    fs::create_directories(screenshotDir_);
    std::vector<std::string> argv = {SHADELAB_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.insert(argv.end(), {"--screenshot-dir", screenshotDir_.string()});
    std::vector<std::string> env;
    for (const std::string& entry : server.environment()) {
        const std::string prefix = entry.substr(0, entry.find('=') + 1);
        if (std::none_of(environment.begin(), environment.end(),
                         [&](const std::string& added) { return added.starts_with(prefix); }))
            env.push_back(entry);
    }
    env.insert(env.end(), environment.begin(), environment.end());
    child_ = std::make_unique<Child>(
        SpawnOptions{argv, env, scratch / (name + ".out"), scratch / (name + ".err")});
    const auto diedBecause = [this]() -> std::string {
        if (child_->running()) return "";
        return "the demo exited (" + child_->waitExit(Seconds(0))->describe() + ")\n" + child_->logs();
    };
    try {
        window_ = XWindow::find(tools, server, scratch, "^shadelab", diedBecause);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(e.what() + (child_->running() ? "\n" + child_->logs() : ""));
    }
}

fs::path DemoProcess::screenshot() {
    char name[32];
    std::snprintf(name, sizeof name, "shadelab-%03d", ++screenshots_);
    const fs::path stem = screenshotDir_ / name;
    window_->key("s");
    // The PNG is renamed into place after the JSON is written: once it exists, both are complete.
    if (!pollUntil([&] { return fs::exists(stem.string() + ".png"); }))
        throw std::runtime_error("S saved no " + stem.string() + ".png within " + kWaitText + "\n" +
                                 child_->logs());
    if (!fs::exists(stem.string() + ".json"))
        throw std::runtime_error("S saved " + stem.string() + ".png but no .json beside it");
    return stem;
}

ExitStatus DemoProcess::quit() {
    // The demo quits on the key press and may destroy its window before xdotool sends the release, which
    // then fails with BadWindow: that failure is the quit itself, not an error, once the demo has exited.
    try {
        window_->key("Escape");
    } catch (const std::exception&) {
        if (const std::optional<ExitStatus> status = child_->waitExit(kWaitLimit)) return *status;
        throw;
    }
    if (const std::optional<ExitStatus> status = child_->waitExit(kWaitLimit)) return *status;
    throw std::runtime_error("the demo did not exit within " + kWaitText + " of Escape\n" + child_->logs());
}

Image renderWithCli(const fs::path& scene, const fs::path& png, const fs::path& scratch,
                    const std::string& api) {
    const std::vector<std::string> argv = {SHADELAB_EXE, "render", scene.string(), "--api",
                                           api,          "--out",  png.string()};
    const ToolRun run = runTool(argv, childEnvironment(""), scratch, kWaitLimit);
    if (!run.ok()) throw std::runtime_error(run.describe(argv));
    return readPng(png);
}

} // namespace shadelab::window_test
