// The page's browser tests' shared parts (browser_support.h).
#include "web/browser_support.h"

namespace shadelab::test::web_test {

std::vector<std::uint8_t> base64Decode(const std::string& text) {
    static const std::string kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<std::uint8_t> out;
    out.reserve(text.size() / 4 * 3);
    unsigned bits = 0;
    int count = 0;
    for (char c : text) {
        const std::size_t value = kAlphabet.find(c);
        if (value == std::string::npos) continue; // '=' padding
        bits = (bits << 6) | unsigned(value);
        count += 6;
        if (count >= 8) {
            count -= 8;
            out.push_back(std::uint8_t((bits >> count) & 0xff));
        }
    }
    return out;
}

bool Session::run(const fs::path& folder) {
    std::string input;
    for (const json& request : requests_) input += request.dump() + "\n";
    input += R"({"op": "quit"})"
             "\n";
    RunOptions options;
    options.program = "/usr/bin/python3";
    options.stdinText = input;
    options.stdoutPath = folder / "answers.jsonl";
    options.timeout = std::chrono::seconds(240);
    std::ofstream(*options.stdoutPath).close();
    const Outcome driver = runWith({SHADELAB_WEB_DRIVER, "session"}, folder, options);
    EXPECT_EQ(driver.exitCode, 0) << driver.err;
    std::ifstream answers(*options.stdoutPath);
    for (std::string line; std::getline(answers, line);) answers_.push_back(json::parse(line));
    if (answers_.size() != requests_.size()) {
        ADD_FAILURE() << "the driver answered " << answers_.size() << " of " << requests_.size()
                      << " requests\n"
                      << driver.err;
        return false;
    }
    for (std::size_t i = 0; i < answers_.size(); ++i)
        if (!answers_[i].value("ok", false)) {
            ADD_FAILURE() << "request " << requests_[i].dump().substr(0, 200) << " failed: " << answers_[i];
            return false;
        }
    return true;
}

Image Session::image(std::size_t i) const {
    const json& a = answers_.at(i);
    Image image(a.at("width"), a.at("height"));
    const std::vector<std::uint8_t> bytes = base64Decode(a.at("data"));
    EXPECT_EQ(bytes.size(), image.rgba.size());
    std::copy_n(bytes.begin(), std::min(bytes.size(), image.rgba.size()), image.rgba.begin());
    return image;
}
ImageF Session::imageF(std::size_t i) const {
    const json& a = answers_.at(i);
    ImageF image(a.at("width"), a.at("height"));
    const std::vector<std::uint8_t> bytes = base64Decode(a.at("data"));
    EXPECT_EQ(bytes.size(), image.rgba.size() * sizeof(float));
    std::memcpy(image.rgba.data(), bytes.data(), std::min(bytes.size(), image.rgba.size() * sizeof(float)));
    return image;
}

// Why no browser test can run here, or "".
std::string browserUnavailable() {
    if (!fs::exists(fs::path(SHADELAB_WEB_BUILD) / "shadelab.wasm"))
        return std::string(SHADELAB_WEB_BUILD) + " holds no browser build (scripts/web.sh build)";
    if (!fs::exists("/usr/bin/chromium") || !fs::exists("/usr/bin/chromedriver"))
        return "no Debian chromium / chromium-driver (scripts/web.sh build installs them)";
    // Selenium reaches chromedriver at "localhost": a root made by debootstrap has no /etc/hosts, and every
    // page test then failed after 30 s with "Can not connect to the Service".
    addrinfo* found = nullptr;
    if (::getaddrinfo("localhost", nullptr, nullptr, &found) != 0)
        return "the name localhost does not resolve (no /etc/hosts?): chromedriver is reached through it; "
               "add "
               "'127.0.0.1 localhost' to /etc/hosts";
    ::freeaddrinfo(found);
    return "";
}

// No WebGL error, warning or uncaught exception in the console during the session.
void expectCleanConsole(const json& entries) {
    for (const json& entry : entries) {
        const std::string message = entry.value("message", "");
        EXPECT_NE(entry.value("level", ""), "SEVERE") << message;
        EXPECT_EQ(message.find("WebGL"), std::string::npos) << message;
        EXPECT_EQ(message.find("GL_INVALID"), std::string::npos) << message;
    }
}

// Browser against native: the interior within 2/255; SwiftShader and llvmpipe rasterize the silhouette
// differently (measured: about 1 % of a sphere's pixels), so up to 1.5 % of the pixels may differ more.
Tolerance swiftShaderTolerance(const Image& image) {
    return Tolerance{2, 0.6, int(0.015 * image.width * image.height)};
}

ImageF asFloat(const Image& image) {
    ImageF out(image.width, image.height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) out.rgba[i] = float(image.rgba[i]) / 255.0f;
    return out;
}

// Native OpenGL ES renders, the browser's counterpart (tests link the headless renderer).
HeadlessRenderer& nativeGles() {
    static HeadlessRenderer renderer(ContextRequest{Backend::Egl, Api::Gles, std::nullopt});
    return renderer;
}

std::vector<AnalyticCapture> captureAnalyticCases(Session& session, ShadingMode mode, int level) {
    std::vector<AnalyticCapture> items;
    for (const AnalyticCase& c : analyticCases()) {
        for (LightingModel model : kLightingModels) {
            Scene scene = c.scene();
            scene.shading = mode;
            scene.lighting = model;
            for (SceneObject& o : scene.objects) o.subdivisions = level;
            session.load(scene);
            items.push_back(
                {std::string(c.name) + "/" + std::string(toString(model)), scene, session.capture("float")});
        }
    }
    return items;
}

fs::path makeLessonFolder(const fs::path& dir) {
    const fs::path folder = dir / "own", outside = dir / "outside";
    fs::create_directories(folder / "scenes");
    fs::create_directories(outside);
    const std::string lesson = R"({"title": "Own <i>lesson</i>", "steps": [
      {"title": "Ring", "caption": "A scene of my own.", "scene": "scenes/ring.json"},
      {"title": "Gouraud", "caption": "The same, Gouraud.", "shading": "gouraud"}]})";
    std::ofstream(folder / kOwnLessonName) << lesson;
    std::ofstream(folder / "scenes" / "ring.json")
        << R"({"image": {"width": 160, "height": 120}, "shading": "flat", "objects": [{"subdivisions": 2}]})";
    std::ofstream(folder / "plain.json") << R"({"shading": "flat"})";
    std::ofstream(folder / "broken.json") << "{\"steps\": ";
    std::ofstream(folder / ".hidden.json") << lesson;
    std::ofstream(outside / "secret.json") << R"({"title": "Not yours", "steps": []})";
    fs::create_symlink(outside / "secret.json", folder / "linked.json");
    return folder;
}

} // namespace shadelab::test::web_test
