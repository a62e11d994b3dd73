#include "lab_report.h"

#include <fstream>

#include "rt/core/error.h"

#include <fmt/format.h>

namespace rt::lab {

namespace {

// "12.34" or "12.34*" when brute force traced a subsample.
std::string rate_cell(const TraceRate& r) {
    return fmt::format("{:.3f}{}", r.mrays_per_second, r.subsampled ? "*" : "");
}

}  // namespace

void print_table_header(std::ostream& out) {
    out << fmt::format(
               "{:<10} {:>9} {:<7} {:>10} {:>9} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}\n",
               "mesh", "triangles", "accel", "build ms", "bytes/tri", "prim 1T", "rand 1T",
               "prim NT", "rand NT", "prim8 1T", "rand8 1T")
        << fmt::format("{:<10} {:>9} {:<7} {:>10} {:>9} {:>65}\n", "", "", "", "", "",
                       "(Mrays/s; * = brute force on a subsample; 8 = packets of eight)");
}

void print_table_row(std::ostream& out, const Measurement& m) {
    out << fmt::format(
        "{:<10} {:>9} {:<7} {:>10.1f} {:>9.1f} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}\n", m.mesh,
        m.triangles, m.accel, m.build_ms, m.bytes_per_triangle, rate_cell(m.primary_one),
        rate_cell(m.random_one), rate_cell(m.primary_all), rate_cell(m.random_all),
        rate_cell(m.primary_packet_one), rate_cell(m.random_packet_one));
    if (m.tree_cost) {
        // Embree prints its own with the device configuration "verbose=2" (bench/lab/README.md).
        const bvh::TreeCost& c = *m.tree_cost;
        out << fmt::format(
            "{:<10} {:>9} {:<7} tree cost {:.2f} (nodes {:.2f} + packets {:.2f}; leaves in pairs "
            "{:.2f}), {} leaves, wide nodes {:.0f} % full\n",
            "", "", "", c.total(), c.nodes, c.leaves, c.leaf_pairs, c.leaf_count, 100.0 * c.fill);
    }
    out << std::flush;
}

void write_csv(const std::string& file, const std::vector<Measurement>& results) {
    std::ofstream out(file);
    if (!out) {
        throw IoError("rt_lab: cannot write " + file);
    }
    out << "mesh,triangles,accel,build_ms,bytes_per_triangle,threads,"
           "primary_mrays_1t,random_mrays_1t,primary_mrays_nt,random_mrays_nt,"
           "rays_traced,subsampled,primary_hits,random_hits,primary_nodes_per_ray,"
           "primary_tests_per_ray,random_nodes_per_ray,random_tests_per_ray,"
           "primary_packet_mrays_1t,random_packet_mrays_1t,tree_cost_nodes,tree_cost_leaves,"
           "tree_cost_leaf_pairs,round\n";
    for (const Measurement& m : results) {
        out << fmt::format(
            "{},{},{},{:.3f},{:.2f},{},{:.4f},{:.4f},{:.4f},{:.4f},{},{},{},{},{:.2f},{:.2f},{:.2f}"
            ",{:.2f},{:.4f},{:.4f}",
            m.mesh, m.triangles, m.accel, m.build_ms, m.bytes_per_triangle, m.threads,
            m.primary_one.mrays_per_second, m.random_one.mrays_per_second,
            m.primary_all.mrays_per_second, m.random_all.mrays_per_second, m.primary_one.rays,
            m.primary_one.subsampled ? 1 : 0, m.primary_one.hits, m.random_one.hits,
            m.primary_one.nodes_per_ray, m.primary_one.tests_per_ray, m.random_one.nodes_per_ray,
            m.random_one.tests_per_ray, m.primary_packet_one.mrays_per_second,
            m.random_packet_one.mrays_per_second);
        // Empty for every method but the BVH.
        out << (m.tree_cost ? fmt::format(",{:.4f},{:.4f},{:.4f}", m.tree_cost->nodes,
                                          m.tree_cost->leaves, m.tree_cost->leaf_pairs)
                            : std::string(",,,"))
            << ',' << m.round << '\n';
    }
    if (!out) {
        throw IoError("rt_lab: cannot write " + file);
    }
}

}  // namespace rt::lab
