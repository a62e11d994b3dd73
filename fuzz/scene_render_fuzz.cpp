// A whole scene folder (scene_folder.h) loaded as rt loads it, then a 4 x 3 pixel window with one
// sample a pixel rendered with every intersection method and layer. Every method must give brute
// force's picture float for float, or every method must refuse the scene (docs/accelerators.md:
// every method answers every ray as brute force does). Embree, which intersects in single
// precision, only has to answer. Sizes the header asks for are capped (maxdepth 4, octree depth
// 8, SEADS 24 voxels a side) so that one input takes milliseconds, not seconds.
#include <algorithm>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "rt/accel/accelerator_stack.h"
#include "rt/accel/make_accelerator.h"
#include "rt/core/diagnostics.h"
#include "rt/render/renderer.h"
#include "rt/scene/read/load_scene.h"

#include "fuzz_input.h"
#include "scene_folder.h"

namespace {

using namespace rt;

constexpr int kMaxDepth = 4;
constexpr int kMaxOctreeDepth = 8;
constexpr int kMaxSeadsVoxels = 24;

struct Method {
    std::string name;
    AcceleratorStackSettings settings;
};

AcceleratorStackSettings stack_of(AccelKind kind, bool culling, bool zbuffer) {
    AcceleratorStackSettings settings;
    settings.method.kind = kind;
    settings.exit_culling = culling;
    settings.zbuffer_first_hits = zbuffer;
    return settings;
}

// Brute force without layers first: the reference.
std::vector<Method> every_method(const Scene& scene) {
    std::vector<Method> methods;
    const struct {
        const char* name;
        AccelKind kind;
    } kinds[] = {{"brute", AccelKind::BruteForce},
                 {"octree", AccelKind::Octree},
                 {"octree -op", AccelKind::Octree},
                 {"seads", AccelKind::Seads},
                 {"bvh", AccelKind::Bvh}};
    for (const auto& kind : kinds) {
        for (const bool culling : {false, true}) {
            for (const bool zbuffer : {false, true}) {
                Method m{std::string(kind.name) + (culling ? "" : " -De") +
                             (zbuffer ? " --zbuffer" : ""),
                         stack_of(kind.kind, culling, zbuffer)};
                m.settings.method = method_for_scene(scene, m.settings.method);
                m.settings.method.octree.level_order = m.name.starts_with("octree -op");
                m.settings.method.octree.threads = 1;
                if (m.settings.method.octree.depth) {
                    m.settings.method.octree.depth =
                        std::min(*m.settings.method.octree.depth, kMaxOctreeDepth);
                }
                if (m.settings.method.seads_resolution) {
                    m.settings.method.seads_resolution =
                        std::min(*m.settings.method.seads_resolution, kMaxSeadsVoxels);
                }
                methods.push_back(std::move(m));
            }
        }
    }
    return methods;
}

// The picture, or nothing when the method refuses the scene (why goes to `refusal`).
std::optional<std::vector<float>> picture_with(const Scene& scene,
                                               const AcceleratorStackSettings& settings,
                                               const RenderSettings& render_settings,
                                               std::string& refusal) {
    try {
        const AcceleratorStack stack(scene, settings, AccelMessages{});
        RenderObserver silent;
        RenderStatistics statistics;
        return render(scene, stack.top(), render_settings, silent, statistics).data();
    } catch (const Error& e) {
        refusal = e.what();
        return std::nullopt;
    }
}

bool same_floats(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// The scene as rt reads it, or nothing when the readers refuse it.
std::optional<Scene> load(const fuzz::SceneFolder& folder, const ReaderDialect& dialect) {
    fuzz::clear_scratch_folder();
    for (const fuzz::FolderFile& file : folder.files) {
        fuzz::write_scratch_file(file.name, file.bytes);
    }
    const std::filesystem::path scn = fuzz::write_scratch_file("fuzz.scn", folder.scn);
    try {
        Diagnostics diagnostics;
        return load_scene(scn, dialect, diagnostics);
    } catch (const InputError& e) {
        fuzz::check_input_error(e, fuzz::Where::File);
        fuzz::tell(std::string("refused by the readers: ") + e.what());
        return std::nullopt;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const fuzz::SceneFolder folder = fuzz::split_scene_folder(fuzz::as_text(data, size));
    const ReaderDialect dialect = fuzz::dialect_from_switches(folder.switches);
    std::optional<Scene> scene = load(folder, dialect);
    if (!scene) {
        return 0;
    }
    // The same camera, 4 x 3 pixels, one sample each.
    scene->view.width = 4;
    scene->view.height = 3;
    scene->view.window = {0, 0, 3, 2};
    scene->view.sample_resolution_x = 1;
    scene->view.sample_resolution_y = 1;
    scene->header.maxdepth = std::min(scene->header.maxdepth, kMaxDepth);
    RenderSettings render_settings;
    render_settings.shading.smooth_shaded_opaque = folder.switches.find("-Po") != std::string::npos;
    render_settings.window = scene->view.window;
    render_settings.threads = 1;

    const std::vector<Method> methods = every_method(*scene);
    std::string brute_refusal;
    const std::optional<std::vector<float>> brute =
        picture_with(*scene, methods.front().settings, render_settings, brute_refusal);
    for (std::size_t i = 1; i < methods.size(); ++i) {
        std::string refusal;
        const std::optional<std::vector<float>> picture =
            picture_with(*scene, methods[i].settings, render_settings, refusal);
        if (brute && !picture) {
            fuzz::finding(methods[i].name + " refuses a scene brute force renders: " + refusal);
        }
        if (!brute && picture) {
            fuzz::finding(methods[i].name +
                          " renders a scene brute force refuses: " + brute_refusal);
        }
        if (brute && picture && !same_floats(*brute, *picture)) {
            fuzz::finding(methods[i].name + " draws another picture than brute force");
        }
    }
    fuzz::tell(brute ? "every method draws brute force's picture"
                     : "every method refuses the scene: " + brute_refusal);
    // Embree (when built) only has to answer: a picture or a refusal.
    std::string ignored;
    (void)picture_with(*scene, stack_of(AccelKind::Embree, true, false), render_settings, ignored);
    return 0;
}
