#include "rt/core/diagnostics.h"

#include <fmt/format.h>

namespace rt {

void Diagnostics::warn(const std::string& message) {
    warnings_.push_back(message);
    if (warning_sink_) {
        warning_sink_(message);
    }
}

void Diagnostics::warn_repeated(const std::string& kind, const std::string& message) {
    const auto [at, added] = repeat_index_.try_emplace(kind, repeats_.size());
    if (added) {
        repeats_.push_back({kind, 0});
    }
    if (++repeats_[at->second].count <= kShownOfAKind) {
        warn(message);
    }
}

void Diagnostics::finish_repeats() {
    for (const Repeats& r : repeats_) {
        if (r.count > kShownOfAKind) {
            warn(fmt::format("{} more {} skipped (the first {} are named above)",
                             r.count - kShownOfAKind, r.kind, kShownOfAKind));
        }
    }
    repeats_.clear();
    repeat_index_.clear();
}

void Diagnostics::note(const std::string& message) {
    notes_.push_back(message);
    if (note_sink_) {
        note_sink_(message);
    }
}

void Diagnostics::trace(const std::string& message) {
    if (trace_sink_) {
        trace_sink_(message);
    }
}

}  // namespace rt
