// The queries of a real render (eye rays in packets, reflections and refractions from surfaces,
// shadow feelers), recorded and asked again: the recorder passes every query on unchanged, a
// replay asks exactly what was recorded, and every method answers the recorded rays as brute
// force does. rt_scene_bench --replay times the methods on such rays.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/accel/accelerator_stack.h"
#include "rt/accel/brute_force.h"
#include "rt/accel/debug/query_recorder.h"
#include "rt/app/run_settings.h"
#include "rt/app/switch_parser.h"
#include "rt/core/diagnostics.h"
#include "rt/render/film_window.h"
#include "rt/render/renderer.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt::test {
namespace {

struct Answer {
    std::size_t query = 0;
    int lane = 0;
    std::optional<Hit> hit;
    bool blocked = false;
};

std::vector<Answer> answers_of(const RecordedQueries& recorded, const Accelerator& accel) {
    std::vector<Answer> answers;
    TraceCounters counters;
    replay_queries(recorded, 0, recorded.queries.size(), accel, counters,
                   [&](std::size_t query, int lane, const std::optional<Hit>& hit, bool blocked) {
                       answers.push_back({query, lane, hit, blocked});
                   });
    return answers;
}

class QueryReplay : public ::testing::Test {
protected:
    void SetUp() override {
        path_ = (source_dir() / "scenes" / "twocubes.scn").string();
        Diagnostics diagnostics;
        scene_ = load_scene(path_, ReaderDialect{}, diagnostics);
        // A third of the view each way: every object, its reflections and shadows, in a second.
        SceneView& view = scene_.view;
        view.width /= 3;
        view.height /= 3;
        view.window = {0, 0, view.width - 1, view.height - 1};
    }

    Options options_for(std::vector<std::string> switches) const {
        switches.insert(switches.begin(), path_);
        return parse_command_line(switches);
    }

    // One render through a recorder over the stack the switches describe, on one thread.
    RecordedQueries record(const std::vector<std::string>& switches, Film* film = nullptr) {
        const Options options = options_for(switches);
        RenderSettings settings;
        settings.shading = run_shading(options);
        settings.window = film_window(scene_.view.window, options.start_line);
        settings.threads = 1;
        const AcceleratorStack stack(scene_, options.accel, AccelMessages{});
        QueryRecorder recorder(stack.top());
        RenderObserver silent;
        RenderStatistics statistics;
        Film rendered = render(scene_, recorder, settings, silent, statistics);
        if (film != nullptr) {
            *film = std::move(rendered);
        }
        return recorder.take();
    }

    std::string path_;
    Scene scene_;
};

TEST_F(QueryReplay, RecordsEveryKindOfQueryARenderAsks) {
    const RecordedQueries recorded = record({"--accel", "bvh"});
    ASSERT_FALSE(recorded.queries.empty());
    ASSERT_EQ(recorded.rays.size(), recorded.t.size());
    std::uint64_t lanes = 0;
    std::vector<int> kinds(6, 0);
    for (const RecordedQuery& query : recorded.queries) {
        ++kinds[static_cast<std::size_t>(query.kind)];
        const bool packet = query.kind == QueryKind::ClosestPacket ||
                            query.kind == QueryKind::EyeClosestPacket ||
                            query.kind == QueryKind::OccludedPacket;
        ASSERT_LE(query.first + (packet ? kPacketSize : 1), recorded.rays.size());
        lanes += packet ? static_cast<std::uint64_t>(__builtin_popcount(query.active)) : 1;
    }
    EXPECT_EQ(lanes, recorded.rays_asked);
    EXPECT_EQ(recorded.rays_asked, answers_of(recorded, BruteForce(scene_)).size());
    // Eye rays go in packets, reflections from surfaces one at a time.
    EXPECT_GT(kinds[static_cast<std::size_t>(QueryKind::EyeClosestPacket)], 0);
    EXPECT_GT(kinds[static_cast<std::size_t>(QueryKind::Closest)], 0);
}

TEST_F(QueryReplay, ReplayAsksWhatTheRenderAskedAndGetsItsAnswers) {
    // Recorded over a recorder over brute force: the inner recorder's copy is what the outer one
    // passed on, query for query, and replaying the outer copy asks the same again.
    const Options options = options_for({"--accel", "brute", "-De"});
    const AcceleratorStack stack(scene_, options.accel, AccelMessages{});
    QueryRecorder inner(stack.top());
    const Accelerator& beneath = inner;  // not the (deleted) copy constructor
    QueryRecorder outer(beneath);
    RenderSettings settings;
    settings.shading = run_shading(options);
    settings.window = film_window(scene_.view.window, options.start_line);
    settings.threads = 1;
    RenderObserver silent;
    RenderStatistics statistics;
    render(scene_, outer, settings, silent, statistics);
    const RecordedQueries asked = outer.take();
    const RecordedQueries passed_on = inner.take();
    ASSERT_EQ(asked.queries.size(), passed_on.queries.size());
    ASSERT_EQ(asked.rays.size(), passed_on.rays.size());
    for (std::size_t q = 0; q < asked.queries.size(); ++q) {
        ASSERT_EQ(asked.queries[q].kind, passed_on.queries[q].kind) << "query " << q;
        ASSERT_EQ(asked.queries[q].active, passed_on.queries[q].active) << "query " << q;
    }
    for (std::size_t r = 0; r < asked.rays.size(); ++r) {
        ASSERT_TRUE(asked.rays[r].origin == passed_on.rays[r].origin &&
                    asked.rays[r].direction == passed_on.rays[r].direction &&
                    asked.t[r].min == passed_on.t[r].min && asked.t[r].max == passed_on.t[r].max)
            << "ray " << r;
    }
    QueryRecorder again(stack.top());
    TraceCounters counters;
    replay_queries(asked, 0, asked.queries.size(), again, counters);
    const RecordedQueries replayed = again.take();
    ASSERT_EQ(replayed.queries.size(), asked.queries.size());
    EXPECT_EQ(replayed.rays_asked, asked.rays_asked);
    EXPECT_TRUE(std::equal(replayed.rays.begin(), replayed.rays.end(), asked.rays.begin(),
                           [](const Ray& a, const Ray& b) {
                               return a.origin == b.origin && a.direction == b.direction;
                           }));
}

TEST_F(QueryReplay, EveryMethodAnswersARendersRaysAsBruteForce) {
    const RecordedQueries recorded = record({"--accel", "brute", "-De"});
    const std::vector<Answer> brute = answers_of(recorded, BruteForce(scene_));
    const auto hits = std::count_if(brute.begin(), brute.end(),
                                    [](const Answer& a) { return a.hit.has_value(); });
    ASSERT_GT(hits, 1000) << "a render that hits nothing would prove nothing";
    ASSERT_LT(hits, static_cast<std::ptrdiff_t>(brute.size()))
        << "and so would one that misses nothing";
    const std::vector<std::vector<std::string>> stacks = {
        {"--accel", "octree"}, {"--accel", "octree", "-De"}, {"--accel", "seads", "-De"},
        {"--accel", "bvh"},    {"--accel", "bvh", "-De"},    {"--accel", "bvh", "--zbuffer"},
    };
    for (const std::vector<std::string>& switches : stacks) {
        std::string name;
        for (const std::string& s : switches) {
            name += s + " ";
        }
        SCOPED_TRACE(name);
        const AcceleratorStack stack(scene_, options_for(switches).accel, AccelMessages{});
        const std::vector<Answer> answers = answers_of(recorded, stack.top());
        ASSERT_EQ(answers.size(), brute.size());
        for (std::size_t i = 0; i < answers.size(); ++i) {
            const Answer& a = answers[i];
            const Answer& b = brute[i];
            ASSERT_EQ(a.hit.has_value(), b.hit.has_value())
                << "query " << a.query << " lane " << a.lane;
            if (a.hit) {
                ASSERT_EQ(a.hit->t, b.hit->t) << "query " << a.query << " lane " << a.lane;
                ASSERT_EQ(a.hit->polygon, b.hit->polygon) << "query " << a.query;
            }
            ASSERT_EQ(a.blocked, b.blocked) << "query " << a.query << " lane " << a.lane;
        }
    }
}

}  // namespace
}  // namespace rt::test
