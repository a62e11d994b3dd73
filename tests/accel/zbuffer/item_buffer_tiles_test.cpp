// An item buffer of tiles (ZBufferSettings::tile_side, exit culling's eye rays) must list in each
// tile every polygon the buffer of single pixels lists in any of the tile's pixels, nearest
// first, and not many more: on every viewed scene, with tiles that do not divide the view.
#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "rt/accel/zbuffer/item_buffer.h"

#include <gtest/gtest.h>

#include "accel/viewed_scenes.h"

namespace rt::test {
namespace {

// The polygons of a pixel's list.
std::vector<std::uint32_t> polygons_of(const ItemBuffer& buffer, int x, int y) {
    std::vector<std::uint32_t> polygons;
    for (const std::uint32_t rank : buffer.candidates(x, y)) {
        polygons.push_back(buffer.polygon(rank));
    }
    return polygons;
}

class ItemBufferTiles : public ::testing::TestWithParam<std::string> {};

TEST_P(ItemBufferTiles, EachTileHoldsItsPixelsLists) {
    const ViewedScene viewed = viewed_scene(GetParam());
    const Camera view = viewed.scene.view.camera();
    const ItemBuffer pixels(viewed.scene, view, {});
    ASSERT_TRUE(pixels.active()) << pixels.inactive_reason();
    for (const int side : {3, 8}) {
        ZBufferSettings settings;
        settings.tile_side = side;
        const ItemBuffer tiles(viewed.scene, view, settings);
        ASSERT_TRUE(tiles.active()) << tiles.inactive_reason();
        EXPECT_LE(tiles.entries(), pixels.entries());
        for (int y = 0; y < view.height; ++y) {
            for (int x = 0; x < view.width; ++x) {
                const std::vector<std::uint32_t> tile = polygons_of(tiles, x, y);
                // Nearest first, as the query's early stop needs.
                const std::span<const std::uint32_t> ranks = tiles.candidates(x, y);
                ASSERT_TRUE(std::is_sorted(ranks.begin(), ranks.end()));
                const std::set<std::uint32_t> listed(tile.begin(), tile.end());
                for (const std::uint32_t id : polygons_of(pixels, x, y)) {
                    ASSERT_TRUE(listed.contains(id)) << "pixel " << x << ", " << y << ": polygon "
                                                     << id << ", tiles of " << side;
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Views, ItemBufferTiles, ::testing::ValuesIn(viewed_scene_names()),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
}  // namespace rt::test
