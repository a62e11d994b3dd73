#include "lab_options.h"

#include <charconv>

#include "rt/core/error.h"

namespace rt::lab {

namespace {

std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        const std::size_t end = comma == std::string::npos ? text.size() : comma;
        if (end > start) {
            parts.push_back(text.substr(start, end - start));
        }
        start = end + 1;
    }
    return parts;
}

std::uint32_t parse_size(const std::string& word) {
    std::uint32_t value = 0;
    std::string digits = word;
    std::uint32_t factor = 1;
    if (!digits.empty() && (digits.back() == 'k' || digits.back() == 'M')) {
        factor = digits.back() == 'k' ? 1000 : 1000000;
        digits.pop_back();
    }
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc{} || end != digits.data() + digits.size() || value == 0) {
        throw UsageError("rt_lab: bad size '" + word + "' (a count like 1000, 10k or 1M)");
    }
    return value * factor;
}

}  // namespace

std::string lab_help() {
    return "rt_lab [switches]: every intersection method on the same meshes and rays\n"
           "  --quick            1k and 10k triangles, shorter runs\n"
           "  --sizes LIST       triangle counts, e.g. 1k,10k,100k,1M (the default)\n"
           "  --meshes LIST      sphere,soup,twocubes (the default)\n"
           "  --accels LIST      brute,octree,seads,bvh,embree (the default; missing ones are "
           "skipped)\n"
           "  --threads N        threads for the all-cores runs (default: all)\n"
           "  --seconds S        least time per measurement (default 0.3)\n"
           "  --seads-side N     SEADS voxels a side (default: the suggested size per mesh)\n"
           "  --octree-depth N   octree depth (default: the suggested depth per mesh)\n"
           "  --csv FILE         also write the table as CSV\n"
           "  --svg FILE         also draw rays/s against triangle count (log-log)\n"
           "  --source DIR       the source tree, for scenes/twocubes.scn (default .)\n";
}

LabOptions parse_lab_options(const std::vector<std::string>& args) {
    LabOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) {
                throw UsageError("rt_lab: " + a + " needs a value");
            }
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            o.show_help = true;
        } else if (a == "--quick") {
            o.sizes = {1000, 10000};
            o.seconds_per_run = 0.1;
            o.brute_force_tests = 2e7;
        } else if (a == "--sizes") {
            o.sizes.clear();
            for (const std::string& s : split_commas(value())) {
                o.sizes.push_back(parse_size(s));
            }
        } else if (a == "--meshes") {
            o.meshes = split_commas(value());
        } else if (a == "--accels") {
            o.accels.clear();
            for (const std::string& s : split_commas(value())) {
                const std::optional<AccelKind> kind = accel_kind_from_name(s);
                if (!kind) {
                    throw UsageError("rt_lab: unknown intersection method '" + s + "'");
                }
                o.accels.push_back(*kind);
            }
        } else if (a == "--threads") {
            o.threads = parse_size(value());
        } else if (a == "--seconds") {
            const std::string& text = value();
            const auto [end, error] =
                std::from_chars(text.data(), text.data() + text.size(), o.seconds_per_run);
            if (error != std::errc{} || end != text.data() + text.size() ||
                !(o.seconds_per_run > 0.0)) {
                throw UsageError("rt_lab: bad number of seconds '" + text + "'");
            }
        } else if (a == "--seads-side") {
            o.seads_side = static_cast<int>(parse_size(value()));
        } else if (a == "--octree-depth") {
            o.octree_depth = static_cast<int>(parse_size(value()));
        } else if (a == "--csv") {
            o.csv_file = value();
        } else if (a == "--svg") {
            o.svg_file = value();
        } else if (a == "--source") {
            o.source_dir = value();
        } else {
            throw UsageError("rt_lab: unknown switch '" + a + "' (try --help)");
        }
    }
    return o;
}

}  // namespace rt::lab
