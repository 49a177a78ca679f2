// One setter per value (DESIGN's "one way in for every value", STYLE practice 18): the window's panel, the
// page's panel and its light and material editors set a value by its name and its text, never by replaying
// keys and never with a range of their own. Each row names the value, reads it, and sets it through the
// check the scene file's value goes through (scene_values.h, validateSceneValues), so a refused value reads
// the same from every door: "lights[0].cutoff_deg: must be <= 90, got 95".
//
// A new value is one row here and one control on each panel.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "app/demo/demo_state.h"

namespace shadelab::app {

struct ValueSetter {
    // The scene file's spelling where it has one ("toon_bands", "projection.near"); a light's values take
    // its index in the name ("lights[1].cutoff_deg"), written "lights[]" here; "material." and "scale" are
    // the panel's shown object's (DemoState::shownObject), or of every object when all are edited.
    std::string_view name;
    // The value as text, in the form `set` reads: a word ("phong"), a number ("31.6"), a colour or vector
    // ("0.1 0.2 0.3"), "true" or "false".
    std::string (*read)(const DemoState& state, std::size_t light);
    // Sets the value, or throws InputError with the check's message and changes nothing; `field` is the
    // name as given (a light's with its index), which a refusal of the text's form names.
    void (*set)(DemoState& state, std::size_t light, std::string_view field, std::string_view text);
};

// Every row, in the panels' order.
std::span<const ValueSetter> valueSetters();

// Sets the value `name` names (a row's name, a light's with its index) to `text`: "" when set, else the
// refusal, which the panels show as they are (an unknown name is refused too).
std::string setValue(DemoState& state, std::string_view name, std::string_view text);
// The value `name` names, as text; throws InputError for an unknown name.
std::string readValue(const DemoState& state, std::string_view name);

// The text `set` reads for a number and a vector: enough digits that a double reads back exactly.
std::string valueText(double value);
std::string valueText(const glm::dvec3& value);

} // namespace shadelab::app
