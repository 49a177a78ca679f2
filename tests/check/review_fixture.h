// What the review tests share: an ACTUAL and an EXPECTED folder in a fresh temporary folder, and small
// images to put in them.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "app/check/review.h"
#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"

namespace shadelab::app {

class ReviewFixture : public ::testing::Test {
protected:
    std::filesystem::path root, actual, expected;

    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root = std::filesystem::temp_directory_path() /
               ("shadelab-review-" + std::to_string(::getpid()) + "-" + info->name());
        std::filesystem::remove_all(root);
        actual = root / "actual";
        expected = root / "expected";
        std::filesystem::create_directories(actual);
        std::filesystem::create_directories(expected);
    }
    void TearDown() override { std::filesystem::remove_all(root); }

    // A w×h image of one grey level, opaque; `spot` > 0 sets pixel (1, 1) to that level instead.
    static Image grey(int w, int h, int level, int spot = -1) {
        Image image(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                std::uint8_t* p = image.pixel(x, y);
                const int v = (spot >= 0 && x == 1 && y == 1) ? spot : level;
                p[0] = p[1] = p[2] = std::uint8_t(v);
                p[3] = 255;
            }
        return image;
    }
    static void put(const std::filesystem::path& dir, const std::string& name, const Image& image) {
        writePng(image, dir / (name + ".png"));
    }
    static std::string bytesOf(const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    static void writeText(const std::filesystem::path& path, const std::string& text) {
        std::ofstream(path, std::ios::binary) << text;
    }
    ReviewOptions options() const {
        ReviewOptions o;
        o.actualDir = actual;
        o.expectedDir = expected;
        return o;
    }
    static const CaseResult& caseNamed(const ReviewReport& report, const std::string& name) {
        for (const CaseResult& c : report.cases)
            if (c.name == name) return c;
        ADD_FAILURE() << "no case " << name;
        static const CaseResult none;
        return none;
    }
};

} // namespace shadelab::app
