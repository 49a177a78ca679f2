// Hostile input end to end, beyond what cli_failures_test.cpp covers: malformed and binary scene
// files, wrong types, deep nesting, huge files and arrays, NaN/Inf literals, unknown keys, out-of-range
// enums, paths that do not exist, are directories or cannot be written, and a GL driver taken away at run
// time. Each case states its exit code (2: bad input, 1: run-time failure), what stderr must name (the
// field or argument, the value, the fix) and that no output or temporary file is left behind.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/run_process.h"

namespace {

namespace fs = std::filesystem;
using namespace shadelab::cli_test;

// A message of shadelab's longer than this floods the terminal: user text must come back truncated.
constexpr std::size_t kMaxMessageBytes = 1000;

// The longest line of `err` that shadelab wrote (Mesa's warnings and sanitizer reports are not its own).
std::size_t longestOwnLine(const std::string& err) {
    std::size_t longest = 0, start = 0;
    while (start < err.size()) {
        std::size_t end = err.find('\n', start);
        if (end == std::string::npos) end = err.size();
        if (err.compare(start, 8, "shadelab") == 0) longest = std::max(longest, end - start);
        start = end + 1;
    }
    return longest;
}

std::string repeat(std::string_view piece, std::size_t times) {
    std::string out;
    out.reserve(piece.size() * times);
    for (std::size_t i = 0; i < times; ++i) out += piece;
    return out;
}

// What a case puts in its folder before the run.
using Prepare = std::function<void(const fs::path& dir)>;

Prepare scene(std::string text) {
    return [text = std::move(text)](const fs::path& dir) { writeFile(dir / "scene.json", text); };
}
Prepare sceneFrom(std::function<std::string()> make) {
    return [make = std::move(make)](const fs::path& dir) { writeFile(dir / "scene.json", make()); };
}
Prepare folder(const char* name) {
    return [name](const fs::path& dir) { fs::create_directory(dir / name); };
}
Prepare file(const char* name) {
    return [name](const fs::path& dir) { writeFile(dir / name, "not a folder\n"); };
}

// The bytes of an earlier run that a failed run must leave as they are.
constexpr std::string_view kPrecious = "not a PNG: the bytes of an earlier run that must survive a failure\n";

struct HostileCase {
    const char* name;
    std::vector<std::string> args;
    int exitCode;                      // 2: bad input, 1: a run-time failure
    std::vector<std::string> mentions; // substrings stderr must contain
    Prepare prepare = nullptr;
    std::vector<std::string> environment = {}; // NAME=value for the child, replacing inherited values
    Display display = Display::Inherit;
    bool preciousOut = false; // out.png exists before the run and must be unchanged after it
};

std::ostream& operator<<(std::ostream& out, const HostileCase& c) {
    return out << c.name;
}

// The scene is read and rejected before any GL context exists, so `reference` (CPU only) and `render`
// behave alike; the cases use `render` where the context matters and `reference` elsewhere.
std::vector<std::string> referenceScene() {
    return {"reference", "scene.json", "--size", "8x8", "--out", "out.png"};
}

const std::string kLongName(300, 'x'); // longer than NAME_MAX (255): stat() fails with ENAMETOOLONG

// Environments in which Mesa's EGL cannot give a context, each failing at a different step.
const std::vector<std::string> kNoEglVendor = {"__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json"};
const std::vector<std::string> kNoDriEngine = {"LIBGL_DRIVERS_PATH=/nonexistent"};
const std::vector<std::string> kNoGl33 = {"MESA_GL_VERSION_OVERRIDE=2.1"};

const HostileCase kCases[] = {
    // ---- malformed JSON: the byte where it went wrong ----
    {.name = "json_empty_file",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "invalid JSON at byte 1", "unexpected end of input"},
     .prepare = scene("")},
    {.name = "json_two_documents",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "invalid JSON at byte 4", "expected end of input"},
     .prepare = scene("{} {}")},
    {.name = "json_is_a_png",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "invalid JSON at byte 1"},
     .prepare = scene(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16))},
    {.name = "json_ill_formed_utf8",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "invalid JSON at byte 14", "UTF-8"},
     .prepare = scene("{\"shading\": \"\xff\"}")},
    {.name = "json_comment",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "invalid JSON at byte 3"},
     .prepare = scene("{ // a comment\n}")},
    {.name = "json_duplicate_key",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json: shading: duplicate key"},
     .prepare = scene(R"({"shading": "flat", "shading": "phong"})")},

    // ---- wrong types ----
    {.name = "type_top_level_array",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"the top level: must be an object, got array"},
     .prepare = scene("[]")},
    {.name = "type_objects_is_object",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"objects: must be an array, got object"},
     .prepare = scene(R"({"objects": {}})")},
    {.name = "type_vector_of_two",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"camera.eye: must be an array of 3 numbers, got array of 2 elements"},
     .prepare = scene(R"({"camera": {"eye": [0, 0]}})")},
    {.name = "type_number_as_string",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"image.width: must be a number, got string \"512\""},
     .prepare = scene(R"({"image": {"width": "512"}})")},
    {.name = "type_nan_as_string",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"objects[0].radius: must be a number, got string \"NaN\""},
     .prepare = scene(R"({"objects": [{"radius": "NaN"}]})")},

    // ---- deep nesting: refused by a bracket count before any tree is built ----
    {.name = "nesting_100000_arrays",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "nested deeper than 64 levels"},
     .prepare =
         sceneFrom([] { return R"({"objects": )" + repeat("[", 100'000) + repeat("]", 100'000) + "}"; })},
    {.name = "nesting_100000_objects",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "nested deeper than 64 levels"},
     .prepare = sceneFrom([] { return repeat(R"({"a": )", 100'000) + "1" + repeat("}", 100'000); })},

    // ---- huge files and arrays ----
    {.name = "file_of_50_mb",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "larger than 16 MiB", "not a scene file"},
     .prepare =
         sceneFrom([] { return R"({"image": {"background": [0)" + repeat(",0", 25'000'000) + "]}}"; })},
    {.name = "array_of_a_million_numbers",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"image.background: must be an array of 3 numbers, got array of 1000000 elements"},
     .prepare =
         sceneFrom([] { return R"({"image": {"background": [0.5)" + repeat(",0.5", 999'999) + "]}}"; })},
    {.name = "array_of_a_million_lights",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"lights: at most 8 lights are supported, got 1000000"},
     .prepare = sceneFrom([] { return R"({"lights": [{})" + repeat(",{}", 999'999) + "]}"; })},
    {.name = "string_of_10_mb",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"shading: unknown value \"xxxx", "...\"; expected one of flat, gouraud, phong, toon"},
     .prepare = sceneFrom([] { return R"({"shading": ")" + std::string(10'000'000, 'x') + "\"}"; })},

    // ---- NaN and Inf: JSON has no such literals, and overflowing numbers are not finite ----
    // NaN and Infinity are syntax errors to the JSON parser; the message must still say which field and
    // that a finite number is wanted.
    {.name = "literal_nan",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "objects[0].radius", "NaN", "finite"},
     .prepare = scene(R"({"objects": [{"radius": NaN}]})")},
    {.name = "literal_infinity",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "objects[0].radius", "Infinity", "finite"},
     .prepare = scene(R"({"objects": [{"radius": Infinity}]})")},
    {.name = "literal_minus_infinity",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "camera.eye[1]", "Infinity", "finite"},
     .prepare = scene(R"({"camera": {"eye": [0, -Infinity, 4]}})")},
    {.name = "number_1e400",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json: camera.eye[1]: must be finite, got 1e400"},
     .prepare = scene(R"({"camera": {"eye": [0, 1e400, 4]}})")},
    {.name = "number_minus_1e400",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json: lights[0].position[2]: must be finite, got -1e400"},
     .prepare = scene(R"({"lights": [{"type": "point", "position": [0, 0, -1e400]}]})")},
    {.name = "number_of_5_million_digits",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"objects[0].radius: must be finite"},
     .prepare =
         sceneFrom([] { return R"({"objects": [{"radius": 1)" + std::string(5'000'000, '0') + "}]}"; })},

    // ---- unknown keys: named, with the keys that would be accepted ----
    {.name = "key_wrong_case",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"Shading: unknown key; expected one of image, camera"},
     .prepare = scene(R"({"Shading": "phong"})")},
    {.name = "key_of_another_light_type",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"lights[0].cutoff_deg: does not apply to a point light; expected one of type, position"},
     .prepare = scene(R"({"lights": [{"type": "point", "position": [0, 0, 0], "cutoff_deg": 30}]})")},
    {.name = "key_of_5000_characters",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"unknown key; expected one of image, camera"},
     .prepare = sceneFrom([] { return "{\"" + std::string(5000, 'k') + "\": 1}"; })},

    // ---- out-of-range enums and levels ----
    {.name = "enum_shading_upper_case",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"shading: unknown value \"PHONG\"; expected one of flat, gouraud, phong, toon"},
     .prepare = scene(R"({"shading": "PHONG"})")},
    {.name = "enum_projection_type",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"projection.type: unknown value \"fisheye\"; expected one of perspective, frustum, "
                  "orthographic"},
     .prepare = scene(R"({"projection": {"type": "fisheye"}})")},
    {.name = "enum_light_type",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions =
         {"lights[0].type: unknown value \"laser\"; expected one of ambient, directional, point, spot"},
     .prepare = scene(R"({"lights": [{"type": "laser"}]})")},
    {.name = "enum_depth",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"depth: unknown value \"inverted\"; expected one of standard, reversed, reversed-infinite"},
     .prepare = scene(R"({"depth": "inverted"})")},
    {.name = "enum_subdivisions_upper_case_auto",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"objects[0].subdivisions: must be a level 0..10 or \"auto\", got string \"AUTO\""},
     .prepare = scene(R"({"objects": [{"subdivisions": "AUTO"}]})")},
    {.name = "range_toon_bands",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"toon_bands: must be between 2 and 16, got 17"},
     .prepare = scene(R"({"toon_bands": 17})")},
    {.name = "range_spot_cutoff",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"lights[0].cutoff_deg: must be <= 90, got 90.0000001"},
     .prepare = scene(R"({"lights": [{"type": "spot", "position": [0, 0, 0], "direction": [0, 0, -1], )"
                      R"("cutoff_deg": 90.0000001}]})")},
    {.name = "flag_depth_bogus",
     .args = {"render", "--depth", "inverted", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--depth", "inverted"}},
    {.name = "flag_specialize_bogus",
     .args = {"render", "--specialize", "maybe", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--specialize", "maybe", "on,off"}},
    {.name = "flag_tolerance_nan",
     .args = {"render", "--tolerance-px", "nan", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--tolerance-px", "positive decimal number of pixels", "nan"}},
    {.name = "flag_tolerance_1e400",
     .args = {"render", "--tolerance-px", "1e400", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--tolerance-px: must be finite, got 1e400"}},
    {.name = "flag_tolerance_empty",
     .args = {"render", "--tolerance-px", "", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--tolerance-px", "positive decimal number", "got \"\""}},
    {.name = "flag_tolerance_hex",
     .args = {"render", "--tolerance-px", "0x10", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--tolerance-px", "positive decimal number", "0x10"}},
    {.name = "flag_subdivisions_huge_names_a_finite_figure",
     .args = {"render", "--subdivisions", "999999999", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--subdivisions", "level 999999999 would need about 2^", "maximum supported level is 10"}},
    {.name = "flag_size_beyond_int",
     .args = {"render", "--size", "99999999999x1", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--size", "99999999999x1", "1..16384"}},
    {.name = "flag_subdivisions_beyond_int",
     .args = {"render", "--subdivisions", "99999999999", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--subdivisions", "99999999999", "0..10 or auto"}},
    {.name = "flag_given_twice",
     .args = {"render", "--size", "8x8", "--out", "a.png", "--out", "b.png"},
     .exitCode = 2,
     .mentions = {"--out", "Run with --help"}},
    {.name = "bench_frames_below_range",
     .args = {"bench", "--frames", "0"},
     .exitCode = 2,
     .mentions = {"--frames", "0", "3 to 100000"}},
    {.name = "bench_backend_bogus",
     .args = {"bench", "--backend", "vulkan"},
     .exitCode = 2,
     .mentions = {"--backend", "vulkan", "expected one of egl, osmesa"}},
    // An invalid regular expression is bad input, found before any benchmark runs.
    {.name = "bench_filter_not_a_regex",
     .args = {"bench", "--filter", "(", "--size", "8x8", "--frames", "3", "--warmup", "0"},
     .exitCode = 2,
     .mentions = {"--filter", "("}},
    // Long arguments reach no recursive std::regex: 50,000 digits and 20,000 nested groups crashed it
    // (SIGSEGV) instead of being refused.
    {.name = "flag_tolerance_fifty_thousand_digits",
     .args = {"render", "--tolerance-px", std::string(50000, '9'), "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--tolerance-px: must be finite"}},
    {.name = "flag_tolerance_fifty_thousand_digits_then_junk",
     .args = {"render", "--tolerance-px", std::string(50000, '1') + "x", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"--tolerance-px", "positive decimal number"}},
    {.name = "bench_filter_twenty_thousand_nested_groups",
     .args = {"bench", "--filter", std::string(20000, '(') + std::string(20000, ')'), "--size", "8x8"},
     .exitCode = 2,
     .mentions = {"--filter", "at most 1000 characters"}},
    {.name = "bench_filter_nested_deeper_than_the_bound",
     .args = {"bench", "--filter", std::string(400, '(') + "a" + std::string(400, ')'), "--size", "8x8"},
     .exitCode = 2,
     .mentions = {"--filter", "nested at most 32 deep"}},
    // A mistyped subcommand too long to be a file name is still bad input, not a run-time error.
    {.name = "mistyped_subcommand_longer_than_a_file_name",
     .args = {kLongName, "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"is neither a subcommand"},
     .display = Display::None},

    // ---- paths that do not exist, are directories, or cannot be written ----
    {.name = "scene_dangling_symlink",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json: cannot read scene file: No such file or directory"},
     .prepare = [](const fs::path& dir) { fs::create_symlink("nowhere.json", dir / "scene.json"); }},
    {.name = "scene_under_a_file",
     .args = {"reference", "f/scene.json", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"f/scene.json: cannot read scene file"},
     .prepare = file("f")},
    {.name = "scene_name_too_long",
     .args = {"reference", kLongName + ".json", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"cannot read scene file: File name too long"}},
    {.name = "scene_is_dev_zero",
     .args = {"reference", "/dev/zero", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"/dev/zero: cannot read scene file: it is not a regular file"}},
    {.name = "out_under_a_file",
     .args = {"render", "--size", "8x8", "--out", "f/out.png"},
     .exitCode = 2,
     .mentions = {"--out", "\"f\""},
     .prepare = file("f")},
    {.name = "showcase_out_is_directory",
     .args = {"--showcase-out", "s.png"},
     .exitCode = 2,
     .mentions = {"--showcase-out", "s.png", "is a directory"},
     .prepare = folder("s.png"),
     .display = Display::None},
    {.name = "screenshot_dir_missing",
     .args = {"--screenshot-dir", "no-such-folder", "--showcase-out", "s.png"},
     .exitCode = 2,
     .mentions = {"--screenshot-dir", "no-such-folder", "does not exist", "mkdir -p"},
     .display = Display::None},
    {.name = "screenshot_dir_is_a_file",
     .args = {"--screenshot-dir", "f", "--showcase-out", "s.png"},
     .exitCode = 2,
     .mentions = {"--screenshot-dir", "f"},
     .prepare = file("f"),
     .display = Display::None},
    {.name = "bench_json_folder_missing",
     .args = {"bench", "--json", "no-such-folder/b.json"},
     .exitCode = 2,
     .mentions = {"--json", "no-such-folder"}},
    {.name = "bench_json_is_directory",
     .args = {"bench", "--json", "b.json"},
     .exitCode = 2,
     .mentions = {"--json", "b.json", "is a directory"},
     .prepare = folder("b.json")},
    // Run-time failures (exit 1): the arguments are fine, writing is what fails.
    {.name = "reference_out_in_proc",
     .args = {"reference", "--size", "8x8", "--out", "/proc/shadelab-hostile-test.png"},
     .exitCode = 1,
     .mentions = {"cannot write PNG", "/proc/shadelab-hostile-test.png"}},
    {.name = "out_name_too_long",
     .args = {"reference", "--size", "8x8", "--out", kLongName + ".png"},
     .exitCode = 2,
     .mentions = {"--out", "File name too long"}},

    // ---- no GL at run time: exit 1, the backend named, the earlier output kept ----
    // glvnd finds no vendor library: Mesa's EGL is not there at all.
    {.name = "egl_without_vendor_library",
     .args = {"render", "--size", "8x8", "--out", "out.png"},
     .exitCode = 1,
     .mentions = {"egl:", "EGL_MESA_platform_surfaceless", "libegl-mesa0"},
     .environment = kNoEglVendor,
     .preciousOut = true},
    // The brief's combination: the vendor library is what fails first.
    {.name = "egl_surfaceless_without_any_driver",
     .args = {"render", "--size", "8x8", "--out", "out.png"},
     .exitCode = 1,
     .mentions = {"egl:"},
     .environment = {"EGL_PLATFORM=surfaceless", "LIBGL_DRIVERS_PATH=/nonexistent",
                     "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json"},
     .preciousOut = true},
    // Mesa's EGL is there but its DRI driver (swrast_dri.so) is not. (GALLIUM_DRIVER=nonexistent fails at
    // the same step, but Mesa leaks from a driver it has already unloaded, which LeakSanitizer cannot
    // attribute to a library to suppress.)
    {.name = "egl_without_dri_driver",
     .args = {"render", "--size", "8x8", "--out", "out.png"},
     .exitCode = 1,
     .mentions = {"egl: ", "surfaceless platform: eglInitialize failed", "libgl1-mesa-dri"},
     .environment = kNoDriEngine,
     .preciousOut = true},
    // A driver that offers less than OpenGL 3.3 core.
    {.name = "egl_without_gl33",
     .args = {"render", "--size", "8x8", "--out", "out.png"},
     .exitCode = 1,
     .mentions = {"egl: ", "surfaceless platform: eglCreateContext (OpenGL 3.3 core) failed"},
     .environment = kNoGl33,
     .preciousOut = true},
    {.name = "demo_showcase_without_egl",
     .args = {"--showcase-out", "s.png"},
     .exitCode = 1,
     .mentions = {"egl:"},
     .environment = kNoEglVendor,
     .display = Display::None},
    {.name = "bench_without_egl",
     .args = {"bench", "--size", "8x8", "--frames", "3", "--warmup", "0"},
     .exitCode = 1,
     .mentions = {"egl:"},
     .environment = kNoEglVendor},
    {.name = "osmesa_without_gl33",
     .args = {"render", "--backend", "osmesa", "--size", "8x8", "--out", "out.png"},
     .exitCode = 1,
     .mentions = {"osmesa: OSMesaCreateContextAttribs (OpenGL 3.3 core) failed"},
     .environment = kNoGl33,
     .preciousOut = true},
    // Mesa 22's OSMesa dereferences a null screen when GALLIUM_DRIVER names a driver it lacks; shadelab
    // must refuse before calling it.
    {.name = "osmesa_with_unknown_gallium_driver",
     .args = {"render", "--backend", "osmesa", "--size", "8x8", "--out", "out.png"},
     .exitCode = 1,
     .mentions = {"osmesa", "GALLIUM_DRIVER", "nonexistent"},
     .environment = {"GALLIUM_DRIVER=nonexistent"},
     .preciousOut = true},
    // The EGL backend names the variable too, instead of blaming the Mesa install.
    {.name = "egl_with_unknown_gallium_driver",
     .args = {"render", "--backend", "egl", "--size", "8x8", "--out", "out.png"},
     .exitCode = 1,
     .mentions = {"egl", "GALLIUM_DRIVER=nonexistent", "unset it"},
     // Mesa's failed screen creation leaks from a driver it has already unloaded (its frames cannot be
     // symbolized, so lsan.supp cannot name them): leak checking is off for this one child under ASan.
     .environment = {"GALLIUM_DRIVER=nonexistent", "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1"},
     .preciousOut = true},
    {.name = "egl_with_gl_version_override_2_1",
     .args = {"render", "--backend", "egl", "--size", "8x8", "--out", "out.png"},
     .exitCode = 1,
     .mentions = {"egl", "MESA_GL_VERSION_OVERRIDE=2.1", "unset it"},
     .environment = {"MESA_GL_VERSION_OVERRIDE=2.1"},
     .preciousOut = true},
    // Work bounded before it is spent (docs/ci-engineers.md "Limits"): objects, triangles per frame,
    // reference ray tests.
    {.name = "objects_over_the_limit",
     .args = {"render", "scene.json", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"scene.json", "objects", "at most 10000 objects", "got 200000"},
     .prepare = sceneFrom([] {
         std::string objects = repeat("{},", 200'000);
         objects.pop_back();
         return R"({"objects": [)" + objects + "]}";
     })},
    {.name = "triangles_over_the_limit",
     .args = {"render", "scene.json", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"scene.json", "objects", "71303168 triangles per frame", "at most 67108864"},
     .prepare = sceneFrom([] {
         std::string objects = repeat(R"({"subdivisions": 10},)", 17);
         objects.pop_back();
         return R"({"objects": [)" + objects + "]}";
     })},
    {.name = "reference_ray_tests_over_the_limit",
     .args = {"reference", "scene.json", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"scene.json", "objects", "4563402752 rays", "smaller image or fewer objects"},
     .prepare = sceneFrom([] {
         std::string objects = repeat(R"({"subdivisions": 0},)", 17);
         objects.pop_back();
         return R"({"image": {"width": 16384, "height": 16384}, "objects": [)" + objects + "]}";
     })},
    // Projections 32-bit float cannot carry: render and reference both drew nothing, exit 0.
    {.name = "perspective_near_1e_minus_300_far_1e300",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "projection.near", "between 1e-30 and 1e+30", "1e-300"},
     .prepare =
         scene(R"({"projection": {"type": "perspective", "fovy_deg": 40, "near": 1e-300, "far": 1e300}})")},
    {.name = "orthographic_window_1e_minus_300",
     .args = {"render", "scene.json", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"scene.json", "projection.left", "between 1e-30 and 1e+30"},
     .prepare = scene(R"({"projection": {"type": "orthographic", "left": -1e-300, "right": 1e-300,
                          "bottom": -1e-300, "top": 1e-300, "near": 1, "far": 10}})")},
    // The same for a frustum's window and an object's scale: render drew nothing where the reference drew
    // the picture (a window of 1e-40), exact shading drew nothing beside the reference's disc (scale 1e-20).
    {.name = "frustum_window_1e_minus_40",
     .args = {"render", "scene.json", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"scene.json", "projection.left", "between 1e-30 and 1e+30", "-1e-40"},
     .prepare = scene(R"({"projection": {"type": "frustum", "left": -1e-40, "right": 1e-40,
                          "bottom": -1e-40, "top": 1e-40, "near": 0.5, "far": 20}})")},
    {.name = "scale_1e_minus_20_under_exact_shading",
     .args = {"render", "scene.json", "--shading", "exact", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"scene.json", "objects[0].scale[2]", "1e-20", "bring the eye closer"},
     .prepare = scene(R"({"objects": [{"scale": [1, 1, 1e-20]}]})")},
    {.name = "scale_1e_minus_155_reference",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "objects[0].scale[2]", "1e-155", "between 1e-30 and 1e+30"},
     .prepare = scene(R"({"objects": [{"scale": [1, 1, 1e-155]}]})")},
    {.name = "standard_depth_with_near_1e_minus_7",
     .args = {"render", "scene.json", "--size", "8x8", "--out", "out.png"},
     .exitCode = 2,
     .mentions = {"scene.json", "projection.near", "objects[0]", "\"depth\": \"reversed\""},
     .prepare = scene(R"({"projection": {"type": "perspective", "fovy_deg": 40, "near": 1e-7, "far": 10}})")},
    // A value float cannot carry is refused naming the file and the field.
    {.name = "fovy_denormal",
     .args = referenceScene(),
     .exitCode = 2,
     .mentions = {"scene.json", "projection.fovy_deg", "at least 1e-06"},
     .prepare =
         scene(R"({"projection": {"type": "perspective", "fovy_deg": 4.9e-324, "near": 0.1, "far": 10}})")},
};

class HostileTest : public ::testing::TestWithParam<HostileCase> {
protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        std::string name = GetParam().name;
        dir_ = fs::temp_directory_path() / ("shadelab-hostile-" + std::to_string(::getpid()) + "-" +
                                            std::to_string(counter++) + "-" + name);
        fs::remove_all(dir_);
        fs::create_directory(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }

    fs::path dir_;
};

TEST_P(HostileTest, ExitCodeMessageAndNoFileLeft) {
    const HostileCase& c = GetParam();
    if (c.prepare) c.prepare(dir_);
    if (c.preciousOut) writeFile(dir_ / "out.png", kPrecious);
    const std::set<std::string> before = listing(dir_);
    const Outcome run = runShadelab(c.args, dir_, c.display, c.environment);
    if (run.err.find("without OSMesa") != std::string::npos)
        GTEST_SKIP() << "this shadelab was built without OSMesa: " << run.err;

    EXPECT_EQ(run.exitCode, c.exitCode) << describe(run).substr(0, 4000);
    for (const std::string& mention : c.mentions)
        EXPECT_NE(run.err.find(mention), std::string::npos) << "stderr does not mention " << mention << "\n"
                                                            << describe(run).substr(0, 4000);
    EXPECT_LE(longestOwnLine(run.err), kMaxMessageBytes) << "the message is not bounded: user text must be "
                                                            "truncated\n"
                                                         << run.err.substr(0, 2000);
    EXPECT_EQ(listing(dir_), before) << "a file was written or left behind";
    if (c.preciousOut) {
        EXPECT_EQ(readFile(dir_ / "out.png"), kPrecious) << "out.png was changed by a failure";
    }
    for (const std::string& arg : c.args) {
        if (arg.starts_with("/proc/")) {
            EXPECT_FALSE(fs::exists(arg)) << arg;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Table, HostileTest, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<HostileCase>& info) { return info.param.name; });

} // namespace
