// Where the library sends warnings and parse traces; the program decides how to show them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace rt {

class Diagnostics {
public:
    using Sink = std::function<void(const std::string&)>;

    /// Warnings are always kept; they also go to the sink if one is set.
    void warn(const std::string& message);
    /// A warning that may come once a polygon or cell, a million times in a bad model: the first
    /// kShownOfAKind of each `kind` (what is skipped, and where: "degenerate polygons in a.obj")
    /// are warned as warn() does, the rest only counted, for finish_repeats().
    void warn_repeated(const std::string& kind, const std::string& message);
    /// One warning for each kind that had more than kShownOfAKind: "99990 more degenerate
    /// polygons in a.obj skipped (the first 10 are named above)". Called when a scene is read.
    void finish_repeats();
    static constexpr std::uint64_t kShownOfAKind = 10;
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
    struct Repeats {
        std::string kind;
        std::uint64_t count = 0;
    };
    std::vector<Repeats> repeats_;  // in the order the kinds first came
    std::unordered_map<std::string, std::size_t> repeat_index_;
    Sink warning_sink_;
    Sink note_sink_;
    Sink trace_sink_;
};

}  // namespace rt
