// The review page's script and style, embedded at build time (cmake/embed_files.cmake generates the
// definition from src/app/check/review_page.js and review_page.css): the page inlines them, so it opens
// from a file with nothing beside it and the files in the tree stay the source of truth.
#pragma once

#include <optional>
#include <string_view>

namespace shadelab::app {

// The text of src/app/check/<name>, e.g. reviewPageAsset("review_page.js"); nullopt if there is no such file.
std::optional<std::string_view> reviewPageAsset(std::string_view name);

} // namespace shadelab::app
