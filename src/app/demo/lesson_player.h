// A lesson being stepped through (docs/lecturers.md "Lessons"): which lesson, which step, and where the step
// keys (PgDn, PgUp, Home, End) go from there. DemoState holds one and makes the step's scene its own.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "shadelab/scene/lesson.h"

namespace shadelab::app {

enum class StepMove { Next, Previous, First, Last };

class LessonPlayer {
public:
    // Throws InputError for a null lesson or one without steps; `index` is clamped to the last step.
    void open(std::shared_ptr<const Lesson> lesson, std::size_t index);
    const Lesson* lesson() const { return lesson_.get(); }
    // Held by whoever draws the step's band, so that the lesson's address names this lesson.
    const std::shared_ptr<const Lesson>& shared() const { return lesson_; }
    std::size_t step() const { return step_; }
    const LessonStep& current() const { return lesson_->steps[step_]; }
    // "step 3 of 15: The view volume"; "" without a lesson.
    std::string stepName() const;

    // Where `move` goes from the current step; "" and the step moved to, or why it did not move ("no
    // lesson open ...", "already at the last step") and the step unchanged.
    std::string move(StepMove move);

private:
    std::shared_ptr<const Lesson> lesson_; // null: a scene alone
    std::size_t step_ = 0;
};

} // namespace shadelab::app
