#include "rt/core/huge_pages.h"

#include <cstdint>
#include <limits>
#include <new>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(HugePages, ReserveHugeMakesRoomAndKeepsTheElements) {
    std::vector<std::uint32_t> values{1, 2, 3};
    const std::size_t big = (kHugePageWorthwhile / sizeof(std::uint32_t)) * 3;
    reserve_huge(values, big);
    EXPECT_GE(values.capacity(), big);
    EXPECT_EQ(values, (std::vector<std::uint32_t>{1, 2, 3}));
    values.resize(big);
    std::iota(values.begin(), values.end(), 0u);
    EXPECT_EQ(values[big - 1], big - 1);
}

// Room that, with the 24 bytes malloc adds, fills whole 2 MiB pages: such a block is mapped on a
// huge-page boundary, so all of it can be huge pages (huge_pages.h).
TEST(HugePages, WholeHugePagesRoomFillsThemWithMallocsBytes) {
    constexpr std::size_t kHugePage = std::size_t{2} << 20;
    struct Record {
        char bytes[72];
    };
    for (const std::size_t n : {kHugePageWorthwhile / sizeof(Record) + 1, std::size_t{1'000'000},
                                std::size_t{129'127}, (std::size_t{9} << 20) / sizeof(Record)}) {
        const std::size_t room = huge_room<Record>(n);
        EXPECT_GE(room, n);
        const std::size_t bytes = room * sizeof(Record) + 24;
        const std::size_t whole = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        EXPECT_LT(whole - bytes, sizeof(Record)) << n;  // no room for one more
        EXPECT_LT(room * sizeof(Record), n * sizeof(Record) + kHugePage) << n;
    }
    EXPECT_EQ(huge_room<std::uint32_t>(1000), 1000u);  // small room: as asked
    struct alignas(64) Line {
        char bytes[64];
    };
    EXPECT_EQ(huge_room<Line>(1'000'000), 1'000'000u);  // not malloc's usual block
    EXPECT_EQ(huge_room<Record>(kHugePageWorthwhile / sizeof(Record)),
              kHugePageWorthwhile / sizeof(Record));  // just under 4 MiB: as asked

    std::vector<std::uint64_t> v{5, 6};
    reserve_whole_huge_pages(v, 1'000'000);
    EXPECT_EQ(v.capacity(), huge_room<std::uint64_t>(1'000'000));
    EXPECT_EQ(v, (std::vector<std::uint64_t>{5, 6}));
    reserve_whole_huge_pages(v, 10);  // never shrinks
    EXPECT_EQ(v.capacity(), huge_room<std::uint64_t>(1'000'000));
    std::vector<std::uint64_t> exact;
    reserve_huge(exact, 1'000'000);  // an accelerator's: its capacity is its memory
    EXPECT_EQ(exact.capacity(), 1'000'000u);
}

TEST(HugePages, ReserveHugeNeverShrinks) {
    std::vector<double> values(100, 1.5);
    values.reserve(1000);
    reserve_huge(values, 10);
    EXPECT_EQ(values.capacity(), 1000u);
    EXPECT_EQ(values.size(), 100u);
}

TEST(HugePages, MoveToHugePagesKeepsTheElementsAndFitsThem) {
    std::vector<std::uint32_t> big(kHugePageWorthwhile / sizeof(std::uint32_t) + 5);
    std::iota(big.begin(), big.end(), 7u);
    big.reserve(big.size() * 2);
    const std::vector<std::uint32_t> before = big;
    move_to_huge_pages(big);
    EXPECT_EQ(big, before);
    EXPECT_EQ(big.capacity(), big.size());

    std::vector<std::uint32_t> small{3, 1, 2};
    small.reserve(100);
    move_to_huge_pages(small);  // too small to be worth moving: left as it is
    EXPECT_EQ(small, (std::vector<std::uint32_t>{3, 1, 2}));
    EXPECT_EQ(small.capacity(), 100u);
}

TEST(HugePages, AdviceOnSmallOrNullMemoryIsHarmless) {
    advise_huge_pages(nullptr, 0);
    advise_huge_pages(nullptr, kHugePageWorthwhile * 2);
    int small = 7;
    advise_huge_pages(&small, sizeof(small));
    EXPECT_EQ(small, 7);
}

// Big room on a 2 MiB boundary, so that all of it may be huge pages; small room as usual. Both are
// given back through the allocator (the sanitized build checks the pairing).
TEST(HugePages, TheAllocatorPutsBigRoomOnHugePageBoundaries) {
    constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
    std::vector<std::uint64_t, HugePageAllocator<std::uint64_t>> big;
    big.reserve(kHugeAllocation / sizeof(std::uint64_t) + 3);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % kHugePage, 0u);
    big.resize(big.capacity());
    std::iota(big.begin(), big.end(), std::uint64_t{11});
    EXPECT_EQ(big.back(), std::uint64_t{11} + big.size() - 1);
    big.push_back(1);  // grows: new huge room, the old given back
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % kHugePage, 0u);
    EXPECT_EQ(big[5], 16u);

    std::vector<int, HugePageAllocator<int>> small{4, 5, 6};
    small.shrink_to_fit();
    EXPECT_EQ(small, (std::vector<int, HugePageAllocator<int>>{4, 5, 6}));

    HugePageAllocator<char> bytes;
    EXPECT_THROW(static_cast<void>(bytes.allocate(std::numeric_limits<std::size_t>::max() - 16)),
                 std::bad_alloc);
}

}  // namespace
}  // namespace rt
