// Output files and special paths end to end (docs/ci-engineers.md "Output files"): `--out` never destroys a
// file the user did not name as the output, writes through devices and FIFOs, follows symbolic links, keeps
// an existing file's mode and owner, leaves nothing behind when interrupted; a scene is a regular file or
// "-". Every case runs twice: as root and as the unprivileged user nobody (in a folder only nobody can
// write).
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "cli/run_process.h"

namespace {

using namespace shadelab::cli_test;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr uid_t kNobody = 65534;
constexpr gid_t kNogroup = 65534;

// A complete PNG: the signature, and the IEND chunk as its last 12 bytes.
bool isCompletePng(const std::string& bytes) {
    static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
    static constexpr std::string_view kIend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    return bytes.size() > 20 && std::string_view(bytes).substr(0, 8) == kSignature &&
           std::string_view(bytes).substr(bytes.size() - 12) == kIend;
}

bool isCharDevice(const char* path, unsigned major, unsigned minor) {
    struct stat st {};
    return ::stat(path, &st) == 0 && S_ISCHR(st.st_mode) && ::major(st.st_rdev) == major &&
           ::minor(st.st_rdev) == minor;
}

bool hasTempFile(const fs::path& folder) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder, error))
        if (entry.path().filename().string().starts_with(".shadelab-")) return true;
    return false;
}

constexpr std::string_view kScene = R"({"image": {"width": 32, "height": 32}})";
constexpr std::string_view kPrecious = "the bytes of an earlier file, which must survive\n";

// Whether this process may drop to nobody: a forked child tries.
bool canBecomeNobody() {
    const pid_t pid = ::fork();
    if (pid == 0)
        ::_exit(::setresgid(kNogroup, kNogroup, kNogroup) == 0 && ::setresuid(kNobody, kNobody, kNobody) == 0
                    ? 0
                    : 1);
    int status = 0;
    return pid > 0 && ::waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

enum class User { Root, Nobody };
inline void PrintTo(User user, std::ostream* os) {
    *os << (user == User::Root ? "root" : "nobody");
}

// Each test in a fresh folder owned by the user it runs as (mode 0700 for nobody: root can still enter).
class OutputSafety : public ::testing::TestWithParam<User> {
protected:
    void SetUp() override {
        if (::geteuid() != 0)
            GTEST_SKIP() << "runs as root (as CI does), to run shadelab both as root and as nobody";
        if (nobody() && !canBecomeNobody())
            GTEST_SKIP() << "this root cannot switch to uid " << kNobody
                         << " (no CAP_SETUID, e.g. in a user namespace): the nobody cases cannot run";
        char pattern[] = "/tmp/shadelab-output-XXXXXX";
        ASSERT_NE(::mkdtemp(pattern), nullptr) << std::strerror(errno);
        dir_ = pattern;
        ::chmod(dir_.c_str(), 0755);
        if (nobody()) {
            ASSERT_EQ(::chown(dir_.c_str(), kNobody, kNogroup), 0) << std::strerror(errno);
        }
    }
    void TearDown() override {
        if (!dir_.empty()) fs::remove_all(dir_);
        // Nothing here may ever replace a device node.
        EXPECT_TRUE(isCharDevice("/dev/null", 1, 3)) << "/dev/null is no longer the null device";
        EXPECT_TRUE(isCharDevice("/dev/full", 1, 7)) << "/dev/full is no longer the full device";
    }

    bool nobody() const { return GetParam() == User::Nobody; }
    // A file made by the test, given to the user the case runs as.
    fs::path make(const std::string& name, std::string_view bytes) {
        const fs::path path = dir_ / name;
        writeFile(path, bytes);
        own(path);
        return path;
    }
    void own(const fs::path& path) {
        if (nobody()) {
            EXPECT_EQ(::lchown(path.c_str(), kNobody, kNogroup), 0) << std::strerror(errno);
        }
    }
    Outcome run(const std::vector<std::string>& args, RunOptions options = {}) {
        if (nobody()) options.user = kNobody;
        options.group = kNogroup;
        return runWith(args, dir_, options);
    }

    fs::path dir_;
};

TEST_P(OutputSafety, OutputThatIsTheSceneIsRefusedBeforeRendering) {
    const fs::path scene = make("sc.json", kScene);
    ASSERT_EQ(::symlink("sc.json", (dir_ / "link.json").c_str()), 0);
    own(dir_ / "link.json");
    ASSERT_EQ(::link(scene.c_str(), (dir_ / "hard.json").c_str()), 0);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"sc.json", "sc.json"}, {"link.json", "sc.json"}, {"sc.json", "link.json"}, {"hard.json", "sc.json"}};
    for (const auto& [input, output] : cases) {
        for (const char* command : {"render", "reference"}) {
            const Outcome r = run({command, input, "--out", output});
            EXPECT_EQ(r.exitCode, 2) << command << " " << input << " --out " << output << ": " << describe(r);
            EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
            EXPECT_NE(r.err.find("is the input file"), std::string::npos) << r.err;
            EXPECT_EQ(readFile(scene), kScene);
        }
    }
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
    EXPECT_FALSE(hasTempFile(dir_));
}

TEST_P(OutputSafety, DevNullIsWrittenThrough) {
    const Outcome r = run({"render", "--size", "16x16", "--out", "/dev/null"});
    EXPECT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_TRUE(isCharDevice("/dev/null", 1, 3));
}

TEST_P(OutputSafety, DevFullFailsWithTheOsErrorAndStaysADevice) {
    for (const char* command : {"render", "reference"}) {
        const Outcome r = run({command, "--size", "16x16", "--out", "/dev/full"});
        EXPECT_EQ(r.exitCode, 1) << describe(r);
        EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(std::strerror(ENOSPC)), std::string::npos) << r.err;
        EXPECT_TRUE(isCharDevice("/dev/full", 1, 7));
    }
}

TEST_P(OutputSafety, FifoReaderGetsTheWholePng) {
    const fs::path fifo = dir_ / "p";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0) << std::strerror(errno);
    own(fifo);
    const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(fd, 0) << std::strerror(errno);
    std::string received;
    bool closed = false;
    std::thread reader([&] { closed = readToEndWithin(fd, 60s, received); });
    const Outcome r = run({"render", "--size", "24x16", "--out", "p"});
    // A writer that never started: end the read now rather than at its deadline.
    if (!r.started) ::close(::open(fifo.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC));
    reader.join();
    ::close(fd);
    EXPECT_TRUE(closed) << "no writer opened and closed the FIFO within 60 s (" << received.size()
                        << " bytes read)";
    EXPECT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_TRUE(isCompletePng(received)) << received.size() << " bytes";
    struct stat st {};
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced";
    EXPECT_FALSE(hasTempFile(dir_));
}

TEST_P(OutputSafety, DashWritesThePngToStandardOutput) {
    const Outcome r = run({"render", "--size", "24x16", "--out", "-"});
    EXPECT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_TRUE(isCompletePng(r.out)) << r.out.size() << " bytes on stdout";
    EXPECT_FALSE(fs::exists(dir_ / "-"));
    const Outcome ref = run({"reference", "--size", "24x16", "--out", "-"});
    EXPECT_EQ(ref.exitCode, 0) << describe(ref);
    EXPECT_TRUE(isCompletePng(ref.out));
}

TEST_P(OutputSafety, SymlinkIsFollowedAndItsTargetReplaced) {
    const fs::path target = make("target.png", kPrecious);
    ASSERT_EQ(::symlink("target.png", (dir_ / "link.png").c_str()), 0);
    own(dir_ / "link.png");
    const Outcome r = run({"render", "--size", "16x16", "--out", "link.png"});
    EXPECT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.png")) << "the link itself was replaced";
    EXPECT_TRUE(isCompletePng(readFile(target)));

    // A dangling link creates its target.
    ASSERT_EQ(::symlink("new.png", (dir_ / "dangling.png").c_str()), 0);
    own(dir_ / "dangling.png");
    const Outcome d = run({"render", "--size", "16x16", "--out", "dangling.png"});
    EXPECT_EQ(d.exitCode, 0) << describe(d);
    EXPECT_TRUE(fs::is_symlink(dir_ / "dangling.png"));
    EXPECT_TRUE(isCompletePng(readFile(dir_ / "new.png")));
    EXPECT_FALSE(hasTempFile(dir_));
}

// /dev/stdout and its kin are the open descriptor, written through as "-" is: the file behind it is never
// replaced (a log appended to with >> kept only the PNG), and a pipe behind it gets the PNG.
TEST_P(OutputSafety, DescriptorPathsWriteThroughTheOpenDescriptor) {
    for (const char* spelling : {"/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"}) {
        const fs::path log = make("log.txt", "H\n");
        RunOptions options;
        options.stdoutPath = log;
        options.stdoutAppends = true;
        const Outcome r = run({"render", "--size", "16x16", "--out", spelling}, options);
        EXPECT_EQ(r.exitCode, 0) << spelling << ": " << describe(r);
        const std::string bytes = readFile(log);
        EXPECT_TRUE(bytes.starts_with("H\n")) << spelling << ": the line before the PNG was lost";
        EXPECT_TRUE(isCompletePng(bytes.substr(std::min<std::size_t>(2, bytes.size()))))
            << spelling << ": " << bytes.size() << " bytes";

        const Outcome piped = run({"render", "--size", "16x16", "--out", spelling});
        EXPECT_EQ(piped.exitCode, 0) << spelling << " into a pipe: " << describe(piped);
        EXPECT_TRUE(isCompletePng(piped.out)) << spelling << " into a pipe";
    }
    const Outcome closed = run({"render", "--size", "16x16", "--out", "/dev/fd/200"});
    EXPECT_EQ(closed.exitCode, 2) << describe(closed);
    EXPECT_NE(closed.err.find("descriptor 200, which is not open"), std::string::npos) << closed.err;
    EXPECT_FALSE(hasTempFile(dir_));
}

// fs.protected_symlinks: a link in a sticky world-writable folder that belongs to neither the caller nor the
// folder's owner is not followed (root's render replaced the file a planted link in /tmp pointed to).
TEST_P(OutputSafety, PlantedLinkInAStickyFolderIsRefused) {
    ASSERT_EQ(::chmod(dir_.c_str(), 01777), 0) << std::strerror(errno);
    const fs::path victim = make("victim.txt", kPrecious);
    ASSERT_EQ(::symlink("victim.txt", (dir_ / "shot.png").c_str()), 0);
    constexpr uid_t kStranger = 4242; // neither the caller nor the folder's owner
    ASSERT_EQ(::lchown((dir_ / "shot.png").c_str(), kStranger, kStranger), 0) << std::strerror(errno);
    const Outcome r = run({"render", "--size", "16x16", "--out", "shot.png"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("fs.protected_symlinks"), std::string::npos) << r.err;
    EXPECT_EQ(readFile(victim), kPrecious);
    EXPECT_TRUE(fs::is_symlink(dir_ / "shot.png"));

    // The caller's own link there is followed, as the kernel follows it.
    ASSERT_EQ(::symlink("victim.txt", (dir_ / "mine.png").c_str()), 0);
    own(dir_ / "mine.png");
    const Outcome mine = run({"render", "--size", "16x16", "--out", "mine.png"});
    EXPECT_EQ(mine.exitCode, 0) << describe(mine);
    EXPECT_TRUE(isCompletePng(readFile(victim)));
    EXPECT_FALSE(hasTempFile(dir_));
}

// A file the caller may not write, and a folder where it may not create the temporary file, are refused
// before any work (a 0444 file was replaced by rename, exit 0).
TEST_P(OutputSafety, UnwritableFileAndFolderAreRefusedUpFront) {
    if (!nobody()) GTEST_SKIP() << "root may write any file and folder; the nobody case tests this";
    const fs::path readOnly = make("ro.png", kPrecious);
    ASSERT_EQ(::chmod(readOnly.c_str(), 0444), 0);
    const Outcome r = run({"render", "--size", "16x16", "--out", "ro.png"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("you may not write it (mode 0444"), std::string::npos) << r.err;
    EXPECT_EQ(readFile(readOnly), kPrecious);

    fs::create_directory(dir_ / "locked");
    own(dir_ / "locked");
    ASSERT_EQ(::chmod((dir_ / "locked").c_str(), 0555), 0);
    for (const char* command : {"render", "reference"}) {
        const Outcome f = run({command, "--size", "16x16", "--out", "locked/x.png"});
        EXPECT_EQ(f.exitCode, 2) << command << ": " << describe(f);
        EXPECT_NE(f.err.find("cannot create files in the folder"), std::string::npos) << f.err;
    }
    EXPECT_TRUE(fs::is_empty(dir_ / "locked"));
}

TEST_P(OutputSafety, FolderBlockDeviceAndSocketAreRefused) {
    fs::create_directory(dir_ / "folder.png");
    own(dir_ / "folder.png");
    ASSERT_EQ(::mknod((dir_ / "block.png").c_str(), S_IFBLK | 0666, ::makedev(7, 200)), 0)
        << std::strerror(errno);
    const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const std::string socketPath = (dir_ / "socket.png").string();
    ASSERT_LT(socketPath.size(), sizeof address.sun_path);
    std::memcpy(address.sun_path, socketPath.c_str(), socketPath.size() + 1);
    ASSERT_EQ(::bind(sock, reinterpret_cast<sockaddr*>(&address), sizeof address), 0) << std::strerror(errno);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"folder.png", "is a directory"}, {"block.png", "is a block device"}, {"socket.png", "is a socket"}};
    for (const auto& [name, what] : cases) {
        const Outcome r = run({"render", "--size", "16x16", "--out", name});
        EXPECT_EQ(r.exitCode, 2) << name << ": " << describe(r);
        EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    }
    struct stat st {};
    ASSERT_EQ(::lstat((dir_ / "block.png").c_str(), &st), 0);
    EXPECT_TRUE(S_ISBLK(st.st_mode));
    ASSERT_EQ(::lstat(socketPath.c_str(), &st), 0);
    EXPECT_TRUE(S_ISSOCK(st.st_mode));
    ::close(sock);
    EXPECT_FALSE(hasTempFile(dir_));
}

TEST_P(OutputSafety, ReplacingKeepsModeAndOwner) {
    const fs::path out = make("out.png", kPrecious);
    ASSERT_EQ(::chmod(out.c_str(), 0600), 0);
    // As root, replace a file that belongs to nobody: it must still belong to nobody.
    if (!nobody()) {
        ASSERT_EQ(::chown(out.c_str(), kNobody, kNogroup), 0);
    }
    struct stat before {};
    ASSERT_EQ(::stat(out.c_str(), &before), 0);
    const Outcome r = run({"render", "--size", "16x16", "--out", "out.png"});
    EXPECT_EQ(r.exitCode, 0) << describe(r);
    struct stat after {};
    ASSERT_EQ(::stat(out.c_str(), &after), 0);
    EXPECT_EQ(after.st_mode & 07777, 0600u);
    EXPECT_EQ(after.st_uid, kNobody);
    EXPECT_EQ(after.st_gid, kNogroup);
    EXPECT_NE(after.st_ino, before.st_ino) << "replaced by rename: a new inode";
    EXPECT_TRUE(isCompletePng(readFile(out)));
}

TEST_P(OutputSafety, LongestLegalNameWorks) {
    const std::string name = std::string(251, 'n') + ".png"; // 255 bytes: NAME_MAX
    const Outcome r = run({"render", "--size", "8x8", "--out", name});
    EXPECT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_TRUE(isCompletePng(readFile(dir_ / name)));
}

TEST_P(OutputSafety, SignalDuringWriteLeavesNoTempAndTheOldFile) {
    for (int signal : {SIGTERM, SIGINT, SIGHUP}) {
        const fs::path out = make("good.png", kPrecious);
        RunOptions options;
        options.signal = signal;
        // Sent while the temporary file exists: the moment that used to leave it behind.
        options.signalWhen = [&] { return hasTempFile(dir_); };
        const Outcome r = run({"reference", "--size", "1500x1500", "--out", "good.png"}, options);
        EXPECT_EQ(r.signal, signal) << "the exit status must say the signal: " << describe(r);
        EXPECT_FALSE(hasTempFile(dir_)) << "signal " << signal;
        EXPECT_EQ(readFile(out), kPrecious) << "signal " << signal;
    }
}

TEST_P(OutputSafety, HelpToAFullDiskFails) {
    RunOptions options;
    options.stdoutPath = "/dev/full";
    const Outcome r = run({"--help"}, options);
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    EXPECT_NE(r.err.find("standard output"), std::string::npos) << r.err;
}

TEST_P(OutputSafety, ControlCharactersInNamesAreEscapedInMessages) {
    const std::string name = "evil\x1b[31mred\x1b[0m.json";
    const Outcome r = run({"render", name, "--out", "o.png"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "raw ESC reached the terminal";
    EXPECT_NE(r.err.find("evil\\x1b[31mred"), std::string::npos) << r.err;
}

TEST_P(OutputSafety, SceneMustBeARegularFileOrDash) {
    const fs::path fifo = dir_ / "s.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0);
    own(fifo);
    RunOptions options;
    options.timeout = 20s; // it used to wait forever for a writer
    const Outcome r = run({"render", "s.json", "--out", "o.png"}, options);
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("s.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("FIFO"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "o.png"));

    RunOptions fromStdin;
    fromStdin.stdinText = std::string(kScene);
    const Outcome s = run({"render", "-", "--out", "o.png"}, fromStdin);
    EXPECT_EQ(s.exitCode, 0) << describe(s);
    EXPECT_TRUE(isCompletePng(readFile(dir_ / "o.png")));
}

TEST_P(OutputSafety, ContentAfterANulByteIsAnError) {
    make("nul.json", std::string(R"({"shading":"flat"})") + std::string(1, '\0') + "garbage");
    const Outcome r = run({"render", "nul.json", "--out", "o.png"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("NUL"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "o.png"));
}

// Memory limits (ulimit -v): estimated before anything is spent, refused with the figures; a failure that
// still comes names what was being built. Never a crash inside Mesa, never a bare std::bad_alloc.
#if defined(SHADELAB_SANITIZED)
#define SKIP_UNDER_ASAN()                                                                                    \
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no RLIMIT_AS run can start"
#else
#define SKIP_UNDER_ASAN() (void)0
#endif

class ResourceLimits : public ::testing::Test {
protected:
    void SetUp() override {
        char pattern[] = "/tmp/shadelab-limits-XXXXXX";
        ASSERT_NE(::mkdtemp(pattern), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        if (!dir_.empty()) fs::remove_all(dir_);
    }
    fs::path dir_;
};

TEST_F(ResourceLimits, RenderUnderASmallAddressSpaceIsRefusedUpFront) {
    SKIP_UNDER_ASAN();
    RunOptions options;
    options.addressSpace = 500'000 * 1024; // `ulimit -v 500000`: Mesa crashed at random here (exit 139)
    const Outcome r = runWith({"render", "--out", "x.png"}, dir_, options);
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    EXPECT_EQ(r.signal, 0) << describe(r);
    EXPECT_NE(r.err.find("needs about"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the limit (ulimit -v) is 488 MiB"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// `reference` gets render's estimate before the work (a bare std::bad_alloc under ulimit -v before).
TEST_F(ResourceLimits, ReferenceUnderASmallAddressSpaceIsRefusedUpFront) {
    SKIP_UNDER_ASAN();
    RunOptions options;
    // 8192² needs about 27 bytes a pixel: 1.8 GB. (Far lower limits stop the process before main: the
    // GL stack's libraries are loaded at start-up, and LLVM's initializers abort below about 200 MB.)
    options.addressSpace = 900'000 * 1024;
    const Outcome r = runWith({"reference", "--size", "8192x8192", "--out", "x.png"}, dir_, options);
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    EXPECT_EQ(r.signal, 0) << describe(r);
    EXPECT_NE(r.err.find("the reference of 8192x8192 needs about"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("ulimit -v"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(ResourceLimits, OutOfMemoryNamesWhatWasBeingBuilt) {
    SKIP_UNDER_ASAN();
    RunOptions options;
    options.addressSpace = 800'000 * 1024; // the issue's `ulimit -v 800000`: "std::bad_alloc" before
    const Outcome r = runWith({"render", "--subdivisions", "10", "--out", "x.png"}, dir_, options);
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    EXPECT_EQ(r.signal, 0) << describe(r);
    EXPECT_EQ(r.err.find("std::bad_alloc"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("MiB"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("ulimit -v"), std::string::npos) << r.err;
}

TEST_F(ResourceLimits, ReportBeyondTheMachineIsRefusedBeforeMeasuring) {
    writeFile(dir_ / "huge.json", R"({"image": {"width": 16384, "height": 16384}})");
    const Outcome r = runWith({"report", "huge.json", "--out", "R"}, dir_);
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("16384x16384"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("more than this machine's"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "R"));
}

// Accepted, then drawn wrong: a directional or spot direction of any scale must light exactly as
// its unit direction, in the renderer and in the reference alike.
TEST_F(ResourceLimits, DirectionsOfAnyScaleDrawTheSamePicture) {
    auto scene = [](const std::string& direction) {
        return R"({"image": {"width": 48, "height": 48}, "lights": [{"type": "directional", "direction": )" +
               direction + R"(}, {"type": "spot", "position": [0, 0, 4], "direction": )" + direction +
               R"(, "cutoff_deg": 40}]})";
    };
    writeFile(dir_ / "unit.json", scene("[1, -1, -1]"));
    writeFile(dir_ / "tiny.json", scene("[1e-30, -1e-30, -1e-30]"));
    writeFile(dir_ / "tinier.json", scene("[1e-300, -1e-300, -1e-300]"));
    for (const char* command : {"render", "reference"}) {
        std::vector<std::string> pictures;
        for (const char* name : {"unit.json", "tiny.json", "tinier.json"}) {
            const Outcome r = runWith({command, name, "--out", "-"}, dir_);
            ASSERT_EQ(r.exitCode, 0) << describe(r);
            pictures.push_back(r.out);
        }
        EXPECT_EQ(pictures[1], pictures[0]) << command << ": [1e-30, ...] differs from [1, ...]";
        EXPECT_EQ(pictures[2], pictures[0]) << command << ": [1e-300, ...] differs from [1, ...]";
    }
}

// DISPLAY names an X server that accepts the connection but never answers (a stopped Xvfb). The
// demo used to hang in XOpenDisplay forever; it must give up within seconds and render the showcase
// headless instead. The silent server is a Unix socket in /tmp/.X11-unix that listens and never accepts.
TEST(SilentDisplay, DemoFallsBackToTheShowcaseWithinSeconds) {
    fs::create_directories("/tmp/.X11-unix");
    int number = 200;
    while (number < 300 && fs::exists("/tmp/.X11-unix/X" + std::to_string(number))) ++number;
    ASSERT_LT(number, 300) << "no free display number";
    const std::string socketPath = "/tmp/.X11-unix/X" + std::to_string(number);
    const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::memcpy(address.sun_path, socketPath.c_str(), socketPath.size() + 1);
    ASSERT_EQ(::bind(sock, reinterpret_cast<sockaddr*>(&address), sizeof address), 0) << std::strerror(errno);
    ASSERT_EQ(::listen(sock, 8), 0);

    char pattern[] = "/tmp/shadelab-display-XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    const fs::path dir = pattern;
    RunOptions options;
    options.timeout = 60s; // a hang is killed here and fails the test
    options.environment = childEnvironment(Display::Inherit, {"DISPLAY=:" + std::to_string(number)});
    const auto start = std::chrono::steady_clock::now();
    const Outcome r = runWith({"--showcase-out", "showcase.png"}, dir, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ::close(sock);
    ::unlink(socketPath.c_str());

    EXPECT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_LT(seconds, 30) << "took " << seconds << " s";
    EXPECT_NE(r.err.find("did not answer"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("showcase"), std::string::npos) << r.err;
    EXPECT_TRUE(isCompletePng(readFile(dir / "showcase.png")));
    fs::remove_all(dir);
}

// A child that cannot start fails the test at once, with the step and the reason, instead of leaving the
// test waiting for what it would have done (a FIFO reader waited 100 s for a writer that never ran).
TEST(RunProcess, AChildThatCannotStartFailsAtOnceNamingWhy) {
    char pattern[] = "/tmp/shadelab-start-XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    const fs::path dir = pattern;
    writeFile(dir / "not-a-program", "#!/bin/sh\n"); // mode 0644: execve refuses it
    RunOptions options;
    options.program = (dir / "not-a-program").string();
    const auto start = std::chrono::steady_clock::now();
    Outcome r;
    EXPECT_NONFATAL_FAILURE(r = runWith({"--help"}, dir, options), "executing failed: Permission denied");
    EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
    EXPECT_FALSE(r.started);
    fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(AsUser, OutputSafety, ::testing::Values(User::Root, User::Nobody),
                         [](const ::testing::TestParamInfo<User>& info) {
                             return info.param == User::Root ? "root" : "nobody";
                         });

} // namespace
