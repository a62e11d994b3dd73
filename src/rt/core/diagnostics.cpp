#include "rt/core/diagnostics.h"

namespace rt {

void Diagnostics::warn(const std::string& message) {
    warnings_.push_back(message);
    if (warning_sink_) {
        warning_sink_(message);
    }
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
