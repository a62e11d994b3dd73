// No program holds a fused multiply-add. Every method must give brute force's picture bit for bit,
// and several steps stand in for another's arithmetic (the plane's question before the exact test,
// lane_exact_hit.h; the float pre-filters' error bounds, float_ray.cpp): a * b + c rounded once in
// one place and twice in the other breaks that. GCC contracts such expressions wherever the target
// has FMA, as its AVX-512 targets do, unless told not to (-ffp-contract=off, cmake/RtCpu.cmake).
#include <cstdlib>
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"
#include <sys/wait.h>

namespace rt::test {
namespace {

namespace fs = std::filesystem;

// Runs the shell command (a pipeline, so in parentheses) in `folder`; its exit status and its
// output and errors together.
ProgramResult run_shell(const std::string& command, const fs::path& folder) {
    const fs::path output = folder / "output.txt";
    const std::string line = fmt::format("cd '{}' && ({}) </dev/null >'{}' 2>&1", folder.string(),
                                         command, output.string());
    const int status = std::system(line.c_str());  // NOLINT(concurrency-mt-unsafe)
    ProgramResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_text(output);
    return result;
}

TEST(NoFusedMultiplyAdd, NoProgramContainsOne) {
    const TempDir dir;
    if (run_shell("command -v objdump", dir.path()).exit_code != 0) {
        GTEST_SKIP() << "objdump is missing (binutils)";
    }
    for (const char* program : {"rt", "show", "merge"}) {
        SCOPED_TRACE(program);
        const std::string path = (bin_dir() / program).string();
        // The name of each function holding an FMA instruction (vfmadd..., vfnmsub..., FMA4's
        // too), then the count of functions, which shows the disassembly was read.
        const ProgramResult r = run_shell(
            fmt::format("objdump -d --no-show-raw-insn '{}' | awk '/^[0-9a-f]+ <.*>:$/ {{ f = $2; "
                        "n++ }} /\\tvfn?m(add|sub)/ && !seen[f]++ {{ print f }} END {{ print n, "
                        "\"functions\" }}'",
                        path),
            dir.path());
        ASSERT_EQ(r.exit_code, 0) << r.out;
        const std::vector<std::string> lines = lines_of(r.out);
        ASSERT_FALSE(lines.empty());
        EXPECT_GT(std::atoi(lines.back().c_str()), 100) << r.out;  // NOLINT(cert-err34-c)
        EXPECT_EQ(lines.size(), 1u) << "fused multiply-adds in " << path << ":\n" << r.out;
    }
}

}  // namespace
}  // namespace rt::test
