// Small helpers for the scene reader tests.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "rt/core/diagnostics.h"
#include "rt/core/error.h"
#include "rt/scene/read/source_text.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt::test {

/// An in-memory file as the readers see it.
inline SourceText text_file(const std::string& name, const std::string& bytes) {
    return SourceText{name, bytes};
}

/// The what() of the InputError the call throws, or "no error".
inline std::string input_error(const std::function<void()>& call) {
    try {
        call();
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

/// The text with every occurrence of `prefix` removed (a temporary folder in file names).
inline std::string without(std::string text, const std::string& prefix) {
    for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix)) {
        text.erase(at, prefix.size());
    }
    return text;
}

/// The shipped test data of the scene readers.
inline std::filesystem::path scene_data() {
    return source_dir() / "tests/data/scene";
}

/// A Diagnostics that records traces too.
struct RecordingDiagnostics {
    Diagnostics diagnostics;
    std::vector<std::string> traces;
    explicit RecordingDiagnostics(bool trace = false) {
        if (trace) {
            diagnostics.set_trace_sink([this](const std::string& m) { traces.push_back(m); });
        }
    }
};

}  // namespace rt::test
