// Scene text → JSON tree (DESIGN §4), the step that meets hostile input: the file is read only if it is a
// regular file of scene size, nesting is bounded before a tree is built, and every syntax error is named
// with its byte (and, for duplicate keys and numbers out of range, its JSON path). scene_parse.cpp turns
// the tree into a Scene.
#include <array>
#include <cerrno>
#include <cstdint>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "scene/scene_internal.h"
#include "shadelab/io/text.h"

namespace shadelab::detail {

namespace {

// The format needs 5 levels (root → objects → object → material → colour); 64 leaves room for growth while
// refusing inputs whose only purpose is to exhaust memory or stack in whatever walks the tree next.
constexpr int kMaxNesting = 64;
// A scene is a few kilobytes; a larger file is a mistake (a PNG, a log), not a scene.

// nlohmann's parser is iterative, but a hostile file nested a million deep still builds a million-node
// tree for nothing. Count brackets outside strings first.
void checkNesting(std::string_view text) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxNesting)
                fail("", "invalid JSON at byte " + std::to_string(i + 1) + ": nested deeper than " +
                             std::to_string(kMaxNesting) + " levels");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

// nlohmann's messages start with "[json.exception.parse_error.101] "; the id means nothing to a user.
std::string_view withoutExceptionId(std::string_view message) {
    if (message.starts_with("[json.exception.")) {
        std::size_t end = message.find("] ");
        if (end != std::string_view::npos) return message.substr(end + 2);
    }
    return message;
}

// A first pass over the text that builds nothing and knows the JSON path of every value. The DOM parser
// silently keeps the last of duplicate keys (we reject them) and reports a number overflow without saying
// where (we name the path). Not a parse callback: nlohmann rescans the parent array after every element
// built with a callback, which made a 100 000-element array take minutes.
class PathTrackingSax : public nlohmann::json_sax<Json> {
public:
    explicit PathTrackingSax(std::string_view text) : text_(text) {}

    bool null() override { return valueDone(); }
    bool boolean(bool) override { return valueDone(); }
    bool number_integer(number_integer_t) override { return valueDone(); }
    bool number_unsigned(number_unsigned_t) override { return valueDone(); }
    bool number_float(number_float_t, const string_t&) override { return valueDone(); }
    bool string(string_t&) override { return valueDone(); }
    bool binary(binary_t&) override { return valueDone(); }
    bool start_object(std::size_t) override { return frames_.emplace_back(true), true; }
    bool start_array(std::size_t) override { return frames_.emplace_back(false), true; }
    bool end_object() override { return frames_.pop_back(), valueDone(); }
    bool end_array() override { return frames_.pop_back(), valueDone(); }

    bool key(string_t& key) override {
        Frame& frame = frames_.back();
        frame.key = key;
        if (!frame.keys.insert(key).second) fail(path(), "duplicate key");
        return true;
    }

    bool parse_error(std::size_t byte, const std::string& lastToken, const Json::exception& e) override {
        // 406 is "number overflow": 1e999 would be inf, which the format forbids like any non-finite number.
        if (e.id == 406) failNotFinite(path(), lastToken);
        // Not JSON at all, but what a user who means "not finite" writes: name the field and say so.
        for (std::string_view literal : {"-Infinity", "Infinity", "NaN"}) {
            const std::size_t at = text_.find(literal, byte >= 2 ? byte - 2 : 0);
            if (at != std::string_view::npos && at <= byte)
                fail(path(),
                     "must be finite, got " + std::string(literal) + " (JSON has no NaN or Infinity)");
        }
        std::string message(withoutExceptionId(e.what()));
        if (message.size() > 200) message = message.substr(0, 200) + "…";
        // A comment is the likeliest reason for a '/' where a value or a key should be.
        const std::size_t slash = text_.find('/', byte >= 2 ? byte - 2 : 0);
        if (slash != std::string_view::npos && slash <= byte &&
            (text_.substr(slash).starts_with("//") || text_.substr(slash).starts_with("/*")))
            message += " (JSON has no comments: remove the // or /* */ text)";
        fail("", "invalid JSON at byte " + std::to_string(byte) + ": " + message);
    }

private:
    struct Frame {
        explicit Frame(bool object) : isObject(object) {}
        bool isObject;
        std::string key;
        std::size_t index = 0;
        std::set<std::string, std::less<>> keys;
    };

    // The path of the value being parsed now.
    std::string path() const {
        std::string out;
        for (const Frame& frame : frames_)
            out = frame.isObject ? keyPath(out, frame.key) : indexPath(out, frame.index);
        return out;
    }

    bool valueDone() {
        if (!frames_.empty() && !frames_.back().isObject) ++frames_.back().index;
        return true;
    }

    std::string_view text_;
    std::vector<Frame> frames_;
};

} // namespace

Json parseJson(std::string_view text) {
    checkNesting(text);
    PathTrackingSax checker(text);
    Json::sax_parse(text.begin(), text.end(), &checker);
    // Syntax errors before it are reported above; but nlohmann's parser takes a NUL byte for the end of the
    // input, which would let anything after it pass unread. JSON text never holds a raw NUL (RFC 8259 §7).
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
        fail("", "invalid JSON: a NUL byte at offset " + std::to_string(nul) +
                     "; a scene file is JSON text, and JSON has no raw NUL");
    try {
        return Json::parse(text.begin(), text.end());
    } catch (const Json::exception& e) { // unreachable after the first pass, but never crash on input
        fail("", "invalid JSON: " + std::string(withoutExceptionId(e.what())));
    }
}

// A scene is a regular file, or "-" for standard input. Anything else (a FIFO, a device, a folder) is
// refused before it is opened: opening a FIFO would wait for a writer forever, a device may never end.
std::string readSceneFile(const std::filesystem::path& path) {
    const bool fromStdin = path == "-";
    const std::string name = fromStdin ? std::string("standard input") : printable(path.string());
    auto cannotRead = [&](const std::string& reason) {
        throw InputError(name + ": cannot read scene file: " + reason);
    };
    int fd = STDIN_FILENO;
    if (!fromStdin) {
        struct stat st {};
        if (::stat(path.c_str(), &st) != 0) cannotRead(std::generic_category().message(errno));
        if (S_ISDIR(st.st_mode)) cannotRead("it is a directory");
        if (!S_ISREG(st.st_mode))
            cannotRead(std::string("it is ") + (S_ISFIFO(st.st_mode) ? "a FIFO" : "not a regular file") +
                       "; a scene is a regular file, or - to read standard input");
        fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
        if (fd < 0) cannotRead(std::generic_category().message(errno));
        // The file could have been swapped between stat and open: check what was opened.
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
            ::close(fd);
            cannotRead("it is not a regular file; a scene is a regular file, or - to read standard input");
        }
    }
    std::string text;
    std::array<char, 65536> chunk;
    for (;;) {
        const ssize_t n = ::read(fd, chunk.data(), chunk.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int error = errno;
            if (!fromStdin) ::close(fd);
            cannotRead("read error: " + std::generic_category().message(error));
        }
        if (n == 0) break;
        text.append(chunk.data(), static_cast<std::size_t>(n));
        if (text.size() > kMaxSceneBytes) {
            if (!fromStdin) ::close(fd);
            checkSceneTextSize(text.size(), name);
        }
    }
    if (!fromStdin) ::close(fd);
    return text;
}

} // namespace shadelab::detail

namespace shadelab {

void checkSceneTextSize(std::size_t bytes, std::string_view name) {
    if (bytes > kMaxSceneBytes)
        throw InputError(printable(name) + ": cannot read scene file: larger than " +
                         std::to_string(kMaxSceneBytes >> 20) + " MiB; not a scene file");
}

} // namespace shadelab
