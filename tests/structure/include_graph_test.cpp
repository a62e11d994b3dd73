// The library's module graph, as src/rt/CMakeLists.txt declares it (rt_add_module(NAME DEPS ...)),
// checked against the includes in src/rt: a file of module A may include "rt/B/..." only if A
// declares rt_B, every declared rt_ dependency is included somewhere, and no modules include each
// other in a cycle. A failure names the file, the line and the include.
#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

using Graph = std::map<std::string, std::set<std::string>>;

fs::path library_dir() {
    return source_dir() / "src" / "rt";
}

// Every rt_add_module call: its name and the rt_ modules after DEPS (a module declared twice, as
// accel is with and without Embree, gets the union).
Graph declared_modules() {
    const std::string text = read_text(library_dir() / "CMakeLists.txt");
    const std::regex call(R"(rt_add_module\(\s*(\w+)([^)]*)\))");
    const std::regex dependency(R"(\brt_(\w+))");
    Graph graph;
    for (auto m = std::sregex_iterator(text.begin(), text.end(), call); m != std::sregex_iterator();
         ++m) {
        std::string arguments = (*m)[2].str();
        arguments = arguments.substr(0, arguments.find("EXCLUDE"));
        std::set<std::string>& deps = graph[(*m)[1].str()];
        for (auto d = std::sregex_iterator(arguments.begin(), arguments.end(), dependency);
             d != std::sregex_iterator(); ++d) {
            deps.insert((*d)[1].str());
        }
    }
    return graph;
}

struct Include {
    std::string file;  ///< relative to the source tree
    int line = 0;
    std::string text;  ///< what is included, e.g. rt/scene/scene.h
    std::string from;  ///< the including file's module
    std::string to;    ///< the included file's module

    std::string where() const {
        return file + ":" + std::to_string(line) + ": #include \"" + text + "\"";
    }
};

// Every #include "rt/<module>/..." of another module in the library's sources.
std::vector<Include> cross_module_includes() {
    const std::regex include_line(R"(^\s*#\s*include\s*"(rt/(\w+)/[^"]+)\")");
    std::vector<Include> includes;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(library_dir())) {
        const std::string extension = entry.path().extension().string();
        if (!entry.is_regular_file() || (extension != ".h" && extension != ".cpp")) {
            continue;
        }
        const fs::path relative = fs::relative(entry.path(), library_dir());
        if (relative.begin() == relative.end() || std::next(relative.begin()) == relative.end()) {
            continue;  // a file directly in src/rt belongs to no module
        }
        const std::string module = relative.begin()->string();
        int number = 0;
        for (const std::string& line : lines_of(read_text(entry.path()))) {
            ++number;
            std::smatch m;
            if (std::regex_search(line, m, include_line) && m[2].str() != module) {
                includes.push_back({fs::relative(entry.path(), source_dir()).generic_string(),
                                    number, m[1].str(), module, m[2].str()});
            }
        }
    }
    std::sort(includes.begin(), includes.end(),
              [](const Include& a, const Include& b) { return a.where() < b.where(); });
    return includes;
}

// A cycle of the graph as its modules in order (the first repeated at the end), or none.
std::vector<std::string> find_cycle(const Graph& graph) {
    std::map<std::string, int> state;  // 0 unseen, 1 on the path, 2 done
    std::vector<std::string> path;
    std::vector<std::string> cycle;
    const auto visit = [&](const auto& self, const std::string& node) -> bool {
        state[node] = 1;
        path.push_back(node);
        const auto found = graph.find(node);
        if (found != graph.end()) {
            for (const std::string& next : found->second) {
                if (state[next] == 1) {
                    cycle.assign(std::find(path.begin(), path.end(), next), path.end());
                    cycle.push_back(next);
                    return true;
                }
                if (state[next] == 0 && self(self, next)) {
                    return true;
                }
            }
        }
        path.pop_back();
        state[node] = 2;
        return false;
    };
    for (const auto& [node, edges] : graph) {
        if (state[node] == 0 && visit(visit, node)) {
            return cycle;
        }
    }
    return {};
}

TEST(IncludeGraph, TheCMakeFileDeclaresTheModules) {
    const Graph declared = declared_modules();
    for (const char* module : {"core", "geometry", "scene", "accel", "render", "app"}) {
        EXPECT_TRUE(declared.count(module)) << module << " not found in src/rt/CMakeLists.txt";
    }
}

TEST(IncludeGraph, EveryIncludedModuleIsDeclared) {
    const Graph declared = declared_modules();
    for (const Include& include : cross_module_includes()) {
        const auto module = declared.find(include.from);
        if (module == declared.end()) {
            ADD_FAILURE() << include.where() << ": module " << include.from
                          << " is not declared in src/rt/CMakeLists.txt";
        } else if (!module->second.count(include.to)) {
            ADD_FAILURE() << include.where() << ": " << include.from << " does not declare rt_"
                          << include.to << " in src/rt/CMakeLists.txt";
        }
    }
}

TEST(IncludeGraph, EveryDeclaredModuleIsIncluded) {
    Graph used;
    for (const Include& include : cross_module_includes()) {
        used[include.from].insert(include.to);
    }
    for (const auto& [module, deps] : declared_modules()) {
        for (const std::string& dep : deps) {
            EXPECT_TRUE(used[module].count(dep))
                << module << " declares rt_" << dep << " but includes nothing of it";
        }
    }
}

TEST(IncludeGraph, ModulesIncludeEachOtherInNoCycle) {
    const std::vector<Include> includes = cross_module_includes();
    Graph used;
    for (const Include& include : includes) {
        used[include.from].insert(include.to);
    }
    const std::vector<std::string> cycle = find_cycle(used);
    if (!cycle.empty()) {
        std::string message = "modules include each other in a cycle:";
        for (std::size_t k = 0; k + 1 < cycle.size(); ++k) {
            const auto first = std::find_if(
                includes.begin(), includes.end(),
                [&](const Include& i) { return i.from == cycle[k] && i.to == cycle[k + 1]; });
            message += "\n  " + cycle[k] + " -> " + cycle[k + 1] + ", e.g. " + first->where();
        }
        ADD_FAILURE() << message;
    }
    std::string declared_cycle;
    for (const std::string& module : find_cycle(declared_modules())) {
        declared_cycle += (declared_cycle.empty() ? "" : " -> ") + module;
    }
    EXPECT_TRUE(declared_cycle.empty())
        << "src/rt/CMakeLists.txt declares a cycle: " << declared_cycle;
}

TEST(IncludeGraph, FindsACycle) {
    const Graph graph = {{"a", {"b"}}, {"b", {"c"}}, {"c", {"a"}}, {"d", {"a"}}};
    const std::vector<std::string> expected = {"a", "b", "c", "a"};
    EXPECT_EQ(find_cycle(graph), expected);
    EXPECT_TRUE(find_cycle({{"a", {"b"}}, {"b", {}}, {"c", {"a", "b"}}}).empty());
}

}  // namespace
}  // namespace rt::test
