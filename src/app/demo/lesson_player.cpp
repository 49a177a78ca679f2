#include "app/demo/lesson_player.h"

#include <algorithm>

#include "shadelab/errors.h"

namespace shadelab::app {

void LessonPlayer::open(std::shared_ptr<const Lesson> lesson, std::size_t index) {
    if (!lesson || lesson->steps.empty()) throw InputError("a lesson has at least one step");
    lesson_ = std::move(lesson);
    step_ = std::min(index, lesson_->steps.size() - 1);
}

std::string LessonPlayer::stepName() const {
    if (!lesson_) return "";
    return "step " + std::to_string(step_ + 1) + " of " + std::to_string(lesson_->steps.size()) + ": " +
           lesson_->steps[step_].title;
}

std::string LessonPlayer::move(StepMove move) {
    if (!lesson_) return "no lesson open (shadelab LESSON.json opens one)";
    const std::size_t last = lesson_->steps.size() - 1;
    const std::size_t to = move == StepMove::First  ? 0
                           : move == StepMove::Last ? last
                           : move == StepMove::Next ? std::min(step_ + 1, last)
                                                    : (step_ == 0 ? 0 : step_ - 1);
    if (to == step_ && (move == StepMove::Next || move == StepMove::Previous))
        return to == 0 ? "already at the first step" : "already at the last step";
    step_ = to;
    return "";
}

} // namespace shadelab::app
