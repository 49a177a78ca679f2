#include "shadelab/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shadelab/errors.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& path) {
    return "\"" + path.string() + "\"";
}

} // namespace

[[noreturn]] void failWrite(std::string_view what, const fs::path& path, const std::string& reason) {
    throw RuntimeError("cannot write " + std::string(what) + " " + quoted(path) + ": " + reason);
}

namespace {

// mkstemp creates files 0600; a finished render should get the permissions fopen would have given it.
// umask can only be read by setting it, so this runs once.
mode_t newFileMode() {
    static const mode_t mode = [] {
        const mode_t mask = ::umask(0);
        ::umask(mask);
        return mode_t(0666) & ~mask;
    }();
    return mode;
}

// A temporary file beside the target. Until commit() renames it over the target, the destructor removes it,
// so an exception anywhere in the writer leaves the directory as it was.
class TempFile {
public:
    TempFile(const fs::path& target, std::string_view what) : target_(target), what_(what) {
        const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
        std::string pattern = (dir / ("." + target.filename().string() + ".XXXXXX")).string();
        const int fd = ::mkstemp(pattern.data());
        if (fd < 0)
            failWrite(what_, target,
                      "cannot create a temporary file in " + quoted(dir) + ": " + std::strerror(errno));
        path_ = pattern;
        // A throwing constructor skips the destructor, so these failures clean up themselves.
        if (::fchmod(fd, newFileMode()) != 0 || !(file_ = ::fdopen(fd, "wb"))) {
            const std::string reason = std::strerror(errno);
            ::close(fd);
            cleanUp();
            failWrite(what_, target, "cannot open the temporary file: " + reason);
        }
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    ~TempFile() { cleanUp(); }

    FILE* stream() const { return file_; }

    // Everything must be on disk before the rename, or a crash could leave a complete-looking empty file.
    void close() {
        if (std::fflush(file_) != 0) fail("flush");
        if (::fsync(::fileno(file_)) != 0) fail("fsync");
        FILE* file = std::exchange(file_, nullptr);
        if (std::fclose(file) != 0) fail("close");
    }

    void commit() {
        std::error_code error;
        fs::rename(path_, target_, error);
        if (error)
            failWrite(what_, target_, "cannot rename " + quoted(path_) + " over it: " + error.message());
        path_.clear();
    }

private:
    [[noreturn]] void fail(const char* step) {
        shadelab::failWrite(what_, target_,
                            std::string(step) + " " + quoted(path_) + ": " + std::strerror(errno));
    }

    void cleanUp() noexcept {
        if (file_) std::fclose(std::exchange(file_, nullptr));
        if (!path_.empty()) ::unlink(path_.c_str());
        path_.clear();
    }

    fs::path target_, path_;
    std::string what_;
    FILE* file_ = nullptr;
};

} // namespace

void writeFileAtomically(const fs::path& path, std::string_view what,
                         const std::function<void(std::FILE*)>& write) {
    TempFile temp(path, what);
    write(temp.stream());
    temp.close();
    temp.commit();
}

} // namespace shadelab
