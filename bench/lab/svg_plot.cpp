#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "rt/core/error.h"

#include <fmt/format.h>

namespace rt::lab {

namespace {

constexpr double kPanelWidth = 440;
constexpr double kPanelHeight = 320;
constexpr double kMargin = 60;  // room for the axes' labels inside each panel

struct Panel {
    std::string mesh;
    bool random = false;
    std::string title() const { return mesh + (random ? ", random rays" : ", camera rays"); }
};

std::string colour(const std::string& accel) {
    static const std::map<std::string, std::string> colours{{"brute", "#888888"},
                                                            {"octree", "#1f77b4"},
                                                            {"seads", "#2ca02c"},
                                                            {"bvh", "#d62728"},
                                                            {"embree", "#9467bd"}};
    const auto it = colours.find(accel);
    return it == colours.end() ? "#000000" : it->second;
}

// What a plot shows for one measurement and kind of ray, and its axis's name.
struct Quantity {
    double (*value)(const Measurement& m, bool random);
    const char* label;
};

double rate(const Measurement& m, bool random) {
    return random ? m.random_one.mrays_per_second : m.primary_one.mrays_per_second;
}

double nanoseconds_per_ray(const Measurement& m, bool random) {
    const double r = rate(m, random);
    return r > 0 ? 1e3 / r : 0.0;
}

constexpr Quantity kRate{rate, "Mrays/s, one thread"};
constexpr Quantity kTime{nanoseconds_per_ray, "ns per ray, one thread"};

// Decades covering the positive values.
void decades(const std::vector<double>& values, double& lo, double& hi) {
    lo = HUGE_VAL;
    hi = -HUGE_VAL;
    for (const double v : values) {
        if (v > 0) {
            lo = std::min(lo, std::floor(std::log10(v)));
            hi = std::max(hi, std::ceil(std::log10(v)));
        }
    }
    if (!(lo < hi)) {
        lo = std::isfinite(lo) ? lo : 0;
        hi = lo + 1;
    }
}

std::string draw_panel(const Panel& panel, const std::vector<Measurement>& results,
                       const Quantity& quantity, double left, double top) {
    std::vector<const Measurement*> mine;
    std::vector<double> xs;
    std::vector<double> ys;
    for (const Measurement& m : results) {
        if (m.mesh == panel.mesh && m.triangles > 0 && quantity.value(m, panel.random) > 0) {
            mine.push_back(&m);
            xs.push_back(static_cast<double>(m.triangles));
            ys.push_back(quantity.value(m, panel.random));
        }
    }
    double x0, x1, y0, y1;
    decades(xs, x0, x1);
    decades(ys, y0, y1);
    const double w = kPanelWidth - 1.5 * kMargin;
    const double h = kPanelHeight - 1.5 * kMargin;
    const double ox = left + kMargin;
    const double oy = top + kPanelHeight - kMargin;
    const auto px = [&](double v) { return ox + (std::log10(v) - x0) / (x1 - x0) * w; };
    const auto py = [&](double v) { return oy - (std::log10(v) - y0) / (y1 - y0) * h; };
    std::string svg =
        fmt::format("<text x='{}' y='{}' font-size='14' text-anchor='middle'>{}</text>\n",
                    ox + w / 2, top + 20, panel.title());
    for (double d = x0; d <= x1; d += 1) {
        const double x = ox + (d - x0) / (x1 - x0) * w;
        svg += fmt::format(
            "<line x1='{0}' y1='{1}' x2='{0}' y2='{2}' stroke='#ddd'/>"
            "<text x='{0}' y='{3}' font-size='11' text-anchor='middle'>1e{4}</text>\n",
            x, oy, oy - h, oy + 16, d);
    }
    for (double d = y0; d <= y1; d += 1) {
        const double y = oy - (d - y0) / (y1 - y0) * h;
        svg += fmt::format(
            "<line x1='{0}' y1='{1}' x2='{2}' y2='{1}' stroke='#ddd'/>"
            "<text x='{3}' y='{4}' font-size='11' text-anchor='end'>{5:g}</text>\n",
            ox, y, ox + w, ox - 6, y + 4, std::pow(10.0, d));
    }
    svg += fmt::format(
        "<text x='{}' y='{}' font-size='11' text-anchor='middle'>triangles</text>\n"
        "<text x='{}' y='{}' font-size='11' transform='rotate(-90 {} {})' "
        "text-anchor='middle'>{}</text>\n",
        ox + w / 2, oy + 34, left + 16, oy - h / 2, left + 16, oy - h / 2, quantity.label);
    std::map<std::string, std::vector<std::pair<double, double>>> lines;
    for (const Measurement* m : mine) {
        lines[m->accel].push_back(
            {px(static_cast<double>(m->triangles)), py(quantity.value(*m, panel.random))});
    }
    for (auto& [accel, points] : lines) {
        std::sort(points.begin(), points.end());
        std::string path;
        for (const auto& [x, y] : points) {
            path += fmt::format("{}{:.1f},{:.1f}", path.empty() ? "M" : " L", x, y);
            svg += fmt::format("<circle cx='{:.1f}' cy='{:.1f}' r='3' fill='{}'/>\n", x, y,
                               colour(accel));
        }
        svg += fmt::format("<path d='{}' fill='none' stroke='{}' stroke-width='2'/>\n", path,
                           colour(accel));
    }
    return svg;
}

void write_plot(const std::string& file, const std::vector<Measurement>& results,
                const Quantity& quantity) {
    std::vector<std::string> meshes;
    std::vector<std::string> accels;
    for (const Measurement& m : results) {
        if (std::find(meshes.begin(), meshes.end(), m.mesh) == meshes.end()) {
            meshes.push_back(m.mesh);
        }
        if (std::find(accels.begin(), accels.end(), m.accel) == accels.end()) {
            accels.push_back(m.accel);
        }
    }
    const double width = 2 * kPanelWidth;
    const double height = static_cast<double>(meshes.size()) * kPanelHeight + 40;
    std::string svg = fmt::format(
        "<svg xmlns='http://www.w3.org/2000/svg' width='{}' height='{}' font-family='sans-serif'>\n"
        "<rect width='100%' height='100%' fill='white'/>\n",
        width, height);
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        for (int r = 0; r < 2; ++r) {
            svg += draw_panel({meshes[i], r == 1}, results, quantity, r * kPanelWidth,
                              static_cast<double>(i) * kPanelHeight);
        }
    }
    for (std::size_t i = 0; i < accels.size(); ++i) {
        const double x = 20 + static_cast<double>(i) * 110;
        const double y = height - 16;
        svg += fmt::format(
            "<line x1='{}' y1='{}' x2='{}' y2='{}' stroke='{}' stroke-width='3'/>"
            "<text x='{}' y='{}' font-size='12'>{}</text>\n",
            x, y, x + 24, y, colour(accels[i]), x + 30, y + 4, accels[i]);
    }
    svg += "</svg>\n";
    std::ofstream out(file);
    out << svg;
    if (!out) {
        throw IoError("rt_lab: cannot write " + file);
    }
}

}  // namespace

void write_svg_plot(const std::string& file, const std::vector<Measurement>& results) {
    write_plot(file, results, kRate);
}

void write_time_plot(const std::string& file, const std::vector<Measurement>& results) {
    write_plot(file, results, kTime);
}

}  // namespace rt::lab
