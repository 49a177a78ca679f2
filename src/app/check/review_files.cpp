// `shadelab review`'s files (review_files.h). The folders hold another program's output, so anything in
// them is untrusted: only regular files are opened, and an output never lands on an input (README "Output
// files").
#include "app/check/review_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "shadelab/errors.h"
#include "shadelab/image/image_file.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

namespace fs = std::filesystem;

std::string reviewQuoted(const fs::path& path) {
    return "\"" + printable(path.string()) + "\"";
}

std::string reviewKindName(mode_t mode) {
    if (S_ISREG(mode)) return "";
    if (S_ISLNK(mode)) return "a symbolic link";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// The whole file, or an error line. O_NONBLOCK: a FIFO put there in the listing's stead opens at once and
// is refused by fstat, instead of waiting for a writer that never comes.
std::string readReviewBytes(const fs::path& path, std::string& error) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        error =
            reviewQuoted(path) + ": " +
            (errno == ELOOP ? std::string("a symbolic link, not a regular file: review reads only regular "
                                          "files (replace the link with the file)")
                            : std::string("cannot open: ") + std::strerror(errno));
        return {};
    }
    std::string bytes;
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        error = reviewQuoted(path) + ": " + reviewKindName(st.st_mode) +
                ", not a regular file: review reads only regular files";
        ::close(fd);
        return {};
    }
    char buffer[65536];
    while (true) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            bytes.append(buffer, std::size_t(n));
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) error = reviewQuoted(path) + ": cannot read: " + std::strerror(errno);
        break;
    }
    ::close(fd);
    return bytes;
}

} // namespace

ReviewEntry reviewEntryAt(const fs::path& path) {
    ReviewEntry entry;
    entry.path = path;
    entry.file = path.filename().string();
    entry.stem = entry.file.size() > 4 ? entry.file.substr(0, entry.file.size() - 4) : entry.file;
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0)
        entry.problem = "missing";
    else
        entry.problem = reviewKindName(st.st_mode);
    return entry;
}

void checkReviewFolder(const fs::path& dir, std::string_view field) {
    std::error_code error;
    if (!fs::is_directory(dir, error))
        throw InputError(std::string(field) + ": " + reviewQuoted(dir) +
                         (fs::exists(dir, error) ? " is not a folder" : " does not exist") +
                         "; give the folder of PNG files");
}

std::vector<ReviewEntry> listReviewPngs(const fs::path& dir, std::string_view field) {
    std::vector<ReviewEntry> entries;
    std::error_code error;
    fs::directory_iterator it(dir, error);
    for (; !error && it != fs::directory_iterator(); it.increment(error)) {
        const std::string file = it->path().filename().string();
        if (file.size() <= 4 || !file.ends_with(".png")) continue;
        entries.push_back(reviewEntryAt(it->path()));
    }
    if (error)
        throw InputError(std::string(field) + ": cannot list " + reviewQuoted(dir) + ": " + error.message());
    std::sort(entries.begin(), entries.end(),
              [](const ReviewEntry& a, const ReviewEntry& b) { return a.file < b.file; });
    return entries;
}

ReviewRead readReviewPng(const ReviewEntry& entry) {
    ReviewRead read;
    read.bytes = readReviewBytes(entry.path, read.error);
    if (!read.error.empty()) {
        read.bytes.clear();
        return read;
    }
    try {
        read.image = decodePng(read.bytes, printable(entry.path.string()));
    } catch (const RuntimeError& e) {
        read.error = e.what();
        read.bytes.clear();
    }
    return read;
}

std::string readReviewText(const fs::path& path) {
    std::string error;
    std::string text = readReviewBytes(path, error);
    if (!error.empty()) throw InputError("--expectations: " + error);
    return text;
}

std::string reviewIndexName(int index) {
    char name[16];
    std::snprintf(name, sizeof name, "%04d", index);
    return name;
}

void writeReviewBytes(const fs::path& path, std::string_view what, const std::string& bytes) {
    writeFileAtomically(
        path, what,
        [&](std::FILE* file) {
            if (std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size())
                failWrite(what, path, "short write");
        },
        OutputRule::InFolder);
}

fs::path prepareReviewOutputs(const ReviewOptions& o, const std::vector<fs::path>& inputs) {
    const std::vector<std::pair<fs::path, std::string_view>> files{{o.json, "--json"}, {o.junit, "--junit"}};
    for (const auto& [path, field] : files) {
        if (path.empty()) continue;
        (void)resolveOutput(path, field);
        refuseStandardOutputAlias(path, field, "the summary",
                                  field == "--json" ? "review.json" : "junit.xml");
        for (const fs::path& input : inputs) refuseOverwritingInput(path, field, input);
    }
    if (!o.json.empty() && (o.json == o.junit || isSameFile(o.json, o.junit)))
        throw InputError("--junit: " + reviewQuoted(o.junit) + " is also --json; give each its own file");
    if (o.out.empty()) return {};
    fs::path cases = o.out / "cases";
    for (const fs::path& folder : {o.actualDir, o.expectedDir, o.masks}) {
        if (folder.empty()) continue;
        for (const fs::path& written : {o.out, cases})
            if (isSameFile(written, folder))
                throw InputError("--out: " + reviewQuoted(written) + " is the input folder " +
                                 reviewQuoted(folder) + "; give the page a folder of its own");
    }
    prepareOutputFolder(o.out, "--out", {"index.html"}, inputs);
    // OUT/cases must be a folder of its own, never a link: the case images are created inside it.
    struct stat st {};
    if (::lstat(cases.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        throw InputError("--out: " + reviewQuoted(cases) + " is " + reviewKindName(st.st_mode) +
                         "; the case images are written into a folder of that name: remove it");
    prepareOutputFolder(cases, "--out", {}, inputs);
    return cases;
}

void checkReviewBlessFolder(const fs::path& expectedDir) {
    if (::access(expectedDir.c_str(), W_OK | X_OK) != 0)
        throw InputError("--bless: cannot write in EXPECTED_DIR " + reviewQuoted(expectedDir) + ": " +
                         std::strerror(errno));
}

} // namespace shadelab::app
