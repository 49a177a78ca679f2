// The docs hold what they promise: every "DESIGN §N" cited in the README, the code, the shaders, the page
// and the scripts names a section of docs/DESIGN.md, which the repository carries; the README links it.
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
const fs::path kRoot = fs::path(SHADELAB_TEST_DATA) / "..";

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::set<int> designSections() {
    const std::string design = readText(kRoot / "docs" / "DESIGN.md");
    std::set<int> sections;
    static const std::regex kHeading(R"((^|\n)## ([0-9]+)\. )");
    for (std::sregex_iterator it(design.begin(), design.end(), kHeading), end; it != end; ++it)
        sections.insert(std::stoi((*it)[2]));
    return sections;
}

TEST(Docs, EveryDesignCitationNamesASectionOfDocsDesign) {
    const std::set<int> sections = designSections();
    ASSERT_GE(sections.size(), 7u) << "docs/DESIGN.md is missing or lost its numbered sections";
    std::vector<fs::path> files = {kRoot / "README.md"};
    for (const char* folder : {"src", "include", "shaders", "web", "scripts", "tests"})
        for (const auto& entry : fs::recursive_directory_iterator(kRoot / folder))
            if (entry.is_regular_file()) files.push_back(entry.path());
    static const std::regex kCitation(R"(DESIGN §([0-9]+))");
    int citations = 0;
    for (const fs::path& file : files) {
        const std::string text = readText(file);
        for (std::sregex_iterator it(text.begin(), text.end(), kCitation), end; it != end; ++it) {
            ++citations;
            EXPECT_TRUE(sections.count(std::stoi((*it)[1])))
                << file.lexically_relative(kRoot) << " cites " << it->str() << ", which docs/DESIGN.md lacks";
        }
    }
    EXPECT_GT(citations, 20) << "the citations were not found: is the source tree where the test looks?";
}

TEST(Docs, ReadmeLinksTheDesignNotesAndNoSeed) {
    const std::string readme = readText(kRoot / "README.md");
    EXPECT_NE(readme.find("](docs/DESIGN.md)"), std::string::npos);
    EXPECT_EQ(readme.find("the seed"), std::string::npos) << "a reference to a file the repository lacks";
    for (const char* image : {"docs/showcase.png", "docs/demo-window.png", "docs/web-page.png"}) {
        EXPECT_NE(readme.find(image), std::string::npos) << image;
        EXPECT_TRUE(fs::exists(kRoot / image)) << image;
    }
}

} // namespace
