// The docs hold what they promise. The README sells and starts (at most 200 lines, the two commands that
// .ci/run runs, a link to each reader's guide); every link of the README and the guides in docs/ resolves,
// to a file and to a heading; the key table the students' guide shows is the program's key bindings, row
// for row; every command the docs show names a script or subcommand that exists with flags that it takes
// (asked of `shadelab SUBCOMMAND --help`); every "DESIGN §N" names a section of docs/DESIGN.md.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h> // only for the GLFW_KEY_* constants: the key table names GLFW's keys
#include <gtest/gtest.h>

#include "app/demo/demo_state.h"

namespace {

namespace fs = std::filesystem;
const fs::path kRoot = fs::path(SHADELAB_TEST_DATA) / "..";

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) result.push_back(line);
    return result;
}

// The README and the readers' guides: every docs/*.md but DESIGN.md, which is the contracts, not a guide.
std::vector<fs::path> readerDocs() {
    std::vector<fs::path> docs = {kRoot / "README.md"};
    for (const auto& entry : fs::directory_iterator(kRoot / "docs"))
        if (entry.path().extension() == ".md" && entry.path().filename() != "DESIGN.md")
            docs.push_back(entry.path());
    return docs;
}

std::string shown(const fs::path& doc) {
    return doc.lexically_relative(kRoot).string();
}

// GitHub's anchor of a heading: lower case, spaces to '-', everything but letters, digits, '-' and '_'
// dropped (the non-ASCII symbols of this project's headings, such as −, are dropped too).
std::string anchorOf(const std::string& heading) {
    std::string anchor;
    for (const char c : heading) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) && u < 128)
            anchor += static_cast<char>(std::tolower(u));
        else if (c == ' ' || c == '-')
            anchor += '-';
        else if (c == '_')
            anchor += '_';
    }
    return anchor;
}

std::set<std::string> anchorsOf(const fs::path& markdown) {
    std::set<std::string> anchors;
    bool inCode = false;
    for (const std::string& line : lines(readText(markdown))) {
        if (line.rfind("```", 0) == 0) inCode = !inCode;
        if (inCode || line.empty() || line[0] != '#') continue;
        const std::size_t text = line.find_first_not_of('#');
        if (text != std::string::npos && line[text] == ' ') anchors.insert(anchorOf(line.substr(text + 1)));
    }
    return anchors;
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
    std::vector<fs::path> files = readerDocs();
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

// STYLE "Docs per reader": what it is, one picture, two commands, where each reader goes next.
TEST(Docs, ReadmeSellsAndStartsAndSendsEachReaderOn) {
    const std::string readme = readText(kRoot / "README.md");
    EXPECT_LE(lines(readme).size(), 200u) << "README.md: the guides in docs/ hold the rest";
    for (const char* guide : {"docs/students.md", "docs/lecturers.md", "docs/ci-engineers.md",
                              "docs/contributors.md", "docs/DESIGN.md"})
        EXPECT_NE(readme.find(std::string("](") + guide + ")"), std::string::npos)
            << "README.md does not link " << guide;
    static const std::regex kPicture(R"(!\[[^\]]*\]\(([^)]+)\))");
    const auto pictures =
        std::distance(std::sregex_iterator(readme.begin(), readme.end(), kPicture), std::sregex_iterator());
    EXPECT_EQ(pictures, 1) << "README.md shows one picture; the guides show the rest";
    EXPECT_NE(readme.find("](docs/showcase.png)"), std::string::npos);
    for (const fs::path& doc : readerDocs())
        EXPECT_EQ(readText(doc).find("the seed"), std::string::npos)
            << shown(doc) << ": a file the repository lacks";
}

// .ci/run runs exactly the README's test command, and the README's first commands are the two from a clone.
TEST(Docs, ReadmeTestCommandIsWhatCiRuns) {
    const std::vector<std::string> readme = lines(readText(kRoot / "README.md"));
    std::vector<std::string> firstBlock;
    for (std::size_t i = 0; i < readme.size(); ++i)
        if (readme[i] == "```sh") {
            for (std::size_t j = i + 1; j < readme.size() && readme[j] != "```"; ++j)
                firstBlock.push_back(readme[j]);
            break;
        }
    ASSERT_EQ(firstBlock.size(), 2u) << "README.md: its first sh block is the two commands";
    EXPECT_EQ(firstBlock[0].substr(0, firstBlock[0].find(' ')), "scripts/run.sh");
    const std::string testCommand = firstBlock[1].substr(0, firstBlock[1].find(' '));
    EXPECT_EQ(testCommand, "scripts/test.sh");
    const std::vector<std::string> ci = lines(readText(kRoot / ".ci" / "run"));
    EXPECT_NE(std::find(ci.begin(), ci.end(), testCommand), ci.end())
        << ".ci/run does not run " << testCommand;
}

TEST(Docs, EveryLinkOfTheReadmeAndTheGuidesResolves) {
    static const std::regex kLink(R"(\]\(([^)\s]+)\))");
    int links = 0;
    std::set<std::string> pictures;
    for (const fs::path& doc : readerDocs()) {
        const std::string text = readText(doc);
        for (std::sregex_iterator it(text.begin(), text.end(), kLink), end; it != end; ++it) {
            const std::string target = (*it)[1];
            if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0) continue;
            ++links;
            const std::size_t hash = target.find('#');
            const std::string file = target.substr(0, hash);
            const fs::path path = file.empty() ? doc : doc.parent_path() / file;
            if (!fs::exists(path)) {
                ADD_FAILURE() << shown(doc) << " links " << target << ", which does not exist";
                continue;
            }
            if (path.extension() == ".png") pictures.insert(fs::weakly_canonical(path).filename().string());
            if (hash != std::string::npos && path.extension() == ".md") {
                EXPECT_TRUE(anchorsOf(path).count(target.substr(hash + 1)))
                    << shown(doc) << " links " << target << ": no such heading in " << shown(path);
            }
        }
    }
    EXPECT_GT(links, 100) << "the links were not found: are the guides in docs/?";
    for (const char* picture : {"showcase.png", "demo-window.png", "web-page.png"})
        EXPECT_TRUE(pictures.count(picture)) << "no guide shows docs/" << picture;
}

// ---- the key table ----

// The GLFW key a key table's `name` means; 0 if it names none.
int glfwKeyNamed(const std::string& name) {
    static const std::map<std::string, int> kNamed = {
        {"+", GLFW_KEY_EQUAL}, // '+' is Shift + '=' (US layout); GLFW reports the key, '='
        {"-", GLFW_KEY_MINUS},
        {"PgDn", GLFW_KEY_PAGE_DOWN},
        {"PgUp", GLFW_KEY_PAGE_UP},
        {"Space", GLFW_KEY_SPACE},
        {"Backspace", GLFW_KEY_BACKSPACE},
        {"→", GLFW_KEY_RIGHT},
        {"←", GLFW_KEY_LEFT},
        {"Home", GLFW_KEY_HOME},
        {"End", GLFW_KEY_END},
        {"Esc", GLFW_KEY_ESCAPE},
        {"F1", GLFW_KEY_F1},
        {"F2", GLFW_KEY_F2},
        {"F11", GLFW_KEY_F11}};
    if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0])))
        return std::toupper(static_cast<unsigned char>(name[0])); // GLFW's printable keys: their ASCII code
    const auto named = kNamed.find(name);
    return named == kNamed.end() ? 0 : named->second;
}

// Every key named in a `| key | action |` table of `doc`, with the row that names it.
std::map<int, int> keyTable(const fs::path& doc, int& tables) {
    std::map<int, int> rowOfKey;
    const std::vector<std::string> text = lines(readText(doc));
    static const std::regex kKeyName("`([^`]+)`");
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i].rfind("| key | action |", 0) != 0) continue;
        ++tables;
        for (std::size_t row = i + 2; row < text.size() && text[row].rfind("|", 0) == 0; ++row) {
            const std::string keys = text[row].substr(1, text[row].find(" | ") - 1);
            std::vector<int> codes;
            for (std::sregex_iterator it(keys.begin(), keys.end(), kKeyName), end; it != end; ++it) {
                const int code = glfwKeyNamed((*it)[1]);
                EXPECT_NE(code, 0) << shown(doc) << ":" << row + 1 << ": no key is named " << it->str();
                codes.push_back(code);
                if (keys.find("keypad") != std::string::npos && code == GLFW_KEY_EQUAL)
                    codes.push_back(GLFW_KEY_KP_ADD);
                if (keys.find("keypad") != std::string::npos && code == GLFW_KEY_MINUS)
                    codes.push_back(GLFW_KEY_KP_SUBTRACT);
            }
            for (const int code : codes)
                if (code != 0 && !rowOfKey.emplace(code, static_cast<int>(row + 1)).second)
                    ADD_FAILURE() << shown(doc) << ":" << row + 1 << ": key " << code << " is in two rows";
        }
    }
    return rowOfKey;
}

TEST(Docs, TheStudentsKeyTableIsTheProgramsKeyBindings) {
    int tables = 0;
    const fs::path students = kRoot / "docs" / "students.md";
    const std::map<int, int> rowOfKey = keyTable(students, tables);
    ASSERT_EQ(tables, 1) << "docs/students.md shows the keys as one `| key | action |` table";
    for (const auto& [code, row] : rowOfKey)
        EXPECT_TRUE(shadelab::app::commandForKey(code).has_value())
            << "docs/students.md:" << row << " lists key " << code << ", which the program does not bind";
    for (const shadelab::app::KeyBinding& binding : shadelab::app::keyBindings()) {
        std::set<int> rows;
        for (const int code : binding.keys) {
            const auto found = rowOfKey.find(code);
            if (found == rowOfKey.end())
                ADD_FAILURE() << "docs/students.md's key table lacks " << binding.label << " ("
                              << binding.action << ")";
            else
                rows.insert(found->second);
        }
        EXPECT_LE(rows.size(), 1u) << binding.label << ": one binding, one row of docs/students.md";
    }
    // Any other guide that shows keys as a table shows keys the program binds.
    for (const fs::path& doc : readerDocs()) {
        if (doc == students) continue;
        int others = 0;
        for (const auto& [code, row] : keyTable(doc, others))
            EXPECT_TRUE(shadelab::app::commandForKey(code).has_value())
                << shown(doc) << ":" << row << ": key " << code;
    }
}

// ---- the commands ----

std::string helpOf(const std::string& subcommand) {
    const std::string command = std::string(SHADELAB_EXE) + " " + subcommand + " --help 2>&1";
    std::string output;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[4096];
        for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
        EXPECT_EQ(pclose(pipe), 0) << command;
    }
    return output;
}

bool mentionsFlag(const std::string& text, const std::string& flag) {
    const std::regex word("(^|[^a-z0-9-])" + flag + "([^a-z0-9-]|$)");
    return std::regex_search(text, word);
}

// The commands a doc shows: each line of its plain and sh code blocks (a continuation line that starts with
// `[` or `--` joins the line before), and each inline code span that starts with shadelab or a script.
std::vector<std::string> commandsShown(const std::string& text) {
    std::vector<std::string> commands;
    bool inCode = false, shell = false;
    for (std::string line : lines(text)) {
        if (line.rfind("```", 0) == 0) {
            shell = !inCode && (line == "```" || line == "```sh");
            inCode = !inCode;
            continue;
        }
        if (!inCode || !shell) continue;
        if (line.rfind("$ ", 0) == 0) line = line.substr(2);
        const std::size_t indent = line.find_first_not_of(' ');
        if (indent > 0 && indent != std::string::npos && !commands.empty() &&
            (line[indent] == '[' || line.compare(indent, 2, "--") == 0)) {
            commands.back() += " " + line.substr(indent);
            continue;
        }
        commands.push_back(line);
    }
    static const std::regex kInline(
        "`((build/)?shadelab [^`]+|(scripts|bench|examples/ci)/[^` ]+\\.sh[^`]*)`");
    for (std::sregex_iterator it(text.begin(), text.end(), kInline), end; it != end; ++it) {
        std::string span = (*it)[1];
        std::replace(span.begin(), span.end(), '\n', ' ');
        commands.push_back(span);
    }
    return commands;
}

TEST(Docs, EveryCommandShownExistsWithTheFlagsItTakes) {
    static const std::set<std::string> kSubcommands = {"render", "reference", "bench", "compare",
                                                       "review", "report",    "check", "slides"};
    static const std::regex kFlag(R"((^|[\s\[])(--[a-z][a-z0-9-]*))");
    static const std::regex kScript(R"((scripts|bench|examples/ci)/[A-Za-z0-9_.-]+\.sh)");
    std::map<std::string, std::string> helps;
    int checked = 0;
    for (const fs::path& doc : readerDocs())
        for (std::string command : commandsShown(readText(doc))) {
            command = std::regex_replace(command, std::regex(R"(\s#\s.*)"), "");
            static const std::regex kSegment(R"(\s\|\s|&&|;)");
            for (std::sregex_token_iterator it(command.begin(), command.end(), kSegment, -1), end; it != end;
                 ++it) {
                std::istringstream words(it->str());
                std::vector<std::string> tokens{std::istream_iterator<std::string>(words), {}};
                if (tokens.empty()) continue;
                std::string flagsFrom; // the help or the script text that must name each flag
                std::string what;
                if (tokens[0] == "shadelab" || tokens[0] == "build/shadelab") {
                    const std::string sub =
                        tokens.size() > 1 && kSubcommands.count(tokens[1]) ? tokens[1] : "";
                    if (!helps.count(sub)) helps[sub] = helpOf(sub);
                    flagsFrom = helps[sub];
                    what = "shadelab " + sub;
                } else if (std::regex_match(tokens[0], kScript)) {
                    const fs::path script = kRoot / tokens[0];
                    const bool runnable = fs::exists(script) && (fs::status(script).permissions() &
                                                                 fs::perms::owner_exec) != fs::perms::none;
                    EXPECT_TRUE(runnable)
                        << shown(doc) << " shows " << tokens[0] << ", which is no executable script";
                    if (!runnable) continue;
                    flagsFrom = readText(script);
                    what = tokens[0];
                    if (tokens[0] == "scripts/web.sh" && tokens.size() > 1) {
                        EXPECT_TRUE(mentionsFlag(flagsFrom, tokens[1] + "\\)"))
                            << shown(doc) << ": scripts/web.sh has no command " << tokens[1];
                        if (tokens[1] == "render") { // the browser's `shadelab render`: render's flags
                            if (!helps.count("render")) helps["render"] = helpOf("render");
                            flagsFrom = helps["render"];
                        }
                    }
                } else {
                    continue;
                }
                ++checked;
                const std::string segment = it->str();
                for (std::sregex_iterator flag(segment.begin(), segment.end(), kFlag), end; flag != end;
                     ++flag)
                    EXPECT_TRUE(mentionsFlag(flagsFrom, (*flag)[2]))
                        << shown(doc) << " shows `" << segment << "`: " << what << " takes no " << (*flag)[2];
            }
        }
    EXPECT_GT(checked, 30) << "the commands were not found";
}

} // namespace
