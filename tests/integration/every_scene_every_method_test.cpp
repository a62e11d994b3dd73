// Every shipped scene, rendered with every intersection method, with and without exit culling and
// with the z-buffer on top, must give brute force's picture exactly: every method answers every
// ray as brute force does (docs/accelerators.md), so every float of the film must agree. The
// views are shrunk, to at most a quarter of their width and height and about kSampleBudget eye
// rays (fewer for a scene of many polygons, whose brute force is slow: kWorkBudget), to keep the
// test to seconds; every object is still in the picture, with its reflections, refractions and
// shadow feelers. A scene with texture-mapped surfaces after its entities (the warning "read only
// with -V" without it) is drawn with -V, so that they are in the picture too.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "rt/accel/accelerator_stack.h"
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

namespace fs = std::filesystem;

constexpr int kLeastShrink = 4;          ///< the view's width and height are divided by this...
constexpr double kSampleBudget = 16000;  ///< ... or more, to keep to about this many eye rays
/// ... and eye rays times polygons to about this (scenes up to 256 polygons keep kSampleBudget)
constexpr double kWorkBudget = kSampleBudget * 256;

// The switches of every method, below the switches that add layers over it.
const std::vector<std::vector<std::string>> kMethods = {
    {"--accel", "octree"}, {"--accel", "octree", "-op"}, {"--accel", "seads"},
    {"--accel", "bvh"},    {"--accel", "brute"},
};
const std::vector<std::vector<std::string>> kLayers = {{}, {"-De"}, {"--zbuffer"}};

std::vector<fs::path> shipped_scenes() {
    std::vector<fs::path> scenes;
    for (const fs::directory_entry& entry : fs::directory_iterator(source_dir() / "scenes")) {
        if (entry.path().extension() == ".scn") {
            scenes.push_back(entry.path());
        }
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

// The view area and output matrix shrunk: the same camera, fewer pixels.
void shrink_view(Scene& scene) {
    SceneView& view = scene.view;
    const double samples = static_cast<double>(view.width) * view.height *
                           view.sample_resolution_x * view.sample_resolution_y;
    const double polygons = std::max<double>(1.0, static_cast<double>(scene.polygons.size()));
    const double budget = std::min(kSampleBudget, kWorkBudget / polygons);
    const int shrink =
        std::max(kLeastShrink, static_cast<int>(std::ceil(std::sqrt(samples / budget))));
    view.width = std::max(1, view.width / shrink);
    view.height = std::max(1, view.height / shrink);
    view.window = {view.window.left / shrink, view.window.top / shrink,
                   std::min(view.width - 1, view.window.right / shrink),
                   std::min(view.height - 1, view.window.bottom / shrink)};
}

std::vector<float> render_with(const Scene& scene, const fs::path& path,
                               const std::vector<std::string>& switches) {
    std::vector<std::string> args = {path.string()};
    args.insert(args.end(), switches.begin(), switches.end());
    const Options options = parse_command_line(args);
    RenderSettings settings;
    settings.shading = run_shading(options);
    settings.window = film_window(scene.view.window, options.start_line);
    const AcceleratorStack stack(scene, options.accel, AccelMessages{});
    RenderObserver silent;
    RenderStatistics statistics;
    return render(scene, stack.top(), settings, silent, statistics).data();
}

// The scene as drawn: with -V when it has texture-mapped surfaces, which -V alone reads.
Scene load_whole(const fs::path& path, std::vector<std::string>& scene_switches) {
    Diagnostics diagnostics;
    Scene scene = load_scene(path, ReaderDialect{}, diagnostics);
    const std::vector<std::string>& warnings = diagnostics.warnings();
    if (std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
            return w.find("texture-mapped surfaces are read only with -V") != std::string::npos;
        })) {
        scene_switches.push_back("-V");
        ReaderDialect textures;
        textures.textures = true;
        scene = load_scene(path, textures, diagnostics);
        EXPECT_FALSE(scene.texture_cells.empty());
    }
    return scene;
}

std::string joined(const std::vector<std::string>& switches) {
    std::string text;
    for (const std::string& s : switches) {
        text += (text.empty() ? "" : " ") + s;
    }
    return text;
}

TEST(EverySceneEveryMethod, DrawsBruteForcesPicture) {
    const std::vector<fs::path> scenes = shipped_scenes();
    ASSERT_GE(scenes.size(), 4u);
    int textured = 0;
    for (const fs::path& path : scenes) {
        SCOPED_TRACE(path.filename().string());
        std::vector<std::string> scene_switches;
        Scene scene = load_whole(path, scene_switches);
        textured += scene.texture_cells.empty() ? 0 : 1;
        shrink_view(scene);
        std::vector<std::string> brute_switches = scene_switches;
        brute_switches.insert(brute_switches.end(), {"--accel", "brute", "-De"});
        const std::vector<float> brute = render_with(scene, path, brute_switches);
        ASSERT_FALSE(brute.empty());
        ASSERT_TRUE(std::any_of(brute.begin(), brute.end(), [](float v) { return v > 0.0f; }))
            << "a black picture would prove nothing";
        for (const std::vector<std::string>& method : kMethods) {
            for (const std::vector<std::string>& layer : kLayers) {
                std::vector<std::string> switches = scene_switches;
                switches.insert(switches.end(), method.begin(), method.end());
                switches.insert(switches.end(), layer.begin(), layer.end());
                SCOPED_TRACE(joined(switches));
                const std::vector<float> picture = render_with(scene, path, switches);
                ASSERT_EQ(picture.size(), brute.size());
                const auto differ = std::mismatch(picture.begin(), picture.end(), brute.begin());
                EXPECT_TRUE(differ.first == picture.end())
                    << "first difference at float " << (differ.first - picture.begin()) << ": "
                    << *differ.first << " against " << *differ.second;
            }
        }
    }
    EXPECT_GE(textured, 2) << "lens.scn and twocubes.scn have texture-mapped surfaces";
}

}  // namespace
}  // namespace rt::test
