// The boxes of each polygon's guards (leaving_table.h), four to a block as structure of arrays, so
// that a ray's line is tested against every guard its direction may meet at once. Kept in the
// guards' own records, each box was a load from another record's cache lines and one slab test at
// a time: about a quarter of the leaving table's query.
//
// The four-lane test makes the same operations on the same values as line_may_meet_box_sse2
// (voxel/polygon_boxes.h), each lane the box it would be given, with the same choices on equal
// and NaN operands, so it answers as that test does box for box. A line with a zero direction
// component takes line_may_meet_box itself, box by box.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "rt/accel/voxel/polygon_boxes.h"

namespace rt {

class GuardBoxes {
public:
    /// Boxes to a block.
    static constexpr std::uint32_t kLanes = 4;

    /// Appends one polygon's guards' boxes (each lo x y z, hi x y z), guard g in lane g % 4 of
    /// its block g / 4; returns the index of its first block.
    std::uint32_t add(std::span<const std::array<float, 6>> boxes) {
        const auto first = static_cast<std::uint32_t>(blocks_.size());
        blocks_.resize(blocks_.size() + (boxes.size() + kLanes - 1) / kLanes);
        for (std::size_t g = 0; g < boxes.size(); ++g) {
            Block& block = blocks_[first + g / kLanes];
            for (std::size_t plane = 0; plane < 6; ++plane) {
                block.plane[plane][g % kLanes] = boxes[g][plane];
            }
        }
        return first;
    }

    /// Of the guards in `asked` (bit g for guard g of the polygon whose blocks start at
    /// `first_block`), those whose boxes `line` may meet: line_may_meet_box's answer for each.
    std::uint32_t met(const LineProbe& line, std::uint32_t first_block, std::uint32_t asked) const {
#if defined(__AVX__)
        if (!line.any_parallel) {
            std::uint32_t found = 0;
            // Shifted as 64 bits: past the eighth block the shift reaches 32.
            for (std::uint32_t block = 0; (std::uint64_t{asked} >> (kLanes * block)) != 0;
                 ++block) {
                if (((asked >> (kLanes * block)) & 0xfu) != 0) {
                    found |= met_by_lanes(line, blocks_[first_block + block]) << (kLanes * block);
                }
            }
            return found & asked;
        }
#endif
        std::uint32_t found = 0;
        for (std::uint32_t bits = asked; bits != 0; bits &= bits - 1) {
            const auto g = static_cast<std::uint32_t>(std::countr_zero(bits));
            const Block& block = blocks_[first_block + g / kLanes];
            std::array<float, 6> box{};
            for (std::size_t plane = 0; plane < 6; ++plane) {
                box[plane] = block.plane[plane][g % kLanes];
            }
            if (line_may_meet_box(line, box.data())) {
                found |= std::uint32_t{1} << g;
            }
        }
        return found;
    }

    std::size_t memory_bytes() const {
        return blocks_.capacity() * sizeof(Block);
    }

private:
    struct alignas(16) Block {
        /// lo x, lo y, lo z, hi x, hi y, hi z; a lane past the polygon's guards stays 0 (its bit
        /// is never asked).
        std::array<std::array<float, kLanes>, 6> plane{};
    };

#if defined(__AVX__)
    /// Bit k: the line may meet lane k's box. As line_may_meet_box_sse2: x and y by min and
    /// max, z by a comparison, the near side by max and the far by min in that order, and a
    /// NaN comparison counting as a meeting.
    static std::uint32_t met_by_lanes(const LineProbe& line, const Block& b) {
        const Slabs x = slabs(line, b, 0);
        const Slabs y = slabs(line, b, 1);
        const Slabs z = slabs(line, b, 2);
        const __m256d z_first = _mm256_cmp_pd(z.lo, z.hi, _CMP_LT_OQ);
        const __m256d z_low = _mm256_blendv_pd(z.hi, z.lo, z_first);
        const __m256d z_high = _mm256_blendv_pd(z.lo, z.hi, z_first);
        const __m256d near = _mm256_max_pd(
            _mm256_max_pd(_mm256_min_pd(x.lo, x.hi), _mm256_min_pd(y.lo, y.hi)), z_low);
        const __m256d far = _mm256_min_pd(
            _mm256_min_pd(_mm256_max_pd(x.lo, x.hi), _mm256_max_pd(y.lo, y.hi)), z_high);
        const int missed = _mm256_movemask_pd(_mm256_cmp_pd(near, far, _CMP_GT_OQ));
        return static_cast<std::uint32_t>(~missed) & 0xfu;
    }
    /// Where the line meets the four boxes' lo and hi planes of `axis`.
    struct Slabs {
        __m256d lo;
        __m256d hi;
    };
    static Slabs slabs(const LineProbe& line, const Block& b, int axis) {
        const __m256d origin = _mm256_set1_pd(line.origin[axis]);
        const __m256d inverse = _mm256_set1_pd(line.inverse[axis]);
        const auto a = static_cast<std::size_t>(axis);
        const __m256d lo = _mm256_cvtps_pd(_mm_load_ps(b.plane[a].data()));
        const __m256d hi = _mm256_cvtps_pd(_mm_load_ps(b.plane[3 + a].data()));
        return {_mm256_mul_pd(_mm256_sub_pd(lo, origin), inverse),
                _mm256_mul_pd(_mm256_sub_pd(hi, origin), inverse)};
    }
#endif

    std::vector<Block> blocks_;
};

}  // namespace rt
