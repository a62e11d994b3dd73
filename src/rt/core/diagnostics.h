// Where the library sends warnings and parse traces; the program decides how to show them.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rt {

class Diagnostics {
public:
    using Sink = std::function<void(const std::string&)>;

    /// Warnings are always kept; they also go to the sink if one is set.
    void warn(const std::string& message);
    /// Informational notes (e.g. the auto-centred look point); kept like warnings.
    void note(const std::string& message);
    /// Parse traces (-df) are produced only when tracing is on.
    void trace(const std::string& message);

    void set_warning_sink(Sink sink) { warning_sink_ = std::move(sink); }
    void set_note_sink(Sink sink) { note_sink_ = std::move(sink); }
    void set_trace_sink(Sink sink) { trace_sink_ = std::move(sink); }
    bool tracing() const { return static_cast<bool>(trace_sink_); }

    const std::vector<std::string>& warnings() const { return warnings_; }
    const std::vector<std::string>& notes() const { return notes_; }

private:
    std::vector<std::string> warnings_;
    std::vector<std::string> notes_;
    Sink warning_sink_;
    Sink note_sink_;
    Sink trace_sink_;
};

}  // namespace rt
