// Fused multiply-adds only where the code asks for them. Every method must give brute force's
// picture bit for bit, and several steps stand in for another's arithmetic (the plane's question
// before the exact test, lane_exact_hit.h): a * b + c rounded once in one place and twice in the
// other breaks that. GCC contracts such expressions wherever the target has FMA (RT_AVX2's -mfma,
// any AVX-512 target) unless told not to (-ffp-contract=off, cmake/RtCpu.cmake). The code asks
// for them in two places only: the float pre-filters (fused_float8.h, and its four-lane and
// one-lane forms in float4.h and triangle_prefilter.h), whose conservative bounds hold either way,
// and exact_edge_sign's std::fma, an exact product's rounding error. So no
// double-precision FMA instruction may appear anywhere else; a contracted build has them in most
// of the geometry and shading.
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

TEST(FusedMultiplyAdd, NoneOnDoublesButTheExactEdgeSign) {
    const TempDir dir;
    if (run_shell("command -v objdump", dir.path()).exit_code != 0) {
        GTEST_SKIP() << "objdump is missing (binutils)";
    }
    for (const char* program : {"rt", "show", "merge"}) {
        SCOPED_TRACE(program);
        const std::string path = (bin_dir() / program).string();
        // The name of each function holding a double-precision FMA instruction (vfmadd...sd,
        // vfnmsub...pd, FMA4's too), but exact_edge_sign, then the count of functions, which
        // shows the disassembly was read.
        const ProgramResult r = run_shell(
            fmt::format("objdump -d --no-show-raw-insn {} | awk '/^[0-9a-f]+ <.*>:$/ {{ f = $2; "
                        "n++ }} /\\tvfn?m(add|sub)[0-9a-z]*[sp]d/ && f !~ /exact_edge_sign/ && "
                        "!seen[f]++ {{ print f }} END {{ print n, \"functions\" }}'",
                        shell_quote(path)),
            dir.path());
        ASSERT_EQ(r.exit_code, 0) << r.out;
        const std::vector<std::string> lines = lines_of(r.out);
        ASSERT_FALSE(lines.empty());
        EXPECT_GT(std::atoi(lines.back().c_str()), 100) << r.out;  // NOLINT(cert-err34-c)
        EXPECT_EQ(lines.size(), 1u) << "double-precision fused multiply-adds in " << path << ":\n"
                                    << r.out;
    }
}

}  // namespace
}  // namespace rt::test
