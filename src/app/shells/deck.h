// `shadelab slides LESSON --deck FILE.html`: every slide of a lesson in one self-contained HTML file, in
// order, each step's "notes" beside its slide as the speaker's notes (commands.h, docs/lecturers.md
// "Lessons").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "shadelab/io/atomic_file.h"
#include "shadelab/scene/lesson.h"

namespace shadelab::app {

class Deck {
public:
    // Checks the output before anything is drawn: `path` by --out's rules (docs/ci-engineers.md "Output
    // files"), named .html or .htm unless it is "-", a device or a FIFO, and none of `inputs` (the lesson,
    // its scenes).
    Deck(const std::filesystem::path& path, const std::vector<std::filesystem::path>& inputs);

    // The next step's slide, as PNG bytes.
    void add(std::string png);
    // Writes the deck atomically: the lesson's title, then each slide with its title as the image's
    // description and its notes.
    void write(const Lesson& lesson) const;

private:
    std::filesystem::path path_;
    std::vector<std::string> pngs_;
};

// The deck's HTML (no file): text escaped, pictures as data: URLs, no request to anywhere.
std::string deckHtml(const Lesson& lesson, const std::vector<std::string>& pngs);

} // namespace shadelab::app
