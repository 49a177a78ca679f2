// "What you are seeing": one line per view and per shading mode — what is drawn, in which space, and the
// lecture's formula for it — from one table, which the help, the window's panel and the page all show.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "shadelab/scene/scene.h"

namespace shadelab::app {

struct ViewExplanation {
    std::string_view name;    // the view's or the shading mode's one spelling (toString)
    std::string_view drawn;   // what is drawn
    std::string_view space;   // in which coordinates
    std::string_view formula; // the lecture's formula behind it
};

// Every view (scene, error, split, profile, outside, ndc) and, for the scene's own picture, every shading
// mode (flat, gouraud, phong, toon, exact), in the order the help lists them.
std::span<const ViewExplanation> viewExplanations();

// The line for what `scene` draws now: its view's entry, and for the camera's picture (the scene view, a
// split's sides) the shading mode's entry with the lighting model's formula. One line, no newline.
std::string whatYouAreSeeing(const Scene& scene);

// The whole table as text, a line per entry ("ndc      the objects after ...; in ...; ..."): the help's
// section under the keys, in --help, the window's help and the page's.
std::string viewHelpText();

} // namespace shadelab::app
