#include "rt/core/error.h"

namespace rt {

std::string SourceLocation::to_string() const {
    if (line <= 0) {
        return file;
    }
    return file + ":" + std::to_string(line);
}

InputError::InputError(SourceLocation where, const std::string& message)
    : Error(where.to_string() + ": " + message), where_(std::move(where)), message_(message) {}

InputError expected_found(const SourceLocation& where, const std::string& expected,
                          const std::string& found) {
    return InputError(where, "expected " + expected + ", found " + found);
}

}  // namespace rt
