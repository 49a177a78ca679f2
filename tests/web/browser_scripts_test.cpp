// scripts/web.sh render and serve: the command line's rules and messages, and a server that gives the page
// and nothing else (browser_support.h: the session and fixture).

#include "web/browser_support.h"

namespace shadelab::test {
namespace {

using namespace web_test;

// A shell line run by /bin/sh in `dir`: what scripts/web.sh render (`web`) and `shadelab render - --out -`
// (`cli`) answer for the same redirections.
Outcome shell(const std::string& line, const fs::path& dir, std::chrono::seconds timeout) {
    RunOptions options;
    options.program = "/bin/sh";
    options.timeout = timeout;
    return runWith({"-c", line}, dir, options);
}

// scripts/web.sh render reads the scene from standard input and writes the PNG to standard output: no
// files, so the command line's rules for them (src/io/, `shadelab render`) have one implementation. What it
// reads follows the command line's bound with its messages: /dev/zero (read until memory ran out) and a
// scene whose text holds an escape are refused as `shadelab render - --out -` refuses them, escaped; a
// picture larger than one script call can carry is read back in bands (8192x8192 ended in a WebDriver
// "script timeout"). A scene file or --out is refused with the way to write files, and nothing is written.
TEST_F(Browser, RenderScriptFollowsTheCommandLinesRules) {
    const std::string web = "'" + std::string(SHADELAB_WEB_SH) + "' render",
                      cli = "'" + std::string(SHADELAB_EXE) + "' render - --out -";
    std::ofstream(dir_ / "escape.json") << "{\"e\x1b[31m\": 1}";
    for (const std::string& input : {std::string("/dev/zero"), std::string("escape.json")}) {
        const Outcome fromWeb = shell(web + " < " + input + " > o.png", dir_, std::chrono::seconds(60));
        const Outcome fromCli = shell(cli + " < " + input + " > c.png", dir_, std::chrono::seconds(60));
        EXPECT_EQ(fromWeb.exitCode, 2) << input << ": " << fromWeb.err;
        EXPECT_EQ(fromWeb.err, fromCli.err) << input;
        EXPECT_EQ(fromWeb.err.find('\x1b'), std::string::npos) << fromWeb.err;
        EXPECT_EQ(fs::file_size(dir_ / "o.png"), 0u) << input;
    }
    RunOptions options;
    options.program = SHADELAB_WEB_SH;
    options.timeout = std::chrono::seconds(60);
    options.stdinText = "{}";
    // The flags are the program's one table (sceneFlags), read from the page: an unknown one is named,
    // and the message lists every flag the command line has.
    const Outcome unknown = runWith({"render", "--shade", "flat"}, dir_, options);
    EXPECT_EQ(unknown.exitCode, 2) << unknown.err;
    EXPECT_NE(unknown.err.find("unknown option \"--shade\""), std::string::npos) << unknown.err;
    for (const SceneFlag& flag : sceneFlags())
        EXPECT_NE(unknown.err.find("--" + std::string(flag.name)), std::string::npos) << flag.name;
    EXPECT_TRUE(unknown.out.empty());
    // Files are the command line's: a scene file or --out is refused before any work, and says how.
    std::ofstream(dir_ / "scene.json") << R"({"image": {"width": 16, "height": 12}})";
    for (const std::vector<std::string>& args : {std::vector<std::string>{"render", "scene.json"},
                                                 std::vector<std::string>{"render", "--out", "o2.png"},
                                                 std::vector<std::string>{"render", "--out=-"}}) {
        const Outcome refused = runWith(args, dir_, options);
        EXPECT_EQ(refused.exitCode, 2) << args.back() << ": " << refused.err;
        EXPECT_NE(refused.err.find("< SCENE.json > FILE.png"), std::string::npos) << refused.err;
        EXPECT_NE(refused.err.find("shadelab render SCENE.json --out FILE.png"), std::string::npos)
            << refused.err;
        EXPECT_TRUE(refused.out.empty());
    }
    EXPECT_FALSE(fs::exists(dir_ / "o2.png"));

    // 3000x2900 is five bands of at most 8 MB: the same picture as the native OpenGL ES render.
    const Outcome big =
        shell(web + " --size 3000x2900 < scene.json > big.png", dir_, std::chrono::seconds(120));
    ASSERT_EQ(big.exitCode, 0) << big.err;
    const Image picture = readPng(dir_ / "big.png");
    Scene scene;
    scene.width = 3000;
    scene.height = 2900;
    const Comparison c = compareImages(picture, nativeGles().render(scene), swiftShaderTolerance(picture));
    EXPECT_TRUE(c.passed) << c.summary();
}

// A free TCP port on 127.0.0.1 (bound and released; the server takes it right after).
int freePort() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof address;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&address), size) != 0 ||
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size) != 0) {
        ::close(fd);
        return -1;
    }
    ::close(fd);
    return ntohs(address.sin_port);
}

// What GET `target` from 127.0.0.1:`port` (HTTP/1.0: the server closes when it is sent) answers, headers
// and body, up to `limit` bytes; "" when nothing answers. A server that accepts and never answers fails
// here after 5 s, not at ctest's timeout.
std::string httpReply(int port, const std::string& target, std::size_t limit) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    const timeval timeout{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(std::uint16_t(port));
    std::string reply;
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        const std::string request = "GET " + target + " HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n";
        if (::write(fd, request.data(), request.size()) == ssize_t(request.size())) {
            char buffer[4096];
            for (ssize_t n; reply.size() < limit && (n = ::read(fd, buffer, sizeof buffer)) > 0;)
                reply.append(buffer, std::size_t(n));
        }
    }
    ::close(fd);
    return reply;
}

// The status code of GET `target`, or -1 when nothing answers.
int httpStatus(int port, const std::string& target) {
    const std::string reply = httpReply(port, target, 256);
    return reply.starts_with("HTTP/1.") && reply.size() > 12 ? std::stoi(reply.substr(9, 3)) : -1;
}

// The body of GET `target`, "" when nothing answers.
std::string httpBody(int port, const std::string& target) {
    const std::string reply = httpReply(port, target, std::string::npos);
    const std::size_t body = reply.find("\r\n\r\n");
    return body == std::string::npos ? "" : reply.substr(body + 4);
}

// The status of GET / from a server just started on `port`, asked every 100 ms until it answers; -1 when
// it has not within 20 s.
int statusOnceServing(int port) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    int index = -1;
    while ((index = httpStatus(port, "/")) < 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    return index;
}

// scripts/web.sh serve serves the page and nothing else: no build files, no listings, no links out of the
// page's folder; a port outside 1..65535 is refused (70000 bound 4464 and printed the wrong URL). With
// --lessons DIR, DIR's files under /own-lessons/ by the same rules, and its lessons (only they, by name)
// in /own-lessons/index.json; a DIR that is not a folder is refused.
TEST_F(Browser, ServeGivesThePageAndNothingElse) {
    RunOptions options;
    options.program = SHADELAB_WEB_SH;
    options.timeout = std::chrono::seconds(30);
    for (const char* port : {"70000", "0", "http"}) {
        const Outcome bad = runWith({"serve", port}, dir_, options);
        EXPECT_EQ(bad.exitCode, 2) << port << ": " << describe(bad);
        EXPECT_NE(bad.err.find("1..65535"), std::string::npos) << bad.err;
    }
    const fs::path own = makeLessonFolder(dir_);
    for (const std::string& folder : {(dir_ / "missing").string(), (own / "plain.json").string()}) {
        const Outcome bad =
            runWith({"serve", std::to_string(freePort()), "--lessons", folder}, dir_, options);
        EXPECT_EQ(bad.exitCode, 2) << folder << ": " << describe(bad);
        EXPECT_NE(bad.err.find("--lessons must name a folder"), std::string::npos) << bad.err;
        EXPECT_NE(bad.err.find(folder), std::string::npos) << bad.err;
    }

    const int port = freePort();
    ASSERT_GT(port, 0);
    const pid_t server = ::fork();
    if (server == 0) {
        ::execl(SHADELAB_WEB_SH, SHADELAB_WEB_SH, "serve", std::to_string(port).c_str(), "--lessons",
                own.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ASSERT_GT(server, 0);
    const int index = statusOnceServing(port);
    EXPECT_EQ(index, 200) << "the page's index.html (the server did not answer within 20 s if -1)";
    EXPECT_EQ(httpStatus(port, "/shadelab.wasm"), 200);
    EXPECT_EQ(httpStatus(port, "/scenes/index.json"), 200);
    for (const char* outside : {"/CMakeCache.txt", "/../CMakeCache.txt", "/generated/",
                                "/header-only/glm/glm.hpp", "/scenes/", "/%2e%2e/CMakeCache.txt"})
        EXPECT_EQ(httpStatus(port, outside), 404) << outside;
    const std::string list = httpBody(port, "/own-lessons/index.json");
    EXPECT_EQ(json::parse(list, nullptr, false), json::array({kOwnLessonName})) << list;
    EXPECT_EQ(httpStatus(port, "/own-lessons/%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E.json"), 200);
    EXPECT_EQ(httpStatus(port, "/own-lessons/scenes/ring.json"), 200);
    EXPECT_EQ(httpStatus(port, "/own-lessons/plain.json"), 200) << "a file in DIR, though not listed";
    for (const char* outside :
         {"/own-lessons/", "/own-lessons/scenes/", "/own-lessons/linked.json",
          "/own-lessons/../outside/secret.json", "/own-lessons/%2e%2e/outside/secret.json",
          "/own-lessons/..%2foutside/secret.json"})
        EXPECT_EQ(httpStatus(port, outside), 404) << outside;
    ::kill(server, SIGTERM);
    int status = 0;
    ::waitpid(server, &status, 0);
}

// A client that asks for `target` and resets the connection (SO_LINGER 0) after reading a little, as a tab
// closed mid-download does. Its small receive buffer keeps the server writing when the reset arrives.
void requestAndHangUp(int port, const std::string& target) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    const int small = 4096;
    ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
    const timeval limit{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof limit);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(std::uint16_t(port));
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        const std::string request = "GET " + target + " HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n";
        if (::write(fd, request.data(), request.size()) == ssize_t(request.size())) {
            char buffer[256];
            (void)!::read(fd, buffer, sizeof buffer); // the answer has started
        }
        const linger reset{1, 0};
        ::setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
    }
    ::close(fd);
}

// web/serve.py answers a path Python cannot look up (a NUL: realpath raised, the connection closed with no
// answer and a traceback) with 400, and a client that hangs up mid-answer (a ConnectionReset or BrokenPipe
// traceback) leaves nothing on standard error; the server goes on answering. Served: a folder with a
// 64 MB file, more than loopback's socket buffers take (the page's 1.3 MB wasm fit in them whole).
TEST_F(Browser, ServeAnswersBadPathsAndIsSilentWhenAClientHangsUp) {
    fs::create_directories(dir_ / "site");
    std::ofstream(dir_ / "site" / "index.html") << "<!doctype html>\n";
    std::ofstream(dir_ / "site" / "big.bin").close();
    fs::resize_file(dir_ / "site" / "big.bin", 64 << 20); // sparse: no 64 MB written to /tmp
    const int port = freePort();
    ASSERT_GT(port, 0);
    const fs::path serve = fs::path(SHADELAB_WEB_DRIVER).parent_path() / "serve.py";
    const fs::path errors = dir_ / "serve.err";
    const pid_t server = ::fork();
    if (server == 0) {
        const int err = ::open(errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (err < 0 || ::dup2(err, STDERR_FILENO) < 0) ::_exit(126);
        ::execl("/usr/bin/python3", "/usr/bin/python3", serve.c_str(), (dir_ / "site").c_str(),
                std::to_string(port).c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ASSERT_GT(server, 0);
    const int index = statusOnceServing(port);
    EXPECT_EQ(index, 200) << "index.html (the server did not answer within 20 s if -1)";
    for (const char* bad : {"/%00", "/scenes/%00.json", "/index.html%00"})
        EXPECT_EQ(httpStatus(port, bad), 400) << bad;
    for (int i = 0; i < 3; ++i) requestAndHangUp(port, "/big.bin");
    std::this_thread::sleep_for(std::chrono::milliseconds(500)); // the handlers' threads meet the resets
    EXPECT_EQ(httpStatus(port, "/"), 200) << "the server answers after the hang-ups";
    ::kill(server, SIGTERM);
    int status = 0;
    ::waitpid(server, &status, 0);
    std::ifstream in(errors);
    const std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(err, "") << "the server's standard error";
}

// scripts/web.sh render: the browser's `shadelab render - --out -` (a PNG of the scene's size on standard
// output; exit 2 with the CLI's message for a bad scene, nothing on standard output).
TEST_F(Browser, RenderScriptWritesThePngOrSaysWhy) {
    RunOptions options;
    options.program = SHADELAB_WEB_SH;
    options.timeout = std::chrono::seconds(60); // four runs, each well under the test's ctest TIMEOUT
    options.stdinText = "{}";
    options.stdoutPath = dir_ / "w.png";
    std::ofstream(*options.stdoutPath).close(); // the runner opens it, as the shell's `> w.png` would
    const Outcome ok = runWith({"render", "--size", "120x90", "--shading", "flat"}, dir_, options);
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    const Image png = readPng(dir_ / "w.png");
    EXPECT_EQ(png.width, 120);
    EXPECT_EQ(png.height, 90);
    Scene scene;
    scene.width = 120;
    scene.height = 90;
    scene.shading = ShadingMode::Flat;
    const Comparison c = compareImages(png, nativeGles().render(scene), swiftShaderTolerance(png));
    EXPECT_TRUE(c.passed) << c.summary();

    options.stdoutPath.reset();
    options.stdinText = R"({"image": {"width": 0}})";
    const Outcome bad = runWith({"render"}, dir_, options);
    options.program = SHADELAB_EXE;
    const Outcome cli = runWith({"render", "-", "--out", "-"}, dir_, options);
    EXPECT_EQ(bad.exitCode, 2) << bad.err;
    EXPECT_EQ(bad.err, cli.err);
    EXPECT_TRUE(bad.out.empty());
    // What WebGL 2 lacks is a run-time failure named by the renderer, as natively (DESIGN §7).
    options.program = SHADELAB_WEB_SH;
    options.stdinText = "{}";
    const Outcome reversed = runWith({"render", "--depth", "reversed"}, dir_, options);
    EXPECT_EQ(reversed.exitCode, 1) << reversed.err;
    EXPECT_TRUE(reversed.err.starts_with("shadelab: depth reversed: needs glClipControl")) << reversed.err;
    EXPECT_EQ(reversed.err.find("Stacktrace"), std::string::npos) << reversed.err;
    EXPECT_TRUE(reversed.out.empty());
}

} // namespace
} // namespace shadelab::test
