// What `shadelab review` reads and writes on disk (review_files.cpp): the folders' PNGs, read only when
// they are regular files and never by a blocking open, and the outputs by the output rules
// (io/atomic_file.h).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "app/check/review.h"
#include "shadelab/image/image.h"

namespace shadelab::app {

struct ReviewEntry {
    std::filesystem::path path;
    std::string file, stem; // "name.png", "name"
    std::string problem;    // "" for a regular file, else what it is: "a symbolic link", "a FIFO"…
};
// The *.png entries of `dir` (named by `field` in messages), in name order; throws InputError when it
// cannot be listed.
std::vector<ReviewEntry> listReviewPngs(const std::filesystem::path& dir, std::string_view field);
ReviewEntry reviewEntryAt(const std::filesystem::path& path);
// InputError unless `dir` is a folder.
void checkReviewFolder(const std::filesystem::path& dir, std::string_view field);

struct ReviewRead {
    std::string bytes;
    Image image;
    std::string error; // "" when read: else one line naming the file and why
};
// Opened with O_NOFOLLOW | O_NONBLOCK and read only if it is a regular file, so a link, FIFO or device
// planted among the PNGs is reported, never followed or waited on.
ReviewRead readReviewPng(const ReviewEntry& entry);
// The expectations file's text (InputError naming --expectations when it cannot be read).
std::string readReviewText(const std::filesystem::path& path);

// "0007": the name a case's files under --out get from its index, never from its untrusted name.
std::string reviewIndexName(int index);
// Writes `bytes` as a file of a folder of outputs (OutputRule::InFolder).
void writeReviewBytes(const std::filesystem::path& path, std::string_view what, const std::string& bytes);
// Checks --json, --junit and --out before any work (none may be an input, the standard output or each
// other) and prepares --out: returns OUT/cases, created, or an empty path without --out.
std::filesystem::path prepareReviewOutputs(const ReviewOptions& options,
                                           const std::vector<std::filesystem::path>& inputs);
// InputError unless EXPECTED_DIR can take a blessed image.
void checkReviewBlessFolder(const std::filesystem::path& expectedDir);

} // namespace shadelab::app
