#include "lab_shares.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>

namespace rt::lab {

namespace {

constexpr const char* kEmbree = "embree";

// What a cell of the share table holds.
using Figure = double (*)(const Measurement& ours, const Measurement& embree);

// A rate or time of 0 is one not measured (brute force's packets, its build): no share.
double ratio(double ours, double theirs) {
    return ours > 0.0 && theirs > 0.0 ? ours / theirs : std::nan("");
}

// The rounds a method was measured in on one mesh, each with Embree's row of the same round.
using Paired = std::vector<std::pair<const Measurement*, const Measurement*>>;

using RowKey = std::tuple<std::string, std::uint64_t, std::string>;

Spread spread_over(const Paired& paired, Figure figure) {
    std::vector<double> values;
    values.reserve(paired.size());
    for (const auto& [ours, embree] : paired) {
        values.push_back(figure(*ours, *embree));
    }
    return spread_of(std::move(values));
}

std::string cell(const Spread& s, unsigned rounds) {
    if (s.count == 0) {
        return "-";
    }
    if (rounds <= 1 || s.count == 1) {
        return fmt::format("{:.2f}", s.median);
    }
    return fmt::format("{:.2f} ({:.2f}-{:.2f})", s.median, s.lowest, s.highest);
}

// The median over `rows` of what `field` reads from each.
template <class Field>
double median_of(const std::vector<const Measurement*>& rows, Field field) {
    std::vector<double> values;
    values.reserve(rows.size());
    for (const Measurement* m : rows) {
        values.push_back(field(*m));
    }
    return spread_of(std::move(values)).median;
}

// Every rate a measurement holds.
constexpr TraceRate Measurement::*kRates[] = {
    &Measurement::primary_one, &Measurement::random_one,         &Measurement::primary_all,
    &Measurement::random_all,  &Measurement::primary_packet_one, &Measurement::random_packet_one};

}  // namespace

Spread spread_of(std::vector<double> values) {
    std::erase_if(values, [](double v) { return !std::isfinite(v); });
    Spread s;
    s.count = values.size();
    if (values.empty()) {
        return s;
    }
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    s.median =
        values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
    s.lowest = values.front();
    s.highest = values.back();
    return s;
}

std::vector<Shares> shares_of_embree(const std::vector<Measurement>& results) {
    std::map<std::tuple<std::string, std::uint64_t, unsigned>, const Measurement*> embree_of;
    for (const Measurement& m : results) {
        if (m.accel == kEmbree) {
            embree_of[{m.mesh, m.triangles, m.round}] = &m;
        }
    }
    std::vector<RowKey> order;
    std::map<RowKey, Paired> paired;
    for (const Measurement& m : results) {
        if (m.accel == kEmbree) {
            continue;
        }
        const auto embree = embree_of.find({m.mesh, m.triangles, m.round});
        if (embree == embree_of.end()) {
            continue;
        }
        const RowKey key{m.mesh, m.triangles, m.accel};
        if (!paired.contains(key)) {
            order.push_back(key);
        }
        paired[key].emplace_back(&m, embree->second);
    }
    std::vector<Shares> shares;
    shares.reserve(order.size());
    for (const RowKey& key : order) {
        const Paired& p = paired[key];
        Shares s;
        std::tie(s.mesh, s.triangles, s.accel) = key;
        s.build = spread_over(p, [](const Measurement& a, const Measurement& e) {
            return ratio(a.build_ms, e.build_ms);
        });
        s.primary = spread_over(p, [](const Measurement& a, const Measurement& e) {
            return ratio(a.primary_one.mrays_per_second, e.primary_one.mrays_per_second);
        });
        s.random = spread_over(p, [](const Measurement& a, const Measurement& e) {
            return ratio(a.random_one.mrays_per_second, e.random_one.mrays_per_second);
        });
        s.primary_packets = spread_over(p, [](const Measurement& a, const Measurement& e) {
            return ratio(a.primary_packet_one.mrays_per_second, e.primary_one.mrays_per_second);
        });
        s.primary_packets_8 = spread_over(p, [](const Measurement& a, const Measurement& e) {
            return ratio(a.primary_packet_one.mrays_per_second,
                         e.primary_packet_one.mrays_per_second);
        });
        s.random_packets_8 = spread_over(p, [](const Measurement& a, const Measurement& e) {
            return ratio(a.random_packet_one.mrays_per_second,
                         e.random_packet_one.mrays_per_second);
        });
        shares.push_back(std::move(s));
    }
    return shares;
}

std::vector<Measurement> median_over_rounds(const std::vector<Measurement>& results) {
    std::vector<RowKey> order;
    std::map<RowKey, std::vector<const Measurement*>> rows;
    for (const Measurement& m : results) {
        const RowKey key{m.mesh, m.triangles, m.accel};
        if (!rows.contains(key)) {
            order.push_back(key);
        }
        rows[key].push_back(&m);
    }
    std::vector<Measurement> medians;
    medians.reserve(order.size());
    for (const RowKey& key : order) {
        const std::vector<const Measurement*>& of = rows[key];
        Measurement m = *of.front();
        m.build_ms = median_of(of, [](const Measurement& r) { return r.build_ms; });
        for (TraceRate Measurement::*rate : kRates) {
            (m.*rate).mrays_per_second =
                median_of(of, [rate](const Measurement& r) { return (r.*rate).mrays_per_second; });
        }
        medians.push_back(std::move(m));
    }
    return medians;
}

void print_shares(std::ostream& out, const std::vector<Shares>& shares, unsigned rounds) {
    if (shares.empty()) {
        return;
    }
    out << (rounds > 1 ? fmt::format("\nShares of Embree's figures in the same round: median "
                                     "(lowest-highest) of {} rounds\n",
                                     rounds)
                       : std::string("\nShares of Embree's figures in the same run\n"));
    out << fmt::format("{:<10} {:>9} {:<7} {:>17} {:>17} {:>17} {:>17} {:>17} {:>17}\n", "mesh",
                       "triangles", "accel", "build time", "prim 1T", "rand 1T", "prim8 : 1T",
                       "prim8 : 8", "rand8 : 8");
    out << fmt::format("{:<10} {:>9} {:<7} {:>107}\n", "", "", "",
                       "(time over Embree's; rates over rtcIntersect1 (: 1T) or rtcIntersect8)");
    for (const Shares& s : shares) {
        out << fmt::format("{:<10} {:>9} {:<7} {:>17} {:>17} {:>17} {:>17} {:>17} {:>17}\n", s.mesh,
                           s.triangles, s.accel, cell(s.build, rounds), cell(s.primary, rounds),
                           cell(s.random, rounds), cell(s.primary_packets, rounds),
                           cell(s.primary_packets_8, rounds), cell(s.random_packets_8, rounds));
    }
    out << std::flush;
}

}  // namespace rt::lab
