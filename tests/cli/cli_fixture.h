// What the command line's end-to-end tests of render, compare and failures share (tests/cli/cli_*_test.cpp,
// built into the one executable cli_test): the fixture that runs the binary in a fresh temporary folder, a
// PNG's size read from its header, a scene that renders fast, and an image of one grey. In a named namespace:
// GoogleTest requires one fixture class for all of a suite's tests, whichever file holds them.
#pragma once

#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

#include "cli/run_process.h"
#include "shadelab/image/image.h"

namespace shadelab::cli_test {

namespace fs = std::filesystem;

struct PngSize {
    std::uint32_t width = 0, height = 0;
};

inline std::uint32_t bigEndian32(const std::string& bytes, std::size_t offset) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) value = value << 8 | std::uint8_t(bytes[offset + i]);
    return value;
}

// The signature and the IHDR chunk, which the PNG spec requires first: length 13 at 8, type at 12,
// width at 16, height at 20, all big-endian.
inline std::optional<PngSize> pngSize(const std::string& bytes) {
    static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
    if (bytes.size() < 24 || std::string_view(bytes).substr(0, 8) != kSignature) return std::nullopt;
    if (bigEndian32(bytes, 8) != 13 || bytes.compare(12, 4, "IHDR") != 0) return std::nullopt;
    return PngSize{bigEndian32(bytes, 16), bigEndian32(bytes, 20)};
}

// A scene that renders fast: 64×64, one low-level sphere, the default light.
inline std::string smallScene(std::string_view shading = "phong", std::string_view lighting = "blinn-phong",
                              int subdivisions = 3, int width = 64, int height = 64) {
    return R"({ "image": { "width": )" + std::to_string(width) + R"(, "height": )" + std::to_string(height) +
           R"( }, "shading": ")" + std::string(shading) + R"(", "lighting": ")" + std::string(lighting) +
           R"(", "objects": [ { "subdivisions": )" + std::to_string(subdivisions) + " } ] }\n";
}

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        dir_ = fs::temp_directory_path() /
               ("shadelab-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" + name);
        fs::remove_all(dir_);
        fs::create_directory(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }

    Outcome shadelab(const std::vector<std::string>& args, Display display = Display::Inherit) const {
        return runShadelab(args, dir_, display);
    }
    // Renders `args` and returns the PNG's bytes, failing the test if the run or the file is not right.
    std::string renderBytes(std::vector<std::string> args, const std::string& out) const {
        args.insert(args.end(), {"--out", out});
        const Outcome run = shadelab(args);
        EXPECT_EQ(run.exitCode, 0) << describe(run);
        const std::string bytes = readFile(dir_ / out);
        EXPECT_TRUE(pngSize(bytes)) << out << " is not a PNG\n" << describe(run);
        return bytes;
    }

    fs::path dir_;
};

inline shadelab::Image filled(int width, int height, std::uint8_t value) {
    shadelab::Image image(width, height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = i % 4 == 3 ? 255 : value;
    return image;
}

} // namespace shadelab::cli_test
