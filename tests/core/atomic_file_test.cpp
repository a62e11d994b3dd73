// write_file_atomically: the file is either the new whole content or the old one, never a part,
// and no temporary is left behind whatever fails.
#include "rt/core/atomic_file.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "rt/core/error.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"
#include <sys/stat.h>

namespace rt {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> names_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) {
        names.push_back(entry.path().filename().string());
    }
    return names;
}

TEST(AtomicFile, WritesTheWholeContentAndNothingElse) {
    const test::TempDir dir;
    const fs::path path = dir.path() / "out.txt";
    write_file_atomically(path, [](std::ostream& out) { out << "first"; });
    EXPECT_EQ(test::read_text(path), "first");
    write_file_atomically(path, [](std::ostream& out) { out << "second, longer"; });
    EXPECT_EQ(test::read_text(path), "second, longer");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, AThrowingWriterLeavesTheOldFileAndItsErrorGoesOn) {
    const test::TempDir dir;
    const fs::path path = dir.write("out.txt", "old");
    EXPECT_THROW(write_file_atomically(path,
                                       [](std::ostream& out) {
                                           out << "half of it";
                                           throw std::logic_error("renderer gave up");
                                       }),
                 std::logic_error);
    EXPECT_EQ(test::read_text(path), "old");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, AFailedStreamIsAnIoErrorAndLeavesTheOldFile) {
    // A stream that went bad (as on a full disk) while the writer was not looking.
    const test::TempDir dir;
    const fs::path path = dir.write("out.txt", "old");
    try {
        write_file_atomically(path, [](std::ostream& out) {
            out << "partial";
            out.setstate(std::ios::badbit);
        });
        FAIL() << "a failed stream was accepted";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cannot write " + path.string() + ": write failed (disk full?)");
    }
    EXPECT_EQ(test::read_text(path), "old");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.txt"});
}

// The rename would put a file where a named pipe (or a device, or a socket) was: every program
// that writes through here refuses, as rt's checks before a render do.
TEST(AtomicFile, APipeInTheWayIsAnIoErrorAndStays) {
    const test::TempDir dir;
    const fs::path path = dir.path() / "out.png";
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    bool wrote = false;
    try {
        write_file_atomically(path, [&](std::ostream& out) {
            wrote = true;
            out << "content";
        });
        FAIL() << "a pipe was replaced";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write " + path.string() +
                                             ": it is a device, a pipe or a socket, not a file");
    }
    EXPECT_FALSE(wrote);
    EXPECT_TRUE(fs::is_fifo(path));
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.png"});
}

TEST(AtomicFile, AFolderInTheWayIsAnIoErrorAndNoTemporaryStays) {
    // The rename over a non-empty folder fails after the content was written.
    const test::TempDir dir;
    const fs::path path = dir.path() / "taken";
    fs::create_directory(path);
    dir.write("taken/inside.txt", "keep");
    try {
        write_file_atomically(path, [](std::ostream& out) { out << "content"; });
        FAIL() << "a folder was replaced";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("cannot write " + path.string() + ": ", 0), 0U)
            << e.what();
    }
    EXPECT_EQ(test::read_text(path / "inside.txt"), "keep");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"taken"});
}

TEST(AtomicFile, AMissingFolderIsAnIoErrorBeforeAnythingIsWritten) {
    const test::TempDir dir;
    const fs::path path = dir.path() / "no_such_folder" / "out.txt";
    bool called = false;
    EXPECT_THROW(write_file_atomically(path, [&](std::ostream&) { called = true; }), IoError);
    EXPECT_FALSE(called);
    EXPECT_FALSE(fs::exists(path.parent_path()));
}

// "cannot create X.tmpPID" alone left the user guessing; the reason comes from the system.
TEST(AtomicFile, CannotCreateSaysWhy) {
    const test::TempDir dir;
    const fs::path path = dir.path() / "no_such_folder" / "out.txt";
    try {
        write_file_atomically(path, [](std::ostream&) {});
        FAIL() << "no error";
    } catch (const IoError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(": cannot create "), std::string::npos) << message;
        EXPECT_NE(message.find(": No such file or directory"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace rt
