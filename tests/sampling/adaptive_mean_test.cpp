// The stopping loop of adaptive supersampling, as pixels and distributed rays both use it: which
// samples it takes, in which order, and when it asks for confirmation.
#include "rt/sampling/adaptive_mean.h"

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr std::uint32_t kTotal = 16;  // a 4x4 pixel: minimum_samples is 4

// Takes samples of a constant grey that all saw surface 7, except where `seen_at` says otherwise;
// records the order of k.
struct FlatSamples {
    std::vector<std::uint32_t> taken;
    std::vector<int> seen_at = std::vector<int>(kTotal, 7);

    SeenSample<int> operator()(std::uint32_t k) {
        taken.push_back(k);
        return {Rgb{0.5, 0.5, 0.5}, seen_at[k]};
    }
};

// Answers `agree` and counts how often it was asked, and about what.
struct Confirmer {
    bool agree = true;
    std::vector<int> asked;

    bool operator()(const int& seen) {
        asked.push_back(seen);
        return agree;
    }
};

std::vector<std::uint32_t> first(std::uint32_t n) {
    std::vector<std::uint32_t> ks;
    for (std::uint32_t k = 0; k < n; ++k) {
        ks.push_back(k);
    }
    return ks;
}

TEST(AdaptiveMean, FlatSamplesOnOneSurfaceStopAtTheMinimumAfterOneConfirmation) {
    const ChiSquareStop stop;
    FlatSamples take;
    Confirmer confirm;
    const RunningStatistics s = adaptive_mean(kTotal, &stop, take, confirm);
    EXPECT_EQ(s.count(), minimum_samples(kTotal));
    EXPECT_EQ(take.taken, first(minimum_samples(kTotal)));
    EXPECT_EQ(confirm.asked, std::vector<int>{7});
    EXPECT_EQ(s.mean(), (Rgb{0.5, 0.5, 0.5}));
}

TEST(AdaptiveMean, WithoutARuleEverySampleIsTakenAndNothingConfirmed) {
    FlatSamples take;
    Confirmer confirm;
    EXPECT_EQ(adaptive_mean(kTotal, nullptr, take, confirm).count(), kTotal);  // -Dx
    EXPECT_EQ(take.taken, first(kTotal));
    EXPECT_TRUE(confirm.asked.empty());
}

TEST(AdaptiveMean, ASampleOnAnotherSurfaceMeansEverySample) {
    const ChiSquareStop stop;
    FlatSamples take;
    take.seen_at[2] = 8;  // an edge between the first samples; the later ones agree again
    Confirmer confirm;
    EXPECT_EQ(adaptive_mean(kTotal, &stop, take, confirm).count(), kTotal);
    EXPECT_TRUE(confirm.asked.empty());
}

TEST(AdaptiveMean, ADisagreeingConfirmationIsAskedOnceAndMeansEverySample) {
    const ChiSquareStop stop;
    FlatSamples take;
    Confirmer confirm{false, {}};
    EXPECT_EQ(adaptive_mean(kTotal, &stop, take, confirm).count(), kTotal);
    EXPECT_EQ(confirm.asked, std::vector<int>{7});
}

TEST(AdaptiveMean, NoisySamplesKeepSamplingUntilTheRuleIsMet) {
    // Black and white in turn: a variance of the mean far above 0.2 display levels squared.
    const ChiSquareStop stop;
    std::uint32_t taken = 0;
    const auto noisy = [&](std::uint32_t k) {
        ++taken;
        return SeenSample<int>{k % 2 == 0 ? Rgb{} : Rgb{1, 1, 1}, 7};
    };
    Confirmer confirm;
    EXPECT_EQ(adaptive_mean(kTotal, &stop, noisy, confirm).count(), kTotal);
    EXPECT_EQ(taken, kTotal);
    EXPECT_TRUE(confirm.asked.empty());
}

TEST(AdaptiveMean, OneSampleIsAllThereIs) {
    const ChiSquareStop stop;
    FlatSamples take;
    Confirmer confirm;
    EXPECT_EQ(adaptive_mean(1, &stop, take, confirm).count(), 1u);
    EXPECT_EQ(adaptive_mean(1, nullptr, take, confirm).count(), 1u);
}

// Records, for each sample taken, how far the loop promised to go: every promise must be kept.
struct PromisedSamples {
    FlatSamples flat;
    std::vector<std::uint32_t> certain;

    SeenSample<int> operator()(std::uint32_t k, std::uint32_t certain_end) {
        certain.push_back(certain_end);
        return flat(k);
    }
};

void expect_promises_kept(const PromisedSamples& take, std::uint32_t taken) {
    for (std::size_t k = 0; k < take.certain.size(); ++k) {
        EXPECT_GT(take.certain[k], k);
        EXPECT_LE(take.certain[k], taken) << "sample " << k;
    }
}

TEST(AdaptiveMean, ItTellsWhichSamplesWillBeTakenWhateverTheyBring) {
    const ChiSquareStop stop;
    PromisedSamples take;
    Confirmer confirm;
    EXPECT_EQ(adaptive_mean(kTotal, &stop, take, confirm).count(), 4u);
    EXPECT_EQ(take.certain, (std::vector<std::uint32_t>{4, 4, 4, 4}));  // the minimum

    PromisedSamples edge;
    edge.flat.seen_at[1] = 8;  // from the third sample on, every sample is certain
    EXPECT_EQ(adaptive_mean(kTotal, &stop, edge, confirm).count(), kTotal);
    EXPECT_EQ(edge.certain[0], 4u);
    EXPECT_EQ(edge.certain[1], 4u);
    EXPECT_EQ(edge.certain[2], kTotal);
    expect_promises_kept(edge, kTotal);

    PromisedSamples refused;
    Confirmer no{false, {}};
    EXPECT_EQ(adaptive_mean(kTotal, &stop, refused, no).count(), kTotal);
    EXPECT_EQ(refused.certain[3], 4u);
    EXPECT_EQ(refused.certain[4], kTotal);  // after the confirmation failed
    expect_promises_kept(refused, kTotal);

    PromisedSamples every;
    EXPECT_EQ(adaptive_mean(kTotal, nullptr, every, confirm).count(), kTotal);  // -Dx
    EXPECT_EQ(every.certain, std::vector<std::uint32_t>(kTotal, kTotal));
}

TEST(AdaptiveMean, NoisySamplesAreCertainOnlyOneAtATimeAfterTheMinimum) {
    const ChiSquareStop stop;
    std::vector<std::uint32_t> certain;
    const auto noisy = [&](std::uint32_t k, std::uint32_t certain_end) {
        certain.push_back(certain_end);
        return SeenSample<int>{k % 2 == 0 ? Rgb{} : Rgb{1, 1, 1}, 7};
    };
    Confirmer confirm;
    EXPECT_EQ(adaptive_mean(kTotal, &stop, noisy, confirm).count(), kTotal);
    for (std::uint32_t k = 4; k < kTotal; ++k) {
        EXPECT_EQ(certain[k], k + 1);  // the rule might stop after any of them
    }
}

}  // namespace
}  // namespace rt
