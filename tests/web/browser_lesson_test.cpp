// Lessons in the page: bundled, loaded and a lecturer's own, stepped with keys and buttons, and their step
// paths and files bounded as the command line bounds them (browser_support.h: the session and fixture).

#include "web/browser_support.h"

namespace shadelab::test {
namespace {

using namespace web_test;

// Lessons in the page: the bundled lesson by ?lesson=URL, its scene files fetched beside it (../scenes/),
// every one of its steps drawn by the page as natively at 320×180, the picker naming it; then a lesson
// loaded as a file steps with Page Down, Space, Page Up and the panel's ▶ button, each step's picture native
// OpenGL ES's render of that step's scene, and R returns to a changed step; the panel shows the step. A
// lecturer's own lesson (scripts/web.sh serve --lessons DIR) is in the picker, as text, and loads from it.
TEST_F(Browser, LessonStepsWithKeysAndButtonsAndTheBundledLessonDrawsEveryStep) {
    const std::string text = R"({"title": "Three steps", "steps": [
      {"title": "One", "caption": "Flat at level 2.", "scene": {"image": {"width": 160, "height": 120},
       "shading": "flat", "objects": [{"subdivisions": 2}]}},
      {"title": "Two", "caption": "Gouraud.", "shading": "gouraud"},
      {"title": "Three", "caption": "Phong, Blinn-Phong.", "shading": "phong", "lighting": "blinn-phong"}]})";
    const Lesson lesson = parseLesson(text, "three.json", [](const std::string&) -> std::string {
        throw std::logic_error("no scene files");
    });
    const fs::path bundledPath = fs::path(SHADELAB_WEB_BUILD) / "lessons" / "lighting.json";
    const Lesson bundled = loadLesson(bundledPath);
    // One page for both parts (a Chromium start is about 6 CPU-seconds), its canvas small: each step key
    // redraws it, and SwiftShader's time goes with its size.
    const fs::path own = makeLessonFolder(dir_);
    const Lesson ownLesson = loadLesson(own / kOwnLessonName);
    Session session;
    session.openWith("?lesson=lessons/lighting.json", {{"lessons", own.string()}});
    session.resize(640, 400);
    const std::size_t bundledUi = session.ui();
    const std::size_t bundledMessage = session.message();
    const std::size_t picker = session.element("#bundled");
    std::vector<std::size_t> bundledCaptures;
    for (std::size_t i = 0; i < bundled.steps.size(); ++i) {
        bundledCaptures.push_back(session.capture(320, 180));
        session.key(kKeyPageDown);
    }
    const std::size_t load = session.loadText(text, "three.json");
    struct Shown {
        const char* after;
        std::size_t step;
        std::size_t ui = 0, capture = 0;
    };
    std::vector<Shown> shown = {{"load", 0}, {"Page Down", 1}, {"Space", 2}, {"Page Up", 1}, {"R", 1}};
    const std::vector<int> keys = {0, kKeyPageDown, kKeySpace, kKeyPageUp, 'R'};
    std::size_t changed = 0;
    for (std::size_t i = 0; i < shown.size(); ++i) {
        if (keys[i] == 'R') {
            session.key('1'); // a key inside the step: flat shading
            changed = session.capture();
        }
        if (keys[i] != 0) session.key(keys[i]);
        shown[i].ui = session.ui();
        shown[i].capture = session.capture();
    }
    session.panel("#step-next", "", "click");
    const std::size_t afterButton = session.ui();
    const std::size_t caption = session.element("#step-caption");
    const std::size_t position = session.element("#step-out");
    // The lecturer's folder (--lessons): its one lesson in the picker, its name as text; picked, it loads
    // with the scene it names from the folder.
    const std::size_t ownOption = session.element("#bundled option[value^=\"own:\"]");
    const std::size_t secondOwn =
        session.element("#bundled option[value^=\"own:\"] ~ option[value^=\"own:\"]");
    session.panel("#bundled", std::string("own:") + kOwnLessonName);
    session.waitUi({"lesson", "title"}, "Own <i>lesson</i>"); // the picker's load fetches lesson and scene
    const std::size_t ownUi = session.ui();
    const std::size_t ownPicture = session.capture();
    const std::size_t ownTitle = session.element("#lesson-title");
    const std::size_t markup = session.element("img");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;

    const json option = session.answer(ownOption).at("element");
    ASSERT_TRUE(option.is_object()) << "the lecturer's lesson is not in the picker";
    EXPECT_EQ(option.at("text"), std::string("own lesson: ") + kOwnLessonName);
    EXPECT_TRUE(session.answer(secondOwn).at("element").is_null())
        << "listed beside the lesson: " << session.answer(secondOwn);
    const json ownShown = session.answer(ownUi).at("ui");
    ASSERT_TRUE(ownShown.at("lesson").is_object()) << ownShown.at("error");
    EXPECT_EQ(ownShown.at("lesson").at("title"), "Own <i>lesson</i>");
    EXPECT_EQ(session.answer(ownTitle).at("element").at("text"), "Own <i>lesson</i>");
    EXPECT_TRUE(session.answer(markup).at("element").is_null()) << "a name or title became markup";
    const Image ownImage = session.image(ownPicture);
    const Comparison ownCompared = compareImages(ownImage, nativeGles().render(ownLesson.steps[0].scene),
                                                 swiftShaderTolerance(ownImage));
    EXPECT_TRUE(ownCompared.passed) << "the lecturer's step 1: " << ownCompared.summary();

    EXPECT_EQ(session.answer(load).at("message"), "") << "the lesson loads";
    for (const Shown& s : shown) {
        SCOPED_TRACE(std::string("after ") + s.after);
        const json lessonUi = session.answer(s.ui).at("ui").at("lesson");
        ASSERT_TRUE(lessonUi.is_object()) << "no lesson in the panel";
        EXPECT_EQ(lessonUi.at("step"), s.step + 1);
        EXPECT_EQ(lessonUi.at("steps"), 3);
        const Image page = session.image(s.capture);
        const Image native = nativeGles().render(lesson.steps[s.step].scene);
        const Comparison c = compareImages(page, native, swiftShaderTolerance(page));
        EXPECT_TRUE(c.passed) << "the page's picture is not native render's of step " << s.step + 1 << ": "
                              << c.summary();
    }
    EXPECT_FALSE(
        compareImages(session.image(changed), session.image(shown.back().capture), kBeyondRounding).passed)
        << "the key inside the step changed nothing (R then had nothing to restore)";
    EXPECT_EQ(session.answer(afterButton).at("ui").at("lesson").at("step"), 3) << "the ▶ button";
    EXPECT_EQ(session.answer(caption).at("element").at("text"), "Phong, Blinn-Phong.");
    EXPECT_EQ(session.answer(position).at("element").at("text"), "step 3 of 3");

    EXPECT_EQ(session.answer(bundledMessage).at("message"), "") << "the bundled lesson loads by its URL";
    EXPECT_EQ(session.answer(bundledUi).at("ui").at("lesson").at("steps"), bundled.steps.size());
    EXPECT_EQ(session.answer(picker).at("element").at("value"), "lesson:lighting.json")
        << "the picker names the bundled lesson";
    for (std::size_t i = 0; i < bundled.steps.size(); ++i) {
        SCOPED_TRACE("bundled lesson, step " + std::to_string(i + 1) + ": " + bundled.steps[i].title);
        Scene scene = bundled.steps[i].scene;
        scene.width = 320;
        scene.height = 180;
        const Image page = session.image(bundledCaptures[i]);
        const Comparison c = compareImages(page, nativeGles().render(scene), swiftShaderTolerance(page));
        EXPECT_TRUE(c.passed) << c.summary();
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// A lesson's step paths and files on the page, as the command line bounds them. Every step's path is checked
// before anything is fetched: the command line's refusals ("-", a NUL, an absolute path) with its messages,
// and what the page alone would take for another place (a scheme, another origin; "http://[" threw outside
// any handler and the page never became ready) in the same form. A step file over 16 MiB is refused with
// the command line's message without reading it whole (a Content-Length over it: not read at all; a stream
// without one: cancelled past 16 MiB), each distinct file is fetched once, and fetching stops where the
// lesson's steps pass what the parser takes (the native message names the step).
TEST_F(Browser, LessonStepPathsAreCheckedFirstAndTheirFilesBounded) {
    const fs::path files = dir_ / "files";
    fs::create_directories(files);
    const std::string small = R"({"image": {"width": 32, "height": 24}})";
    std::ofstream(files / "s.json") << small;
    const auto lessonWith = [](const std::vector<std::string>& scenes) {
        json lesson = {{"title", "t"}, {"steps", json::array()}};
        for (const std::string& scene : scenes)
            lesson["steps"].push_back(
                {{"title", "step " + std::to_string(lesson["steps"].size())}, {"scene", scene}});
        return lesson.dump();
    };
    // The text the page's C++ is handed for a path (web/main.cpp shadelab_load_lesson's reader), so the
    // native parser gives the message the page must give.
    const auto pageReader = [&files](const std::string& path) -> std::string {
        if (path.starts_with("../stream/")) checkSceneTextSize(kMaxSceneBytes + 1, path);
        std::ifstream in(files / path, std::ios::binary);
        if (!in) throw InputError("no such test file");
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        checkSceneTextSize(text.size(), path);
        return text;
    };
    const auto nativeMessage = [&](const std::string& text, const std::string& name) {
        try {
            (void)parseLesson(text, name, pageReader);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(the native parser took it)");
    };
    const std::string elsewhere = ": steps[1].scene: must be a path relative to the lesson's folder, got ";

    // Refused before any request: the command line's rules, then the page's.
    struct Refusal {
        std::string path, expected;
    };
    std::vector<Refusal> refusals;
    for (const std::string& path :
         {std::string("/files/abs.json"), std::string("-"), std::string("a\0b.json", 8), std::string()})
        refusals.push_back({path, ""}); // expected: the native parser's message
    for (const std::string path :
         {"http://127.0.0.2:9/x.json", "//127.0.0.2:9/x.json", "data:application/json,{}",
          "javascript:alert(1)", "\\\\127.0.0.2:9\\x.json", " http://127.0.0.2:9/x.json", "http://["})
        refusals.push_back({path, elsewhere + quotedValue(path)});
    for (std::size_t i = 0; i < refusals.size(); ++i) {
        const std::string name = "refused-" + std::to_string(i) + ".json";
        const std::string text = lessonWith({"s.json", refusals[i].path});
        std::ofstream(files / name) << text;
        refusals[i].expected =
            refusals[i].expected.empty() ? nativeMessage(text, name) : name + refusals[i].expected;
    }
    std::ofstream(files / "bad-url.json") << lessonWith({"http://["});
    const std::string badUrlExpected =
        "bad-url.json: steps[0].scene: must be a path relative to the lesson's "
        "folder, got \"http://[\"";
    // A data: lesson has no folder for its steps.
    const std::string dataLesson = "data:application/json," + lessonWith({"s.json"});

    // Too large: one file of 17 MiB (sent with its Content-Length), 200 MiB streamed without one and with
    // one; and steps that parse more than 64 MiB in all (15 MiB named five times: the sixth step's file is
    // never fetched).
    const auto padded = [&](const fs::path& path, std::size_t bytes) {
        const std::string head = R"({"image": {"width": 8, "height": 8})";
        std::ofstream(path, std::ios::binary) << head << std::string(bytes - head.size() - 1, ' ') << "}";
    };
    padded(files / "big17.json", 17 << 20);
    padded(files / "t1.json", 15 << 20);
    padded(files / "t2.json", 1 << 20);
    const std::vector<std::pair<std::string, std::string>> large = {
        {"big-file.json", lessonWith({"s.json", "big17.json"})},
        {"streamed.json", lessonWith({"s.json", "../stream/200.json"})},
        {"declared.json", lessonWith({"s.json", "../stream/200-declared.json"})},
        {"steps-total.json", lessonWith({"t1.json", "t1.json", "t1.json", "t1.json", "t1.json", "t2.json"})},
    };
    for (const auto& [name, text] : large) std::ofstream(files / name) << text;

    Session session;
    const std::size_t open = session.openWithFiles("?lesson=files/bad-url.json", files);
    const std::size_t openMessage = session.message();
    std::vector<std::size_t> refused;
    for (std::size_t i = 0; i < refusals.size(); ++i)
        refused.push_back(session.loadUrl("files/refused-" + std::to_string(i) + ".json"));
    const std::size_t beforeAnyFile = session.served();
    const std::size_t data = session.loadUrl(dataLesson);
    std::vector<std::size_t> largeLoads;
    for (const auto& [name, text] : large) largeLoads.push_back(session.loadUrl("files/" + name));
    session.sleep(1); // the stream's server thread notes what it sent once the page has hung up
    const std::size_t served = session.served();
    const std::size_t shown = session.message();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;

    EXPECT_EQ(session.answer(open).at("failed"), "");
    EXPECT_EQ(session.answer(openMessage).at("message"), badUrlExpected)
        << "?lesson= with a step \"http://[\"";
    for (std::size_t i = 0; i < refusals.size(); ++i)
        EXPECT_EQ(session.answer(refused[i]).at("message"), refusals[i].expected) << json(refusals[i].path);
    const json requestedFirst = session.answer(beforeAnyFile).at("requested");
    for (const char* never : {"/files/s.json", "/files/abs.json"})
        EXPECT_EQ(std::count(requestedFirst.begin(), requestedFirst.end(), never), 0)
            << never << " was requested for a refused lesson: " << requestedFirst;
    const std::string dataMessage = session.answer(data).at("message");
    EXPECT_NE(
        dataMessage.find(R"(steps[0].scene: the page cannot fetch it beside the lesson, whose URL "data:)"),
        std::string::npos)
        << dataMessage;
    EXPECT_NE(dataMessage.find("has no folder"), std::string::npos) << dataMessage;
    for (std::size_t i = 0; i < large.size(); ++i)
        EXPECT_EQ(session.answer(largeLoads[i]).at("message"), nativeMessage(large[i].second, large[i].first))
            << large[i].first;
    const json& requested = session.answer(served).at("requested");
    const json& streamed = session.answer(served).at("streamed");
    const auto times = [&](const std::string& path) {
        return std::count(requested.begin(), requested.end(), path);
    };
    EXPECT_EQ(times("/files/t1.json"), 1) << "t1.json, named by two steps, fetched once";
    EXPECT_EQ(times("/files/t2.json"), 0) << "fetched after the steps passed 64 MiB of scene text";
    // What the server could send before the page hung up: the limit, plus what the sockets' buffers and the
    // browser's network process hold.
    ASSERT_TRUE(streamed.contains("/stream/200.json")) << streamed;
    ASSERT_TRUE(streamed.contains("/stream/200-declared.json")) << streamed;
    const double mib = 1 << 20;
    EXPECT_LT(streamed.at("/stream/200.json").get<double>() / mib, 48) << "MiB sent without a Content-Length";
    EXPECT_LT(streamed.at("/stream/200-declared.json").get<double>() / mib, 32)
        << "MiB sent after the header";
    std::printf("streamed before the page hung up: %.1f MiB without a Content-Length, %.1f MiB with one\n",
                streamed.at("/stream/200.json").get<double>() / mib,
                streamed.at("/stream/200-declared.json").get<double>() / mib);
    EXPECT_FALSE(session.answer(shown).at("message").get<std::string>().empty()) << "the last refusal shows";
    for (const json& entry : session.answer(console).at("console"))
        EXPECT_EQ(entry.value("message", "").find("Uncaught"), std::string::npos) << entry;
}

} // namespace
} // namespace shadelab::test
