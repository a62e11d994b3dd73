// Adaptive supersampling (manual -X, -Dx) on the shipped twocubes at a sample resolution of 4:
// it must reach the error of taking every sample with clearly fewer samples. The reference is
// the mean of several full renders with other seeds.
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include "rt/image/ppm_format.h"

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

struct Render {
    Image8 image;
    std::uint64_t rays = 0;  ///< eye samples plus distributed rays, from -dx
};

class AdaptiveSampling : public ::testing::Test {
protected:
    void SetUp() override {
        fs::copy(source_dir() / "scenes", dir_.path(), fs::copy_options::recursive);
        std::string scene = read_text(dir_.path() / "twocubes.scn");
        scene.replace(scene.find("$ 1\n"), 4, "$ 4\n");                       // sample resolution
        scene.replace(scene.find("$ 0 0 511 399"), 13, "$ 200 150 319 239");  // around the cube
        dir_.write("cubes4.scn", scene);
    }

    Render render(const std::vector<std::string>& extra, int seed) {
        std::vector<std::string> args{"cubes4",   "-n",      "--quiet", "-dx",
                                      "--output", "out.ppm", "--seed",  std::to_string(seed)};
        args.insert(args.end(), extra.begin(), extra.end());
        const ProgramResult r = run_program("rt", args, dir_.path());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        Render out;
        out.image = read_ppm(dir_.path() / "out.ppm");
        const std::regex line(
            R"((\d+) samples, \d+ intersections distributing (\d+) rays, (\d+) probes)");
        for (auto it = std::sregex_iterator(r.err.begin(), r.err.end(), line);
             it != std::sregex_iterator(); ++it) {
            out.rays += std::stoull((*it)[1]) + std::stoull((*it)[2]) + std::stoull((*it)[3]);
        }
        return out;
    }

    TempDir dir_;
};

double rms_difference(const Image8& a, const std::vector<double>& reference) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        const double d = a.rgb[i] - reference[i];
        sum += d * d;
    }
    return std::sqrt(sum / static_cast<double>(a.rgb.size()));
}

TEST_F(AdaptiveSampling, ReachesTheErrorOfFullSamplingWithFewerSamples) {
    constexpr int kReferenceRenders = 4;
    std::vector<double> reference;
    for (int seed = 100; seed < 100 + kReferenceRenders; ++seed) {
        const Render r = render({"-Dx"}, seed);
        reference.resize(r.image.rgb.size());
        for (std::size_t i = 0; i < reference.size(); ++i) {
            reference[i] += r.image.rgb[i] / static_cast<double>(kReferenceRenders);
        }
    }
    const Render full = render({"-Dx"}, 1);
    const Render adaptive = render({}, 1);
    ASSERT_EQ(full.image.width, 120);
    ASSERT_EQ(full.image.height, 90);
    ASSERT_GT(full.rays, 0U);
    const double full_error = rms_difference(full.image, reference);
    const double adaptive_error = rms_difference(adaptive.image, reference);
    const double ratio = static_cast<double>(adaptive.rays) / static_cast<double>(full.rays);
    RecordProperty("sample_ratio", std::to_string(ratio));
    std::printf("adaptive: %llu rays, error %.3f; full: %llu rays, error %.3f; ratio %.3f\n",
                static_cast<unsigned long long>(adaptive.rays), adaptive_error,
                static_cast<unsigned long long>(full.rays), full_error, ratio);
    EXPECT_LE(adaptive_error, full_error * 1.15);
    EXPECT_LT(ratio, 0.6);
}

}  // namespace
}  // namespace rt::test
