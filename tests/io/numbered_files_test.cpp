// Numbered outputs (shadelab/io/numbered_files.h), the demo's S: the first number at which every name is
// free, the contents in place, nothing planted in the folder opened or replaced, no temporary left.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "shadelab/errors.h"
#include "shadelab/io/numbered_files.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

std::set<std::string> listing(const fs::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
    return names;
}

class NumberedFilesTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("shadelab-numbered-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(NumberedFilesTest, TakesTheFirstNumberWhereEveryNameIsFreeAndOpensNothingThere) {
    // 001: the JSON's name is taken; 002: the PNG's is a link to a file outside, which must stay as it is;
    // 003: a FIFO, which must not block.
    std::ofstream(dir_ / "shadelab-001.json") << "mine";
    std::ofstream(dir_ / "outside.txt") << "keep";
    fs::create_symlink(dir_ / "outside.txt", dir_ / "shadelab-002.png");
    ASSERT_EQ(::mkfifo((dir_ / "shadelab-003.json").c_str(), 0600), 0);
    int last = 0;
    const std::string stem = writeNumberedFiles(dir_, "shadelab-", last, {{".json", "{}"}, {".png", "PNG"}});
    EXPECT_EQ(stem, (dir_ / "shadelab-004").string());
    EXPECT_EQ(last, 4);
    EXPECT_EQ(contents(dir_ / "shadelab-004.json"), "{}");
    EXPECT_EQ(contents(dir_ / "shadelab-004.png"), "PNG");
    EXPECT_EQ(contents(dir_ / "shadelab-001.json"), "mine");
    EXPECT_EQ(contents(dir_ / "outside.txt"), "keep");
    EXPECT_TRUE(fs::is_symlink(dir_ / "shadelab-002.png"));
    EXPECT_FALSE(fs::exists(dir_ / "shadelab-002.json")) << "a number given up leaves none of its names";
    // The next call starts after the last number, and nothing but the outputs is left.
    EXPECT_EQ(writeNumberedFiles(dir_, "shadelab-", last, {{".json", "b"}, {".png", "c"}}),
              (dir_ / "shadelab-005").string());
    EXPECT_EQ(listing(dir_),
              (std::set<std::string>{"outside.txt", "shadelab-001.json", "shadelab-002.png",
                                     "shadelab-003.json", "shadelab-004.json", "shadelab-004.png",
                                     "shadelab-005.json", "shadelab-005.png"}));
}

TEST_F(NumberedFilesTest, AFolderThatCannotTakeThemIsARuntimeErrorAndLeavesNothing) {
    int last = 0;
    try {
        (void)writeNumberedFiles(dir_ / "missing", "shadelab-", last, {{".json", "{}"}});
        FAIL() << "a missing folder was accepted";
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot create a file in"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(listing(dir_).empty());
}

} // namespace
} // namespace shadelab
