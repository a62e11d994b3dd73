#include "rt/scene/read/edge_loop.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

using Loop = std::vector<std::uint32_t>;

TEST(ChainEdges, ListedOrderInEitherOrientation) {
    EXPECT_EQ(chain_edges(std::vector<Edge>{{0, 1}, {1, 2}, {2, 3}, {3, 0}}), (Loop{0, 1, 2, 3}));
    EXPECT_EQ(chain_edges(std::vector<Edge>{{1, 0}, {2, 1}, {3, 2}, {0, 3}}), (Loop{0, 1, 2, 3}));
    EXPECT_EQ(chain_edges(std::vector<Edge>{{0, 1}, {2, 1}, {2, 3}, {0, 3}}), (Loop{0, 1, 2, 3}));
    // The first edge turned round to meet the second.
    EXPECT_EQ(chain_edges(std::vector<Edge>{{0, 1}, {0, 3}, {3, 2}, {2, 1}}), (Loop{1, 0, 3, 2}));
    EXPECT_EQ(chain_edges(std::vector<Edge>{{5, 6}, {7, 5}, {6, 7}}), (Loop{6, 5, 7}));
}

TEST(ChainEdges, AssemblesALoopListedOutOfOrder) {
    EXPECT_EQ(chain_edges(std::vector<Edge>{{0, 1}, {2, 3}, {1, 2}, {3, 0}}), (Loop{0, 1, 2, 3}));
    EXPECT_EQ(chain_edges(std::vector<Edge>{{0, 1}, {3, 4}, {4, 0}, {2, 3}, {1, 2}}),
              (Loop{0, 1, 2, 3, 4}));
}

TEST(ChainEdges, RefusesWhatIsNotOneClosedLoop) {
    EXPECT_TRUE(chain_edges(std::vector<Edge>{{0, 1}, {1, 2}, {2, 3}}).empty());  // open
    EXPECT_TRUE(chain_edges(std::vector<Edge>{{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}})
                    .empty());  // two loops
    EXPECT_TRUE(chain_edges(std::vector<Edge>{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {3, 4}, {4, 0}})
                    .empty());  // a figure of eight
    EXPECT_TRUE(chain_edges(std::vector<Edge>{{0, 1}, {1, 0}}).empty());
    EXPECT_TRUE(chain_edges(std::vector<Edge>{{0, 1}, {1, 2}, {1, 2}}).empty());
}

}  // namespace
}  // namespace rt
