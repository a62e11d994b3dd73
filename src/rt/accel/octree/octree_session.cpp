#include "rt/accel/octree/octree_session.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "rt/accel/octree/octree_ddda.h"
#include "rt/accel/voxel/box.h"
#include "rt/core/text.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

namespace rt {

namespace {

// A command the session cannot carry out; its text is printed and the session goes on.
class CommandError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A node and the lattice cube it covers (the finest lattice, 2^depth a side).
struct Place {
    std::uint32_t node = 0;
    std::array<std::int64_t, 3> origin{};
    std::int64_t size = 1;
};

// "1 polygon", "3 polygons", "2 leaves".
std::string count_of(std::uint64_t n, std::string_view one, std::string_view many = {}) {
    if (n == 1) {
        return fmt::format("1 {}", one);
    }
    return many.empty() ? fmt::format("{} {}s", n, one) : fmt::format("{} {}", n, many);
}

std::string point_text(const Vec3& p) {
    return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x, p.y, p.z);
}

std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t at = 0;
    while (at < line.size()) {
        const std::size_t start = line.find_first_not_of(" \t\r", at);
        if (start == std::string_view::npos) {
            break;
        }
        const std::size_t end = std::min(line.find_first_of(" \t\r", start), line.size());
        words.push_back(line.substr(start, end - start));
        at = end;
    }
    return words;
}

double number(std::string_view command, std::string_view word) {
    const std::optional<double> value = parse_double(word);
    if (!value) {
        throw CommandError(cat({command, ": expected a number, found ", quote_token(word)}));
    }
    return *value;
}

class Session {
public:
    Session(const Scene& scene, const Octree& octree, std::ostream& out)
        : scene_(scene), octree_(octree), tree_(octree.tree()), out_(out) {
        path_.push_back({0, {0, 0, 0}, std::int64_t{1} << tree_.depth});
    }

    void banner() const {
        const auto leaves = std::count_if(tree_.nodes.begin(), tree_.nodes.end(),
                                          [](const OctreeNode& n) { return n.is_leaf(); });
        fmt::print(out_,
                   "octree: depth {}, {} nodes ({} leaves), {} polygons, world {} to {}\n"
                   "'help' lists the commands; 'quit' or the end of the input ends the session\n",
                   tree_.depth, tree_.nodes.size(), leaves, scene_.polygons.size(),
                   point_text(tree_.world.lo), point_text(tree_.world.hi));
    }

    // Carries out one line; false when the session should end.
    bool execute(std::string_view line);

private:
    void help(std::span<const std::string_view> args);
    void node(std::span<const std::string_view> args);
    void child(std::span<const std::string_view> args);
    void up(std::span<const std::string_view> args);
    void root(std::span<const std::string_view> args);
    void list(std::span<const std::string_view> args);
    void find(std::span<const std::string_view> args);
    void ray(std::span<const std::string_view> args);
    void pixel(std::span<const std::string_view> args);

    struct Command {
        std::string_view name;
        std::string_view arguments;
        std::string_view help;
        void (Session::*run)(std::span<const std::string_view>);
        std::size_t arity;
    };
    static const std::array<Command, 9>& commands();

    const OctreeNode& at(const Place& p) const { return tree_.nodes[p.node]; }
    Box3 box_of(const Place& p) const;
    std::string path_text(const std::vector<Place>& path) const;
    std::string describe(const std::vector<Place>& path) const;
    std::vector<Place> path_to(const std::array<std::int64_t, 3>& cell) const;
    void walk(const Ray& ray);
    std::string exit_face(const Ray& ray, const OctreeLeafAt& leaf) const;

    const Scene& scene_;
    const Octree& octree_;
    const OctreeTree& tree_;
    std::ostream& out_;
    std::vector<Place> path_;  // from the root to the current node
};

const std::array<Session::Command, 9>& Session::commands() {
    static constexpr std::array<Command, 9> kCommands{{
        {"help", "", "this list", &Session::help, 0},
        {"node", "", "the current node: where it is, its box, leaf or children", &Session::node, 0},
        {"child", "N", "go down to the child in octant N (0-7: bit 0 +x, bit 1 +y, bit 2 +z)",
         &Session::child, 1},
        {"up", "", "back up to the parent", &Session::up, 0},
        {"root", "", "back to the root", &Session::root, 0},
        {"list", "", "the current node's box and its polygons (a leaf's, or all below it)",
         &Session::list, 0},
        {"find", "X Y Z", "go to the leaf that holds the point", &Session::find, 3},
        {"ray", "OX OY OZ DX DY DZ",
         "follow the ray through the leaves as the DDDA steps, and its hit", &Session::ray, 6},
        {"pixel", "X Y", "the same for the eye ray through the pixel's centre", &Session::pixel, 2},
    }};
    return kCommands;
}

bool Session::execute(std::string_view line) {
    const std::vector<std::string_view> words = words_of(line);
    if (words.empty() || words[0].starts_with('#')) {
        return true;
    }
    if (words[0] == "quit" || words[0] == "exit") {
        return false;
    }
    for (const Command& c : commands()) {
        if (c.name == words[0]) {
            if (words.size() - 1 != c.arity) {
                throw CommandError(fmt::format("{}: expected {} argument{}{}, found {}", c.name,
                                               c.arity, c.arity == 1 ? "" : "s",
                                               c.arity == 0 ? "" : cat({" (", c.arguments, ")"}),
                                               words.size() - 1));
            }
            (this->*c.run)(std::span(words).subspan(1));
            return true;
        }
    }
    throw CommandError(
        cat({"unknown command ", quote_token(words[0]), "; 'help' lists the commands"}));
}

void Session::help(std::span<const std::string_view> /*args*/) {
    for (const Command& c : commands()) {
        fmt::print(out_, "  {:<24} {}\n", cat({c.name, " ", c.arguments}), c.help);
    }
    fmt::print(out_, "  {:<24} {}\n", "quit", "end the session (so does the end of the input)");
}

Box3 Session::box_of(const Place& p) const {
    Box3 box;
    for (int a = 0; a < 3; ++a) {
        box.lo[a] = tree_.lattice(a, p.origin[static_cast<std::size_t>(a)]);
        box.hi[a] = tree_.lattice(a, p.origin[static_cast<std::size_t>(a)] + p.size);
    }
    return box;
}

std::string Session::path_text(const std::vector<Place>& path) const {
    if (path.size() == 1) {
        return "the root";
    }
    std::string text = "path";
    for (std::size_t level = 1; level < path.size(); ++level) {
        text += fmt::format(" {}", path[level].node - at(path[level - 1]).first);
    }
    return text;
}

std::string Session::describe(const std::vector<Place>& path) const {
    const Place& p = path.back();
    const OctreeNode& n = at(p);
    const Box3 box = box_of(p);
    const std::string what = n.is_leaf()
                                 ? "leaf, " + count_of(n.count, "polygon")
                                 : fmt::format("interior, children {} to {}", n.first, n.first + 7);
    return fmt::format("node {}, {} (level {}): lattice ({}, {}, {}) side {}, box {} to {}; {}",
                       p.node, path_text(path), path.size() - 1, p.origin[0], p.origin[1],
                       p.origin[2], p.size, point_text(box.lo), point_text(box.hi), what);
}

void Session::node(std::span<const std::string_view> /*args*/) {
    fmt::print(out_, "{}\n", describe(path_));
}

void Session::child(std::span<const std::string_view> args) {
    const std::optional<std::int64_t> octant = parse_integer(args[0]);
    if (!octant || *octant < 0 || *octant > 7) {
        throw CommandError(
            cat({"child: expected an octant from 0 to 7, found ", quote_token(args[0])}));
    }
    const Place& here = path_.back();
    if (at(here).is_leaf()) {
        throw CommandError(fmt::format("child: node {} is a leaf, with no children", here.node));
    }
    Place next{at(here).first + static_cast<std::uint32_t>(*octant), here.origin, here.size / 2};
    for (std::size_t a = 0; a < 3; ++a) {
        next.origin[a] += ((*octant >> a) & 1) != 0 ? next.size : 0;
    }
    path_.push_back(next);
    node(args);
}

void Session::up(std::span<const std::string_view> args) {
    if (path_.size() == 1) {
        throw CommandError("up: already at the root");
    }
    path_.pop_back();
    node(args);
}

void Session::root(std::span<const std::string_view> args) {
    path_.resize(1);
    node(args);
}

void Session::list(std::span<const std::string_view> args) {
    node(args);
    const OctreeNode& n = at(path_.back());
    if (n.is_leaf()) {
        for (const std::uint32_t id : tree_.leaf_polygons(n)) {
            fmt::print(out_, "  polygon {} from {}, {} corners\n", id,
                       scene_.origin_of(id).to_string(), scene_.polygons[id].corner_count);
        }
        return;
    }
    // Every polygon filed in a leaf below, once each.
    std::vector<std::uint32_t> below;
    std::vector<std::uint32_t> pending{path_.back().node};
    while (!pending.empty()) {
        const OctreeNode& m = tree_.nodes[pending.back()];
        pending.pop_back();
        if (m.is_leaf()) {
            const std::span<const std::uint32_t> ids = tree_.leaf_polygons(m);
            below.insert(below.end(), ids.begin(), ids.end());
        } else {
            for (std::uint32_t c = 0; c < 8; ++c) {
                pending.push_back(m.first + c);
            }
        }
    }
    std::sort(below.begin(), below.end());
    below.erase(std::unique(below.begin(), below.end()), below.end());
    for (std::uint32_t c = 0; c < 8; ++c) {
        const OctreeNode& m = tree_.nodes[n.first + c];
        fmt::print(out_, "  octant {}: node {}, {}\n", c, n.first + c,
                   m.is_leaf() ? "leaf, " + count_of(m.count, "polygon") : "interior");
    }
    fmt::print(out_, "  {} polygons below: {}\n", below.size(), fmt::join(below, " "));
}

std::vector<Place> Session::path_to(const std::array<std::int64_t, 3>& cell) const {
    std::vector<Place> path{{0, {0, 0, 0}, std::int64_t{1} << tree_.depth}};
    while (!at(path.back()).is_leaf()) {
        const Place& here = path.back();
        const std::int64_t half = here.size / 2;
        Place next{at(here).first, here.origin, half};
        for (std::size_t a = 0; a < 3; ++a) {
            if (cell[a] >= here.origin[a] + half) {
                next.node += 1U << a;
                next.origin[a] += half;
            }
        }
        path.push_back(next);
    }
    return path;
}

void Session::find(std::span<const std::string_view> args) {
    const Vec3 p{number("find", args[0]), number("find", args[1]), number("find", args[2])};
    if (!tree_.world.contains(p)) {
        throw CommandError(fmt::format("find: {} is outside the octree's world, {} to {}",
                                       point_text(p), point_text(tree_.world.lo),
                                       point_text(tree_.world.hi)));
    }
    // The lattice cell as the DDDA reads it: floor, with the world's far faces in the last cell.
    const std::int64_t last = (std::int64_t{1} << tree_.depth) - 1;
    std::array<std::int64_t, 3> cell{};
    for (int a = 0; a < 3; ++a) {
        const double c = std::floor((p[a] - tree_.world.lo[a]) / tree_.step[a]);
        cell[static_cast<std::size_t>(a)] =
            std::clamp(static_cast<std::int64_t>(c), std::int64_t{0}, last);
    }
    path_ = path_to(cell);
    fmt::print(out_, "{} is in lattice cell ({}, {}, {})\n", point_text(p), cell[0], cell[1],
               cell[2]);
    node(args);
}

std::string Session::exit_face(const Ray& ray, const OctreeLeafAt& leaf) const {
    // The face the DDDA leaves by: the nearest of the three far faces along the ray.
    double nearest = std::numeric_limits<double>::infinity();
    std::string face = "?";
    for (int a = 0; a < 3; ++a) {
        if (ray.direction[a] == 0.0) {
            continue;
        }
        const bool forward = ray.direction[a] > 0.0;
        const std::int64_t plane = leaf.origin[a] + (forward ? leaf.size : 0);
        const double t = (tree_.lattice(a, plane) - ray.origin[a]) / ray.direction[a];
        if (t < nearest) {
            nearest = t;
            face = cat({forward ? "+" : "-", std::string_view("xyz").substr(a, 1)});
        }
    }
    return face;
}

void Session::walk(const Ray& ray) {
    fmt::print(out_, "ray from {} along {}\n", point_text(ray.origin), point_text(ray.direction));
    const Interval all{0.0, kBeyondAnyScene};
    Interval inside;
    if (!clip_to_box(ray, tree_.world, all, inside)) {
        fmt::print(out_, "misses the octree's world\n");
        return;
    }
    fmt::print(out_, "enters the world at t {:.6g}, leaves it at t {:.6g}\n", inside.min,
               inside.max);
    std::vector<double> step_exits;
    double entry = inside.min;
    walk_octree_inside(
        tree_, ray, inside,
        [&](std::span<const std::uint32_t> polygons, double t_exit, const OctreeLeafAt& leaf) {
            const auto index = static_cast<std::uint32_t>(leaf.node - tree_.nodes.data());
            const std::array<std::int64_t, 3> cell{leaf.origin[0], leaf.origin[1], leaf.origin[2]};
            const bool last = t_exit >= inside.max;
            fmt::print(
                out_,
                "step {}: node {}, {}, lattice ({}, {}, {}) side {}: t {:.6g} to {:.6g}, {}; {}\n",
                step_exits.size() + 1, index, path_text(path_to(cell)), leaf.origin[0],
                leaf.origin[1], leaf.origin[2], leaf.size, entry, std::min(t_exit, inside.max),
                last ? std::string("out of the world")
                     : fmt::format("out by the {} face", exit_face(ray, leaf)),
                polygons.empty() ? std::string("no polygons")
                                 : fmt::format("polygons {}", fmt::join(polygons, " ")));
            step_exits.push_back(t_exit);
            entry = t_exit;
            return false;
        });
    TraceCounters counters;
    const std::optional<Hit> hit = octree_.closest_hit(ray, all, counters);
    const std::string search = fmt::format("the search stepped {} and made {}",
                                           count_of(counters.voxels_stepped, "leaf", "leaves"),
                                           count_of(counters.polygon_tests, "polygon test"));
    if (!hit) {
        fmt::print(out_, "no hit; {}\n", search);
        return;
    }
    const auto found = std::find_if(step_exits.begin(), step_exits.end(),
                                    [&](double t_exit) { return t_exit >= hit->t; });
    fmt::print(out_, "hit: polygon {} from {} at t {:.6g}, point {}, in the leaf of step {}; {}\n",
               hit->polygon, scene_.origin_of(hit->polygon).to_string(), hit->t,
               point_text(ray.at(hit->t)), found - step_exits.begin() + 1, search);
}

void Session::ray(std::span<const std::string_view> args) {
    Ray r;
    for (int a = 0; a < 3; ++a) {
        r.origin[a] = number("ray", args[static_cast<std::size_t>(a)]);
        r.direction[a] = number("ray", args[static_cast<std::size_t>(a) + 3]);
    }
    if (r.direction == Vec3{}) {
        throw CommandError("ray: the direction must not be zero");
    }
    walk(r);
}

void Session::pixel(std::span<const std::string_view> args) {
    const std::optional<std::int64_t> x = parse_integer(args[0]);
    const std::optional<std::int64_t> y = parse_integer(args[1]);
    const SceneView& v = scene_.view;
    if (!x || !y || *x < 0 || *y < 0 || *x >= v.width || *y >= v.height) {
        throw CommandError(
            fmt::format("pixel: expected a column from 0 to {} and a row from 0 "
                        "to {}, found {} {}",
                        v.width - 1, v.height - 1, quote_token(args[0]), quote_token(args[1])));
    }
    walk(v.camera().primary_ray(static_cast<double>(*x) + 0.5, static_cast<double>(*y) + 0.5));
}

}  // namespace

int run_octree_session(const Scene& scene, const Octree& octree, OctreeSessionStreams streams) {
    Session session(scene, octree, streams.answers);
    session.banner();
    int failed = 0;
    std::string line;
    while (true) {
        streams.answers << streams.prompt << std::flush;
        if (!std::getline(streams.commands, line)) {
            if (!streams.prompt.empty()) {
                streams.answers << '\n';  // the prompt's line, left open at the end of input
            }
            break;
        }
        try {
            if (!session.execute(line)) {
                break;
            }
        } catch (const CommandError& e) {
            streams.answers << "error: " << e.what() << '\n';
            ++failed;
        }
    }
    streams.answers << std::flush;
    return failed;
}

}  // namespace rt
