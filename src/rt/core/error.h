// Errors with their source location; only a program's main() turns them into messages and exits.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace rt {

/// A place in an input file; line and column are 1-based, 0 means unknown.
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;

    /// "file:line" (or "file" when the line is unknown).
    std::string to_string() const;
};

/// Base of every error the library reports.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A malformed input file. what() is the one-line message "file:line: message".
class InputError : public Error {
public:
    InputError(SourceLocation where, const std::string& message);
    const SourceLocation& where() const { return where_; }
    const std::string& message() const { return message_; }

private:
    SourceLocation where_;
    std::string message_;
};

/// Builds the usual "expected X, found Y" message at a location.
InputError expected_found(const SourceLocation& where, const std::string& expected,
                          const std::string& found);

/// A bad command line: unknown switch, bad argument, forbidden combination.
class UsageError : public Error {
public:
    using Error::Error;
};

/// A setting the library cannot honour: outside its range, or too big to build. The message names
/// the setting in the library's words ("the octree node limit"), and setting() gives that name,
/// so that a program can say which of its switches set it (the library knows no switches).
class SettingError : public UsageError {
public:
    SettingError(std::string setting, const std::string& message)
        : UsageError(message), setting_(std::move(setting)) {}
    const std::string& setting() const { return setting_; }

private:
    std::string setting_;
};

/// A switch or feature that is recognised but not implemented yet; never silently ignored.
class NotImplementedError : public Error {
public:
    using Error::Error;
};

/// A file that cannot be opened, read or written.
class IoError : public Error {
public:
    using Error::Error;
};

}  // namespace rt
