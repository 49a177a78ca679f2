// What the demo window's S saves, and where (demo_window.h says what every window test checks): out of
// memory, beside an earlier screenshot, beside planted links and FIFOs, and without hard links.
#include <sys/resource.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "shadelab/image/image_file.h"
#include "window/demo_window.h"

namespace shadelab::window_test {
namespace {

int entriesIn(const fs::path& dir) {
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
    return entries;
}

// With an earlier shadelab-001 pair in the screenshot folder, S saves shadelab-002 (the JSON first, the
// PNG complete once it has content) and leaves the earlier pair and nothing else beside it.
void expectScreenshotBesideAnEarlierOne(DemoWindow& test, const std::string& name,
                                        const std::vector<std::string>& environment = {}) {
    const fs::path dir = test.scratch() / (name + "-screenshots");
    fs::create_directories(dir);
    const std::string earlier = "an earlier launch's screenshot";
    std::ofstream(dir / "shadelab-001.png") << earlier;
    std::ofstream(dir / "shadelab-001.json") << earlier;
    DemoProcess& demo =
        test.startDemo(name, {"--size", "320x240", "--hide-panel", "--gl-debug"}, environment);
    demo.window().key("s");
    // Without hard links the name is held by an empty file for the moment before the rename.
    ASSERT_TRUE(pollUntil([&] {
        std::error_code error;
        return fs::file_size(dir / "shadelab-002.png", error) > 0 && !error;
    })) << "S saved no shadelab-002.png beside the earlier shadelab-001 within "
        << kWaitText << ":\n"
        << demo.err();
    EXPECT_TRUE(fs::exists(dir / "shadelab-002.json"));
    EXPECT_EQ(readText(dir / "shadelab-001.png"), earlier) << "S overwrote shadelab-001.png";
    EXPECT_EQ(readText(dir / "shadelab-001.json"), earlier) << "S overwrote shadelab-001.json";
    EXPECT_EQ(readPng(dir / "shadelab-002.png").width, 320);
    EXPECT_EQ(entriesIn(dir), 4) << "temporaries or placeholders left in " << dir;
    test.expectCleanQuit(demo);
}

// A screenshot that runs out of memory used to end the demo (the exception escaped GLFW's key
// callback). Under an address-space limit just above what the demo holds (set on the running process, as
// `prlimit --as` does), S must report "screenshot not saved" and the demo must go on and quit cleanly.
TEST_F(DemoWindow, ScreenshotOutOfMemoryKeepsTheDemoRunning) {
#if defined(SHADELAB_SANITIZED)
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no RLIMIT_AS applies to it";
#endif
    DemoProcess& demo = startDemo("oom-demo", {"--size", "640x480", "--hide-panel"});
    // Once the picture shows, its target and the copy into the window exist (Mesa builds its blit code at
    // the first copy): only the screenshot is left to meet the limit.
    ASSERT_TRUE(pollUntil([&] { return !uniform(demo.window().capture()); })) << "no picture in the window";
    std::ifstream status("/proc/" + std::to_string(demo.pid()) + "/status");
    long vmSizeKiB = 0;
    for (std::string line; std::getline(status, line);)
        if (line.starts_with("VmSize:")) vmSizeKiB = std::stol(line.substr(7));
    ASSERT_GT(vmSizeKiB, 0);
    const rlimit tight{rlim_t(vmSizeKiB + 2048) * 1024, RLIM_INFINITY};
    ASSERT_EQ(::prlimit(demo.pid(), RLIMIT_AS, &tight, nullptr), 0) << std::strerror(errno);
    demo.window().key("s");
    const bool reported =
        pollUntil([&] { return demo.err().find("screenshot not saved") != std::string::npos; });
    EXPECT_TRUE(reported) << "no 'screenshot not saved' on stderr:\n" << demo.err();
    // The reason is named: an incomplete framebuffer with its status (what Mesa gives here), a GL or C++
    // out-of-memory — never a bare std::bad_alloc.
    const std::string err = demo.err();
    EXPECT_TRUE(err.find("GL_FRAMEBUFFER_INCOMPLETE") != std::string::npos ||
                err.find("GL_OUT_OF_MEMORY") != std::string::npos ||
                err.find("out of memory") != std::string::npos)
        << err;
    const rlimit free{RLIM_INFINITY, RLIM_INFINITY};
    ASSERT_EQ(::prlimit(demo.pid(), RLIMIT_AS, &free, nullptr), 0) << std::strerror(errno);
    const ExitStatus exit = demo.quit();
    EXPECT_EQ(exit.code, 0) << "the demo did not survive the failed screenshot: " << exit.describe();
}

// S restarted at shadelab-001 each launch and replaced an earlier screenshot. With an earlier
// shadelab-001 pair in the folder, S must save shadelab-002 and leave shadelab-001 as it was.
TEST_F(DemoWindow, ScreenshotTakesTheNextFreeNumberAndNeverOverwrites) {
    expectScreenshotBesideAnEarlierOne(*this, "keep-demo");
}

// S never opens or replaces what is already in the screenshot folder. Its temporaries had predictable names
// (.shadelab-shot-<pid>.json/.png) and were written through whatever was there: a planted link made S
// replace the file it pointed to, a planted FIFO hung the demo (Esc did nothing). Links and a FIFO planted
// at the old temporaries' names and at the next shadelab-NNN names must all be left as they are.
TEST_F(DemoWindow, ScreenshotOpensNothingPlantedInTheFolder) {
    const fs::path dir = scratch() / "planted-screenshots";
    fs::create_directories(dir);
    const fs::path victim = scratch() / "victim.txt";
    std::ofstream(victim) << "precious";
    DemoProcess& demo = startDemo("planted", {"--size", "320x240", "--hide-panel", "--gl-debug"});
    const std::string shot = ".shadelab-shot-" + std::to_string(demo.pid());
    fs::create_symlink(victim, dir / (shot + ".json"));
    ASSERT_EQ(::mkfifo((dir / (shot + ".png")).c_str(), 0666), 0) << std::strerror(errno);
    fs::create_symlink(victim, dir / "shadelab-001.png");
    ASSERT_EQ(::mkfifo((dir / "shadelab-002.json").c_str(), 0666), 0) << std::strerror(errno);
    demo.window().key("s");
    EXPECT_TRUE(pollUntil([&] { return fs::exists(dir / "shadelab-003.png"); }))
        << "S saved no shadelab-003.png within " << kWaitText << ":\n"
        << demo.err();
    EXPECT_TRUE(fs::exists(dir / "shadelab-003.json"));
    EXPECT_EQ(readText(victim), "precious") << "S wrote through a planted link";
    EXPECT_TRUE(fs::is_symlink(dir / (shot + ".json")));
    EXPECT_TRUE(fs::is_symlink(dir / "shadelab-001.png"));
    EXPECT_TRUE(fs::is_fifo(dir / (shot + ".png")));
    EXPECT_TRUE(fs::is_fifo(dir / "shadelab-002.json"));
    EXPECT_EQ(entriesIn(dir), 6) << "temporaries left in " << dir;
    expectCleanQuit(demo);
}

// On a file system without hard links (link() fails with EPERM: vfat, some FUSE file systems) S claims the
// next free name exclusively and renames into it ("Operation not permitted", nothing saved, before).
TEST_F(DemoWindow, ScreenshotWithoutHardLinksClaimsTheNextFreeName) {
    // The sanitizers' runtime wants to be first among the libraries; the preloaded one is not instrumented.
    const char* asan = std::getenv("ASAN_OPTIONS");
    expectScreenshotBesideAnEarlierOne(*this, "no-links",
                                       {std::string("LD_PRELOAD=") + SHADELAB_NO_HARD_LINKS,
                                        "ASAN_OPTIONS=" + std::string(asan ? asan : "") +
                                            (asan && *asan ? ":" : "") + "verify_asan_link_order=0"});
}

} // namespace
} // namespace shadelab::window_test
