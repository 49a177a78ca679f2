// Scene files (DESIGN §4): JSON → Scene, with every error naming the JSON path, the value and what is
// expected. Parsing reads structure and types; the range checks live in one set of check* functions that
// both parseScene (per entity, as it is read) and validateScene (after CLI overrides) call, so the two can
// never disagree about what a valid scene is.
#include "shadelab/scene.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "shadelab/atomic_file.h"
#include "shadelab/errors.h"
#include "shadelab/subdivision.h"
#include "shadelab/text.h"
#include "shadelab/vocabulary.h"

namespace shadelab {

namespace {

using Json = nlohmann::json;

// The format needs 5 levels (root → objects → object → material → colour); 64 leaves room for growth while
// refusing inputs whose only purpose is to exhaust memory or stack in whatever walks the tree next.
constexpr int kMaxNesting = 64;
// A scene is a few kilobytes; a larger file is a mistake (a PNG, a log), not a scene.
constexpr std::uintmax_t kMaxSceneFileBytes = 16u << 20;

struct IntRange {
    int lo, hi;
};
constexpr IntRange kImageSizeRange{1, kMaxImageSize};
constexpr IntRange kSubdivisionRange{0, kMaxSubdivisions};
constexpr IntRange kToonBandRange{kMinToonBands, kMaxToonBands};

// ---- message pieces ----

// What std::to_chars(value) gives: the fewest significant digits that read back as `value`, in fixed or
// scientific notation, whichever is shorter (fixed on a tie). Written out because the browser build's
// libc++ has no floating-point to_chars, and the page must word a message exactly as the command line does.
std::string formatNumber(double value) {
    if (!std::isfinite(value)) return std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf";
    std::array<char, 40> scientific{};
    int digits = 1;
    for (; digits < 17; ++digits) {
        std::snprintf(scientific.data(), scientific.size(), "%.*e", digits - 1, value);
        if (std::strtod(scientific.data(), nullptr) == value) break;
    }
    std::snprintf(scientific.data(), scientific.size(), "%.*e", digits - 1, value);
    const int exponent = std::atoi(std::strchr(scientific.data(), 'e') + 1);
    std::array<char, 400> fixed{}; // up to 309 integer digits
    std::snprintf(fixed.data(), fixed.size(), "%.*f", std::max(0, digits - 1 - exponent), value);
    const std::string a(fixed.data()), b(scientific.data());
    return a.size() <= b.size() ? a : b;
}

std::string formatVec(const glm::dvec3& v) {
    return "[" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + "]";
}

std::string describe(const Json& value) {
    switch (value.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return value.get<bool>() ? "true" : "false";
    case Json::value_t::string:
        return "string " + quotedValue(value.get_ref<const std::string&>());
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
        return "number " + formatNumber(value.get<double>());
    case Json::value_t::array:
        return "array of " + std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements");
    case Json::value_t::object:
        return "object";
    default:
        return "unsupported value";
    }
}

std::string joinKeys(std::span<const std::string_view> keys) {
    std::string out;
    for (std::string_view key : keys) out += (out.empty() ? "" : ", ") + std::string(key);
    return out;
}

// ---- JSON paths: objects[0].material.diffuse[2] ----

bool isPlainKey(std::string_view key) {
    if (key.empty() || key.size() > kMaxQuotedChars) return false; // a long key is quoted, and so truncated
    for (char c : key)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
    return true;
}

std::string keyPath(std::string_view parent, std::string_view key) {
    if (!isPlainKey(key)) return std::string(parent) + "[" + quotedValue(key) + "]";
    return parent.empty() ? std::string(key) : std::string(parent) + "." + std::string(key);
}

std::string indexPath(std::string_view parent, std::size_t index) {
    return std::string(parent) + "[" + std::to_string(index) + "]";
}

[[noreturn]] void fail(std::string_view path, std::string_view message) {
    throw InputError(path.empty() ? std::string(message) : std::string(path) + ": " + std::string(message));
}

// ---- range checks, shared by parseScene and validateScene ----

void checkFinite(double value, std::string_view path) {
    if (!std::isfinite(value)) fail(path, "must be finite, got " + formatNumber(value));
}

void checkGreater(double value, double min, std::string_view path) {
    checkFinite(value, path);
    if (!(value > min)) fail(path, "must be > " + formatNumber(min) + ", got " + formatNumber(value));
}

void checkAtLeast(double value, double min, std::string_view path) {
    checkFinite(value, path);
    if (!(value >= min)) fail(path, "must be >= " + formatNumber(min) + ", got " + formatNumber(value));
}

void checkIntRange(int value, IntRange range, std::string_view path) {
    if (value < range.lo || value > range.hi)
        fail(path, "must be between " + std::to_string(range.lo) + " and " + std::to_string(range.hi) +
                       ", got " + std::to_string(value));
}

void checkFiniteVec(const glm::dvec3& v, std::string_view path) {
    for (int i = 0; i < 3; ++i) checkFinite(v[i], indexPath(path, i));
}

void checkColor(const glm::dvec3& color, std::string_view path) {
    for (int i = 0; i < 3; ++i) checkAtLeast(color[i], 0, indexPath(path, i));
}

void checkNonZeroVec(const glm::dvec3& v, std::string_view path) {
    checkFiniteVec(v, path);
    if (v == glm::dvec3(0)) fail(path, "must be non-zero, got " + formatVec(v));
}

// Errors from camera.h and sphere.h may already name the field; add the path only where they don't.
[[noreturn]] void failWithin(std::string_view path, const InputError& error) {
    std::string_view message = error.what();
    if (message.starts_with(path)) throw error;
    fail(path, message);
}

void checkSubdivisions(int level, const std::string& path) {
    if (level == kAutoSubdivisions) return;
    if (level > kSubdivisionRange.hi) {
        // Its message says how much memory the level would take, which is the useful part.
        try {
            checkSubdivisionLevel(level, path.c_str());
        } catch (const InputError& e) {
            failWithin(path, e);
        }
    }
    checkIntRange(level, kSubdivisionRange, path);
}

void checkViewAt(double at) {
    checkFinite(at, "view_at");
    if (!(at >= 0 && at <= 1))
        fail("view_at", "must be between 0 and 1 (a fraction of the picture), got " + formatNumber(at));
}

void checkImageSize(const Scene& scene) {
    checkIntRange(scene.width, kImageSizeRange, "image.width");
    checkIntRange(scene.height, kImageSizeRange, "image.height");
}

void checkImage(const Scene& scene) {
    checkImageSize(scene);
    checkColor(scene.background, "image.background");
}

void checkCamera(const Scene& scene) {
    checkFiniteVec(scene.eye, "camera.eye");
    checkFiniteVec(scene.target, "camera.target");
    checkFiniteVec(scene.up, "camera.up");
    try {
        cameraFrame(scene.eye, scene.target, scene.up);
    } catch (const InputError& e) {
        failWithin("camera", e);
    }
}

void checkDistinct(double value, double other, std::string_view otherName, std::string_view path) {
    checkFinite(value, path);
    if (value == other)
        fail(path, "must differ from " + std::string(otherName) + " (" + formatNumber(other) + "), got " +
                       formatNumber(value));
}

void checkProjection(const Projection& p) {
    if (p.type == ProjectionType::Perspective) {
        checkGreater(p.fovyDeg, 0, "projection.fovy_deg");
        if (!(p.fovyDeg < 180)) fail("projection.fovy_deg", "must be < 180, got " + formatNumber(p.fovyDeg));
        // The projection holds cot(fovy/2) in 32-bit float and scales depth by it: narrower views lose the
        // picture (4.9e-324 made the window zero-wide). 1e-6 degrees keeps it near 1e8.
        if (p.fovyDeg < kMinFovyDeg)
            fail("projection.fovy_deg",
                 "must be at least " + formatNumber(kMinFovyDeg) +
                     " degrees (a narrower view does not fit 32-bit float matrices), got " +
                     formatNumber(p.fovyDeg));
    } else {
        checkFinite(p.left, "projection.left");
        checkDistinct(p.right, p.left, "left", "projection.right");
        checkFinite(p.bottom, "projection.bottom");
        checkDistinct(p.top, p.bottom, "bottom", "projection.top");
    }
    checkGreater(p.near, 0, "projection.near");
    checkFinite(p.far, "projection.far");
    if (!(p.far > p.near))
        fail("projection.far", "must be > near (" + formatNumber(p.near) + "), got " + formatNumber(p.far));
    // The projection matrix reaches the GPU as 32-bit float (normal range 1.2e-38..3.4e38, and its entries
    // are products and quotients of these values): near 1e-300 or a window of ±1e-300 became 0 there and
    // drew nothing. Refuse what float cannot carry instead of drawing a wrong picture; a scene that needs
    // more can change its units.
    auto inFloatRange = [](double magnitude, std::string_view path) {
        if (magnitude != 0 && (magnitude < kMinProjectionExtent || magnitude > kMaxProjectionExtent))
            fail(path, "must be 0 or between " + formatNumber(kMinProjectionExtent) + " and " +
                           formatNumber(kMaxProjectionExtent) +
                           " in magnitude (the projection is 32-bit float on the GPU), got " +
                           formatNumber(magnitude) + "; change the scene's units");
    };
    inFloatRange(p.near, "projection.near");
    inFloatRange(p.far, "projection.far");
    if (p.type == ProjectionType::Orthographic) {
        inFloatRange(std::abs(p.left), "projection.left");
        inFloatRange(std::abs(p.right), "projection.right");
        inFloatRange(std::abs(p.bottom), "projection.bottom");
        inFloatRange(std::abs(p.top), "projection.top");
        inFloatRange(std::abs(p.right - p.left), "projection.right");
        inFloatRange(std::abs(p.top - p.bottom), "projection.top");
    }
    inFloatRange(p.far - p.near, "projection.far");
}

void checkMaterial(const Material& m, const std::string& path) {
    checkColor(m.ambient, keyPath(path, "ambient"));
    checkColor(m.diffuse, keyPath(path, "diffuse"));
    checkColor(m.specular, keyPath(path, "specular"));
    // pow(0, 0) is undefined in GLSL (DESIGN §3).
    checkAtLeast(m.shininess, 1, keyPath(path, "shininess"));
}

void checkObject(const SceneObject& object, const std::string& path) {
    checkFiniteVec(object.center, keyPath(path, "center"));
    checkGreater(object.radius, 0, keyPath(path, "radius"));
    std::string scalePath = keyPath(path, "scale");
    checkFiniteVec(object.scale, scalePath);
    // Negative components mirror (allowed); zero flattens the ellipsoid and its normal matrix.
    for (int i = 0; i < 3; ++i)
        if (object.scale[i] == 0) fail(indexPath(scalePath, i), "must be non-zero, got 0");
    checkSubdivisions(object.subdivisions, keyPath(path, "subdivisions"));
    checkMaterial(object.material, keyPath(path, "material"));
}

void checkObjectCount(std::size_t count) {
    if (count > kMaxObjects)
        fail("objects", "at most " + std::to_string(kMaxObjects) + " objects are supported, got " +
                            std::to_string(count) + "; draw fewer objects");
}

// The work a scene asks for, bounded before any of it is done (README "Limits"): the triangles drawn per
// frame, and the ray-object tests of the analytic reference (pixels × objects), which render and reference
// share as one notion of a valid scene.
void checkWork(const Scene& scene) {
    double triangles = 0;
    for (const SceneObject& object : scene.objects)
        triangles += double(sphereTriangleCount(subdivisionLevel(scene, object)));
    if (triangles > double(kMaxTrianglesPerFrame))
        fail("objects", "the scene draws " + formatNumber(triangles) +
                            " triangles per frame (each object 4^(level+1)); at most " +
                            std::to_string(kMaxTrianglesPerFrame) +
                            " are allowed: lower the objects' subdivisions or draw fewer objects");
    const double rayTests = double(scene.width) * scene.height * double(scene.objects.size());
    if (rayTests > double(kMaxReferenceRayTests))
        fail("objects", "the analytic reference would test " + formatNumber(rayTests) +
                            " rays against objects (width x height x objects); at most " +
                            std::to_string(kMaxReferenceRayTests) +
                            " are allowed: use a smaller image or fewer objects");
}

// Standard depth (DESIGN's [-1, 1] mapping, near → +1) puts a point at distance d at NDC z ≈ 1 − 2·near/d
// in 32-bit float, whose spacing just below 1 is 6e-8: past d ≈ 3e7·near whole objects round onto the near
// plane and are clipped (measured: the default sphere at d = 3 loses a third of its pixels with near 1e-7
// and vanishes with near 1e-10, while the reversed modes draw it whole). Refuse before that, with a margin.
void checkStandardDepthRange(const Scene& scene) {
    if (scene.depth != DepthMode::Standard || scene.projection.type != ProjectionType::Perspective) return;
    const double near = scene.projection.near;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        const double extent =
            std::abs(o.radius) * std::max({std::abs(o.scale.x), std::abs(o.scale.y), std::abs(o.scale.z)});
        const double farthest = std::min(glm::length(o.center - scene.eye) + extent, scene.projection.far);
        if (farthest / near > kMaxStandardDepthRatio)
            fail("projection.near",
                 "with \"depth\": \"standard\", " + indexPath("objects", i) + " reaches " +
                     formatNumber(farthest / near) +
                     " x near from the eye; 32-bit depth rounds points beyond " +
                     formatNumber(kMaxStandardDepthRatio) +
                     " x near onto the near plane and clips them: raise near to at least " +
                     formatNumber(farthest / kMaxStandardDepthRatio) + " or use \"depth\": \"reversed\"");
    }
}

void checkLightCount(std::size_t count) {
    if (count > static_cast<std::size_t>(kMaxLights))
        fail("lights",
             "at most " + std::to_string(kMaxLights) + " lights are supported, got " + std::to_string(count));
}

// "an ambient light", "a point light".
std::string withArticle(std::string_view noun) {
    bool vowel = !noun.empty() && std::string_view("aeiou").find(noun.front()) != std::string_view::npos;
    return (vowel ? "an " : "a ") + std::string(noun);
}

std::string lightName(LightType type) {
    return withArticle(std::string(toString(type)) + " light");
}

bool hasPosition(LightType type) {
    return type == LightType::Point || type == LightType::Spot;
}
bool hasDirection(LightType type) {
    return type == LightType::Directional || type == LightType::Spot;
}

void checkAttenuation(const glm::dvec3& a, const std::string& path) {
    for (int i = 0; i < 3; ++i) checkAtLeast(a[i], 0, indexPath(path, i));
    if (!(a.x + a.y + a.z > 0)) fail(path, "components must have a positive sum, got " + formatVec(a));
}

// Only the fields the light's type uses are checked: the others are ignored by the lighting code.
void checkLight(const Light& light, const std::string& path) {
    checkColor(light.ambient, keyPath(path, "ambient"));
    checkColor(light.diffuse, keyPath(path, "diffuse"));
    checkColor(light.specular, keyPath(path, "specular"));
    if (hasPosition(light.type)) {
        checkFiniteVec(light.position, keyPath(path, "position"));
        checkAttenuation(light.attenuation, keyPath(path, "attenuation"));
    }
    if (hasDirection(light.type)) checkNonZeroVec(light.direction, keyPath(path, "direction"));
    if (light.type == LightType::Spot) {
        std::string cutoffPath = keyPath(path, "cutoff_deg");
        checkAtLeast(light.cutoffDeg, 0, cutoffPath);
        if (!(light.cutoffDeg <= 90)) fail(cutoffPath, "must be <= 90, got " + formatNumber(light.cutoffDeg));
        checkAtLeast(light.exponent, 0, keyPath(path, "exponent"));
    }
}

// ---- JSON text → tree ----

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
        if (e.id == 406)
            fail(path(), "must be finite, got " + (lastToken.size() > kMaxQuotedChars
                                                       ? lastToken.substr(0, kMaxQuotedChars) + "..."
                                                       : lastToken));
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

// ---- tree → values (types and structure; ranges are the check* functions above) ----

void requireObject(const Json& value, std::string_view path) {
    if (!value.is_object())
        fail(path.empty() ? "the top level" : path, "must be an object, got " + describe(value));
}

void checkKeys(const Json& object, std::string_view path, std::span<const std::string_view> allowed) {
    for (auto it = object.begin(); it != object.end(); ++it)
        if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
            fail(keyPath(path, it.key()), "unknown key; expected one of " + joinKeys(allowed));
}

// For objects whose keys depend on their type (projections, lights): a key that another type takes is not a
// typo but a misunderstanding, so say that it does not apply rather than that it is unknown.
void checkKeysOfType(const Json& object, std::string_view path, std::span<const std::string_view> allowed,
                     std::span<const std::string_view> anyType, std::string_view typeName) {
    auto contains = [](std::span<const std::string_view> keys, std::string_view key) {
        return std::find(keys.begin(), keys.end(), key) != keys.end();
    };
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (contains(allowed, it.key())) continue;
        std::string problem =
            contains(anyType, it.key()) ? "does not apply to " + std::string(typeName) : "unknown key";
        fail(keyPath(path, it.key()), problem + "; expected one of " + joinKeys(allowed));
    }
}

const Json* member(const Json& object, std::string_view key) {
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

double readNumber(const Json& value, std::string_view path) {
    if (!value.is_number()) fail(path, "must be a number, got " + describe(value));
    double number = value.get<double>();
    checkFinite(number, path);
    return number;
}

// Whole numbers beyond int are reported against the field's range before converting (which would overflow).
int readInt(const Json& value, std::string_view path, IntRange range) {
    double number = readNumber(value, path);
    if (number != std::floor(number)) fail(path, "must be a whole number, got " + formatNumber(number));
    if (number < std::numeric_limits<int>::min() || number > std::numeric_limits<int>::max())
        fail(path, "must be between " + std::to_string(range.lo) + " and " + std::to_string(range.hi) +
                       ", got " + formatNumber(number));
    return static_cast<int>(number);
}

glm::dvec3 readVec3(const Json& value, std::string_view path) {
    if (!value.is_array() || value.size() != 3)
        fail(path, "must be an array of 3 numbers, got " + describe(value));
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) v[i] = readNumber(value[i], indexPath(path, i));
    return v;
}

const std::string& readString(const Json& value, std::string_view path) {
    if (!value.is_string()) fail(path, "must be a string, got " + describe(value));
    return value.get_ref<const std::string&>();
}

template <class Enum, std::size_t N>
Enum readEnum(const Json& value, std::string_view path, const std::array<Enum, N>& values) {
    return parseNameOrThrow(readString(value, path), path, values);
}

// Optional fields: the output keeps its default when the key is absent. Returns whether it was present.
bool readField(const Json& object, std::string_view path, std::string_view key, double& out) {
    const Json* value = member(object, key);
    if (value) out = readNumber(*value, keyPath(path, key));
    return value != nullptr;
}

bool readField(const Json& object, std::string_view path, std::string_view key, glm::dvec3& out) {
    const Json* value = member(object, key);
    if (value) out = readVec3(*value, keyPath(path, key));
    return value != nullptr;
}

void readIntField(const Json& object, std::string_view path, std::string_view key, IntRange range, int& out) {
    if (const Json* value = member(object, key)) out = readInt(*value, keyPath(path, key), range);
}

void readImage(const Json& image, Scene& scene) {
    static constexpr std::array<std::string_view, 3> kKeys = {"width", "height", "background"};
    requireObject(image, "image");
    checkKeys(image, "image", kKeys);
    readIntField(image, "image", "width", kImageSizeRange, scene.width);
    readIntField(image, "image", "height", kImageSizeRange, scene.height);
    readField(image, "image", "background", scene.background);
    checkImage(scene);
}

void readCamera(const Json& camera, Scene& scene) {
    static constexpr std::array<std::string_view, 3> kKeys = {"eye", "target", "up"};
    requireObject(camera, "camera");
    checkKeys(camera, "camera", kKeys);
    readField(camera, "camera", "eye", scene.eye);
    readField(camera, "camera", "target", scene.target);
    readField(camera, "camera", "up", scene.up);
    checkCamera(scene);
}

// left/right/bottom/top may be omitted for frustum and orthographic and then default to -1, 1, -1, 1 (the
// Projection defaults): the unit square, a sensible orthographic view of the default unit sphere.
Projection readProjection(const Json& json) {
    static constexpr std::array<std::string_view, 4> kPerspectiveKeys = {"type", "fovy_deg", "near", "far"};
    static constexpr std::array<std::string_view, 7> kBoxKeys = {"type", "left", "right", "bottom",
                                                                 "top",  "near", "far"};
    requireObject(json, "projection");
    Projection p;
    if (const Json* type = member(json, "type"))
        p.type = readEnum(*type, "projection.type", kProjectionTypes);
    static constexpr std::array<std::string_view, 8> kAnyKeys = {"type",   "fovy_deg", "left", "right",
                                                                 "bottom", "top",      "near", "far"};
    bool perspective = p.type == ProjectionType::Perspective;
    checkKeysOfType(json, "projection",
                    perspective ? std::span<const std::string_view>(kPerspectiveKeys) : kBoxKeys, kAnyKeys,
                    withArticle(std::string(toString(p.type)) + " projection"));
    readField(json, "projection", "fovy_deg", p.fovyDeg);
    readField(json, "projection", "left", p.left);
    readField(json, "projection", "right", p.right);
    readField(json, "projection", "bottom", p.bottom);
    readField(json, "projection", "top", p.top);
    readField(json, "projection", "near", p.near);
    readField(json, "projection", "far", p.far);
    checkProjection(p);
    return p;
}

Material readMaterial(const Json& json, const std::string& path) {
    static constexpr std::array<std::string_view, 4> kKeys = {"ambient", "diffuse", "specular", "shininess"};
    requireObject(json, path);
    checkKeys(json, path, kKeys);
    Material m;
    readField(json, path, "ambient", m.ambient);
    readField(json, path, "diffuse", m.diffuse);
    readField(json, path, "specular", m.specular);
    readField(json, path, "shininess", m.shininess);
    return m;
}

SceneObject readObject(const Json& json, const std::string& path) {
    static constexpr std::array<std::string_view, 5> kKeys = {"center", "radius", "scale", "subdivisions",
                                                              "material"};
    requireObject(json, path);
    checkKeys(json, path, kKeys);
    SceneObject object;
    readField(json, path, "center", object.center);
    readField(json, path, "radius", object.radius);
    readField(json, path, "scale", object.scale);
    if (const Json* level = member(json, "subdivisions"); level && level->is_string()) {
        if (level->get<std::string>() != "auto")
            fail(keyPath(path, "subdivisions"), "must be a level 0.." + std::to_string(kMaxSubdivisions) +
                                                    " or \"auto\", got " + describe(*level));
        object.subdivisions = kAutoSubdivisions;
    } else {
        readIntField(json, path, "subdivisions", kSubdivisionRange, object.subdivisions);
        // In a file "auto" is spelled out; kAutoSubdivisions is only the in-memory sentinel.
        if (object.subdivisions < 0)
            checkIntRange(object.subdivisions, kSubdivisionRange, keyPath(path, "subdivisions"));
    }
    if (const Json* material = member(json, "material"))
        object.material = readMaterial(*material, keyPath(path, "material"));
    checkObject(object, path);
    return object;
}

const Json& requireArray(const Json& value, std::string_view path) {
    if (!value.is_array()) fail(path, "must be an array, got " + describe(value));
    return value;
}

std::vector<SceneObject> readObjects(const Json& json) {
    checkObjectCount(requireArray(json, "objects").size());
    std::vector<SceneObject> objects;
    for (std::size_t i = 0; i < requireArray(json, "objects").size(); ++i)
        objects.push_back(readObject(json[i], indexPath("objects", i)));
    return objects;
}

std::span<const std::string_view> lightKeys(LightType type) {
    static constexpr std::array<std::string_view, 2> kAmbient = {"type", "ambient"};
    static constexpr std::array<std::string_view, 5> kDirectional = {"type", "direction", "ambient",
                                                                     "diffuse", "specular"};
    static constexpr std::array<std::string_view, 6> kPoint = {"type",    "position", "attenuation",
                                                               "ambient", "diffuse",  "specular"};
    static constexpr std::array<std::string_view, 9> kSpot = {"type",       "position", "direction",
                                                              "cutoff_deg", "exponent", "attenuation",
                                                              "ambient",    "diffuse",  "specular"};
    switch (type) {
    case LightType::Ambient:
        return kAmbient;
    case LightType::Directional:
        return kDirectional;
    case LightType::Point:
        return kPoint;
    case LightType::Spot:
        break;
    }
    return kSpot;
}

void readRequired(const Json& json, const std::string& path, std::string_view key, LightType type,
                  glm::dvec3& out) {
    if (!readField(json, path, key, out)) fail(keyPath(path, key), "required for " + lightName(type));
}

Light readLight(const Json& json, const std::string& path) {
    requireObject(json, path);
    const Json* typeJson = member(json, "type");
    if (!typeJson) fail(keyPath(path, "type"), "required; expected one of " + joinNames(kLightTypes));
    Light light;
    light.type = readEnum(*typeJson, keyPath(path, "type"), kLightTypes);
    checkKeysOfType(json, path, lightKeys(light.type), lightKeys(LightType::Spot), lightName(light.type));
    if (light.type == LightType::Ambient) light.diffuse = light.specular = glm::dvec3(0);
    if (hasPosition(light.type)) readRequired(json, path, "position", light.type, light.position);
    if (hasDirection(light.type)) readRequired(json, path, "direction", light.type, light.direction);
    if (light.type == LightType::Spot && !readField(json, path, "cutoff_deg", light.cutoffDeg))
        fail(keyPath(path, "cutoff_deg"), "required for a spot light");
    readField(json, path, "exponent", light.exponent);
    readField(json, path, "attenuation", light.attenuation);
    readField(json, path, "ambient", light.ambient);
    readField(json, path, "diffuse", light.diffuse);
    readField(json, path, "specular", light.specular);
    checkLight(light, path);
    return light;
}

std::vector<Light> readLights(const Json& json) {
    checkLightCount(requireArray(json, "lights").size());
    std::vector<Light> lights;
    for (std::size_t i = 0; i < json.size(); ++i)
        lights.push_back(readLight(json[i], indexPath("lights", i)));
    return lights;
}

Scene readScene(const Json& root) {
    static constexpr std::array<std::string_view, 14> kKeys = {
        "image", "camera",         "projection", "shading", "lighting", "toon_bands", "tolerance_px",
        "depth", "vertex_normals", "overlay",    "view",    "view_at",  "objects",    "lights"};
    requireObject(root, "");
    checkKeys(root, "", kKeys);
    Scene scene;
    if (const Json* image = member(root, "image")) readImage(*image, scene);
    if (const Json* camera = member(root, "camera")) readCamera(*camera, scene);
    if (const Json* projection = member(root, "projection")) scene.projection = readProjection(*projection);
    if (const Json* shading = member(root, "shading"))
        scene.shading = readEnum(*shading, "shading", kAllShadingModes);
    if (const Json* lighting = member(root, "lighting"))
        scene.lighting = readEnum(*lighting, "lighting", kLightingModels);
    readIntField(root, "", "toon_bands", kToonBandRange, scene.toonBands);
    checkIntRange(scene.toonBands, kToonBandRange, "toon_bands");
    readField(root, "", "tolerance_px", scene.tolerancePx);
    checkGreater(scene.tolerancePx, 0, "tolerance_px");
    if (const Json* depth = member(root, "depth")) scene.depth = readEnum(*depth, "depth", kDepthModes);
    if (const Json* normals = member(root, "vertex_normals"))
        scene.vertexNormals = readEnum(*normals, "vertex_normals", kVertexNormals);
    if (const Json* overlay = member(root, "overlay"))
        scene.overlay = readEnum(*overlay, "overlay", kOverlays);
    if (const Json* view = member(root, "view")) {
        const std::string& text = readString(*view, "view");
        ViewParse parsed = parseView(text);
        if (!parsed.view) fail("view", "\"" + printable(text) + "\": " + parsed.error);
        scene.view = *parsed.view;
    }
    if (const Json* at = member(root, "view_at")) {
        scene.view.at = readNumber(*at, "view_at");
        checkViewAt(*scene.view.at);
    }
    if (const Json* objects = member(root, "objects")) scene.objects = readObjects(*objects);
    if (const Json* lights = member(root, "lights")) scene.lights = readLights(*lights);
    return scene;
}

// A scene is a regular file, or "-" for standard input. Anything else (a FIFO, a device, a folder) is
// refused before it is opened: opening a FIFO would wait for a writer forever, a device may never end.
std::string readFile(const std::filesystem::path& path) {
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
        if (text.size() > kMaxSceneFileBytes) {
            if (!fromStdin) ::close(fd);
            cannotRead("larger than " + std::to_string(kMaxSceneFileBytes >> 20) + " MiB; not a scene file");
        }
    }
    if (!fromStdin) ::close(fd);
    return text;
}

} // namespace

std::string_view toString(DepthMode mode) {
    switch (mode) {
    case DepthMode::Standard:
        return "standard";
    case DepthMode::Reversed:
        return "reversed";
    case DepthMode::ReversedInfinite:
        return "reversed-infinite";
    }
    return "unknown";
}

std::optional<DepthMode> parseDepthMode(std::string_view text) {
    return parseName(text, kDepthModes);
}

std::string_view toString(Overlay overlay) {
    switch (overlay) {
    case Overlay::None:
        return "none";
    case Overlay::Wireframe:
        return "wireframe";
    case Overlay::Normals:
        return "normals";
    }
    return "unknown";
}

std::optional<Overlay> parseOverlay(std::string_view text) {
    return parseName(text, kOverlays);
}

std::string_view toString(ProjectionType type) {
    switch (type) {
    case ProjectionType::Perspective:
        return "perspective";
    case ProjectionType::Frustum:
        return "frustum";
    case ProjectionType::Orthographic:
        return "orthographic";
    }
    return "unknown";
}

Light Scene::defaultLight() {
    Light light;
    light.type = LightType::Point;
    light.position = {3, 3, 5};
    light.ambient = glm::dvec3(0.1);
    light.diffuse = glm::dvec3(1);
    light.specular = glm::dvec3(1);
    light.attenuation = {1, 0, 0};
    return light;
}

Scene parseScene(std::string_view jsonText, std::string_view source) {
    try {
        return readScene(parseJson(jsonText));
    } catch (const InputError& e) {
        throw InputError(std::string(source) + ": " + e.what());
    }
}

namespace {

Json toJson(const glm::dvec3& v) {
    return Json::array({v.x, v.y, v.z});
}

Json toJson(const Projection& p) {
    Json json = {{"type", toString(p.type)}, {"near", p.near}, {"far", p.far}};
    if (p.type == ProjectionType::Perspective) {
        json["fovy_deg"] = p.fovyDeg;
    } else {
        json["left"] = p.left;
        json["right"] = p.right;
        json["bottom"] = p.bottom;
        json["top"] = p.top;
    }
    return json;
}

Json toJson(const SceneObject& o) {
    const Material& m = o.material;
    return {{"center", toJson(o.center)},
            {"radius", o.radius},
            {"scale", toJson(o.scale)},
            {"subdivisions", o.subdivisions == kAutoSubdivisions ? Json("auto") : Json(o.subdivisions)},
            {"material",
             {{"ambient", toJson(m.ambient)},
              {"diffuse", toJson(m.diffuse)},
              {"specular", toJson(m.specular)},
              {"shininess", m.shininess}}}};
}

// Only the keys the light's type reads: the others are errors in a scene file.
Json toJson(const Light& l) {
    Json json = {{"type", toString(l.type)}, {"ambient", toJson(l.ambient)}};
    if (l.type == LightType::Ambient) return json;
    json["diffuse"] = toJson(l.diffuse);
    json["specular"] = toJson(l.specular);
    if (hasPosition(l.type)) {
        json["position"] = toJson(l.position);
        json["attenuation"] = toJson(l.attenuation);
    }
    if (hasDirection(l.type)) json["direction"] = toJson(l.direction);
    if (l.type == LightType::Spot) {
        json["cutoff_deg"] = l.cutoffDeg;
        json["exponent"] = l.exponent;
    }
    return json;
}

} // namespace

std::string sceneToJson(const Scene& scene) {
    Json objects = Json::array(), lights = Json::array();
    for (const SceneObject& o : scene.objects) objects.push_back(toJson(o));
    for (const Light& l : scene.lights) lights.push_back(toJson(l));
    Json root = {
        {"image",
         {{"width", scene.width}, {"height", scene.height}, {"background", toJson(scene.background)}}},
        {"camera", {{"eye", toJson(scene.eye)}, {"target", toJson(scene.target)}, {"up", toJson(scene.up)}}},
        {"projection", toJson(scene.projection)},
        {"shading", toString(scene.shading)},
        {"lighting", toString(scene.lighting)},
        {"toon_bands", scene.toonBands},
        {"tolerance_px", scene.tolerancePx},
        {"depth", toString(scene.depth)},
        {"vertex_normals", toString(scene.vertexNormals)},
        {"overlay", toString(scene.overlay)},
        {"view", toString(scene.view)},
        {"objects", objects},
        {"lights", lights}};
    if (scene.view.at) root["view_at"] = *scene.view.at;
    return root.dump(2) + "\n";
}

void saveScene(const Scene& scene, const std::filesystem::path& path) {
    const std::string text = sceneToJson(scene);
    writeFileAtomically(path, "scene", [&](std::FILE* file) {
        if (std::fwrite(text.data(), 1, text.size(), file) != text.size())
            failWrite("scene", path, std::generic_category().message(errno));
    });
}

Scene loadScene(const std::filesystem::path& path) {
    return parseScene(readFile(path), path.string());
}

void validateScene(const Scene& scene) {
    validateSceneValues(scene);
    checkSceneLimits(scene);
}

void validateSceneValues(const Scene& scene) {
    checkImage(scene);
    checkIntRange(scene.toonBands, kToonBandRange, "toon_bands");
    checkFinite(scene.tolerancePx, "tolerance_px");
    checkGreater(scene.tolerancePx, 0, "tolerance_px");
    checkCamera(scene);
    checkProjection(scene.projection);
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        checkObject(scene.objects[i], indexPath("objects", i));
    checkLightCount(scene.lights.size());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) checkLight(scene.lights[i], indexPath("lights", i));
    if (scene.view.at) checkViewAt(*scene.view.at);
    (void)sceneView(scene); // the derived matrices must be finite too
    checkObjectCount(scene.objects.size());
}

void checkSceneLimits(const Scene& scene) {
    checkWork(scene);
    checkStandardDepthRange(scene);
}

SceneView sceneView(const Scene& scene) {
    checkImageSize(scene);
    checkProjection(scene.projection);
    SceneView view;
    try {
        view.viewFromWorld = viewFromWorld(cameraFrame(scene.eye, scene.target, scene.up));
    } catch (const InputError& e) {
        failWithin("camera", e);
    }
    const Projection& p = scene.projection;
    view.orthographic = p.type == ProjectionType::Orthographic;
    try {
        if (p.type == ProjectionType::Perspective) {
            double aspect = static_cast<double>(scene.width) / scene.height;
            view.volume = viewVolumeFromFovy(p.fovyDeg, aspect, p.near, p.far);
        } else {
            view.volume = ViewVolume{p.left, p.right, p.bottom, p.top, p.near, p.far};
        }
        validateViewVolume(view.volume);
    } catch (const InputError& e) {
        failWithin("projection", e);
    }
    view.depth = scene.depth;
    // Valid planes can still be too close together or too large for double (left 0, right 1e-320;
    // near 1e200): the matrices must come out finite, or the projection is an input error.
    auto finiteMatrix = [](const glm::dmat4& m) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r])) return false;
        return true;
    };
    if (scene.depth == DepthMode::Standard)
        view.clipFromView =
            view.orthographic ? orthographicClipFromView(view.volume) : perspectiveClipFromView(view.volume);
    else
        view.clipFromView =
            view.orthographic
                ? reversedOrthographicClipFromView(view.volume)
                : reversedPerspectiveClipFromView(view.volume, scene.depth == DepthMode::ReversedInfinite);
    if (!finiteMatrix(view.clipFromView))
        fail("projection",
             "its planes give a non-finite projection matrix (left/right, bottom/top or near/far "
             "too close together or too large for double precision); choose a wider or smaller "
             "volume");
    if (!finiteMatrix(view.viewFromWorld))
        fail("camera", "eye and target give a non-finite view matrix; move them closer to the origin");
    return view;
}

glm::dmat4 worldFromObject(const SceneObject& object) {
    return glm::scale(glm::translate(glm::dmat4(1), object.center), object.radius * object.scale);
}

std::vector<std::string> sceneWarnings(const Scene& scene) {
    std::vector<std::string> warnings;
    auto check = [&](const glm::dvec3& colour, const std::string& path) {
        if (std::max({colour.x, colour.y, colour.z}) > kSuspectColour)
            warnings.push_back(path + ": " + formatVec(colour) +
                               " has a component above 10; colours are linear 0..1 (0..255 values would need "
                               "dividing by 255)");
    };
    check(scene.background, "image.background");
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const std::string path = "objects[" + std::to_string(i) + "].material.";
        check(scene.objects[i].material.ambient, path + "ambient");
        check(scene.objects[i].material.diffuse, path + "diffuse");
        check(scene.objects[i].material.specular, path + "specular");
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const std::string path = "lights[" + std::to_string(i) + "].";
        check(scene.lights[i].ambient, path + "ambient");
        check(scene.lights[i].diffuse, path + "diffuse");
        check(scene.lights[i].specular, path + "specular");
    }
    return warnings;
}

} // namespace shadelab
