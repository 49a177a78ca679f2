// Wavefront OBJ with its MTL materials, read by Debian's tinyobjloader. tinyobjloader does not check what
// a user most often gets wrong, nor say where: a first pass over the text checks every number, index and
// mtllib name with its line number, so that the library reads only text already known to be sound.
#define TINYOBJLOADER_USE_DOUBLE // as model_libraries.cpp compiles it: coordinates read as written
#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <unordered_map>

#include "scene/model_internal.h"
#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab::detail {
namespace {

std::string lineField(std::size_t line) {
    return "line " + std::to_string(line);
}

// The line's words into `out` (one vector reused for every line: a large file has millions).
void words(std::string_view line, std::vector<std::string_view>& out) {
    out.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
}

// The line starting at `at`, and `at` moved past its end. Lines end as tinyobjloader's safeGetline ends
// them: "\n", "\r\n" or a lone "\r" (old Mac files), so that the check and the library read the same lines.
std::string_view nextLine(std::string_view text, std::size_t& at) {
    std::size_t end = at; // a loop, not find_first_of, which calls memchr once per character
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    const std::string_view line = text.substr(at, end - at);
    at = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
    return line;
}

// The first pass: per line, "v"/"vn" numbers finite, "f" indices non-zero and in range (a negative index
// counts back from the vertices read so far), mtllib names inside the model's folder.
class ObjChecker {
public:
    ObjChecker(std::string_view name, SideFileReader reader, void* context)
        : name_(name), reader_(reader), context_(context) {}

    void check(std::string_view text) {
        // Positive indices may name a vertex given later in the file: count them all first.
        std::vector<std::string_view> w;
        for (std::size_t at = 0; at <= text.size();) {
            words(nextLine(text, at), w);
            if (!w.empty() && w[0] == "v") ++totalPositions_;
            if (!w.empty() && w[0] == "vn") ++totalNormals_;
        }
        std::size_t line = 1;
        for (std::size_t at = 0; at <= text.size(); ++line) {
            words(nextLine(text, at), w);
            checkLine(w, line);
        }
    }
    // MTL text by name, read while checking, for the library's material reader.
    std::map<std::string, std::string> materials;

private:
    [[noreturn]] void fail(std::size_t line, const std::string& what) const {
        throw InputError(printable(name_) + ": " + lineField(line) + ": " + what);
    }

    void checkNumbers(const std::vector<std::string_view>& w, std::size_t line, std::size_t needed) {
        if (w.size() < needed + 1)
            fail(line, quotedValue(w[0]) + " needs " + std::to_string(needed) + " numbers, got " +
                           std::to_string(w.size() - 1));
        for (std::size_t k = 1; k <= needed; ++k) {
            const std::string word(w[k]);
            char* end = nullptr;
            const double value = std::strtod(word.c_str(), &end);
            if (end == word.c_str() || *end != '\0') fail(line, quotedValue(w[k]) + " is not a number");
            if (!std::isfinite(value)) fail(line, quotedValue(w[k]) + " is not a finite number");
        }
    }

    // `what`: "vertex" or "normal", whose plural `whats` names the count.
    void checkIndex(std::string_view text, std::size_t line, std::size_t soFar, std::size_t total,
                    const char* what, const char* whats) const {
        long long index = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
        if (error != std::errc() || end != text.data() + text.size())
            fail(line, "the " + std::string(what) + " index " + quotedValue(text) + " is not a whole number");
        const bool inRange =
            index > 0 ? std::size_t(index) <= total : index < 0 && std::size_t(-(index + 1)) < soFar;
        if (!inRange)
            fail(line, "the " + std::string(what) + " index " + std::string(text) + " is out of range (" +
                           std::to_string(index > 0 ? total : soFar) + " " + whats +
                           (index > 0 ? " in the file" : " before this line") +
                           "; OBJ indices start at 1, negative ones count back)");
    }

    void checkLine(const std::vector<std::string_view>& w, std::size_t line) {
        if (w.empty() || w[0].front() == '#') return;
        if (w[0] == "v") {
            checkNumbers(w, line, 3);
            ++positions_;
        } else if (w[0] == "vn") {
            checkNumbers(w, line, 3);
            ++normals_;
        } else if (w[0] == "f") {
            if (w.size() < 4)
                fail(line, "a face needs at least 3 corners, got " + std::to_string(w.size() - 1));
            for (std::size_t k = 1; k < w.size(); ++k) {
                const std::string_view corner = w[k];
                const std::size_t slash = corner.find('/');
                checkIndex(corner.substr(0, slash), line, positions_, totalPositions_, "vertex", "vertices");
                if (slash == std::string_view::npos) continue;
                // tinyobjloader reads the number after a '/' with atoi, which skips blanks: an empty index
                // at a corner's end ("1//", "1/2/", "1/") would be read from the next corner.
                if (corner.back() == '/')
                    fail(line, "the corner " + quotedValue(corner) +
                                   " ends with '/': give the index after it, or leave the '/' out");
                const std::size_t second = corner.find('/', slash + 1);
                if (second != std::string_view::npos)
                    checkIndex(corner.substr(second + 1), line, normals_, totalNormals_, "normal", "normals");
            }
        } else if (w[0] == "mtllib") {
            for (std::size_t k = 1; k < w.size(); ++k) {
                const std::string file(w[k]);
                if (!materials.count(file))
                    materials[file] = readSideFile(reader_, context_, file, name_, lineField(line));
            }
        }
    }

    std::string_view name_;
    SideFileReader reader_;
    void* context_;
    std::size_t positions_ = 0, normals_ = 0, totalPositions_ = 0, totalNormals_ = 0;
};

// The library asks for each mtllib by name: the text the checker read.
class CheckedMaterials : public tinyobj::MaterialReader {
public:
    explicit CheckedMaterials(const std::map<std::string, std::string>& texts) : texts_(texts) {}
    bool operator()(const std::string& file, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* byName, std::string* warn, std::string* err) override {
        const auto found = texts_.find(file);
        if (found == texts_.end()) return false;
        std::istringstream in(found->second);
        tinyobj::LoadMtl(byName, materials, &in, warn, err);
        return true;
    }

private:
    const std::map<std::string, std::string>& texts_;
};

// The text as a stream without a copy (an istringstream copies it twice: a 77 MB OBJ would be held three
// times). tinyobjloader only reads from it, so the const_cast never writes.
class ViewBuffer : public std::streambuf {
public:
    explicit ViewBuffer(std::string_view text) {
        char* begin = const_cast<char*>(text.data());
        setg(begin, begin, begin + text.size());
    }
};

glm::dvec3 colour(const tinyobj::real_t (&c)[3]) {
    return {c[0], c[1], c[2]};
}

} // namespace

Model parseObj(std::string_view text, std::string_view name, SideFileReader sideFile, void* context) {
    ObjChecker checker(name, sideFile, context);
    checker.check(text);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    ViewBuffer buffer(text);
    std::istream in(&buffer);
    CheckedMaterials reader(checker.materials);
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &reader, true, false))
        throw InputError(printable(name) + ": " + printable(err.empty() ? "not an OBJ file" : err));

    RawMesh raw;
    // Every corner with a normal: the file's normals, a vertex per (position, normal) pair; otherwise the
    // positions as shared vertices and normals made from the faces.
    bool fileNormals = true;
    for (const tinyobj::shape_t& shape : shapes)
        for (const tinyobj::index_t& corner : shape.mesh.indices)
            fileNormals = fileNormals && corner.normal_index >= 0;
    std::unordered_map<std::uint64_t, std::uint32_t> vertexOf;
    auto vertex = [&](const tinyobj::index_t& corner) {
        const auto position = std::uint64_t(corner.vertex_index);
        const std::uint64_t key =
            fileNormals ? (position << 32) | std::uint32_t(corner.normal_index) : position;
        const auto [slot, added] = vertexOf.emplace(key, std::uint32_t(raw.positions.size()));
        if (added) {
            const auto p = 3 * std::size_t(corner.vertex_index);
            raw.positions.emplace_back(attrib.vertices[p], attrib.vertices[p + 1], attrib.vertices[p + 2]);
            if (fileNormals) {
                const auto n = 3 * std::size_t(corner.normal_index);
                raw.normals.emplace_back(attrib.normals[n], attrib.normals[n + 1], attrib.normals[n + 2]);
            }
        }
        return slot->second;
    };
    for (const tinyobj::shape_t& shape : shapes) {
        const std::vector<tinyobj::index_t>& corners = shape.mesh.indices;
        for (std::size_t c = 0; c + 2 < corners.size(); c += 3) {
            // One declaration, so the vertices are numbered in the corners' order whatever the compiler
            // (a function's arguments are evaluated in no set order: gcc and emscripten's clang differ).
            const glm::uint a = vertex(corners[c]), b = vertex(corners[c + 1]), d = vertex(corners[c + 2]);
            raw.triangles.emplace_back(a, b, d);
        }
    }
    if (!materials.empty()) {
        const tinyobj::material_t& m = materials.front();
        // Ns 0 is common in exported files and means "no highlight to speak of": the lowest shininess.
        raw.material = Material{colour(m.ambient), colour(m.diffuse), colour(m.specular),
                                std::max(1.0, double(m.shininess))};
    }
    return finishModel(std::move(raw), name);
}

} // namespace shadelab::detail
