#include "rt/scene/read/attributes_reader.h"

#include <unordered_map>

#include "rt/scene/read/counted_lines.h"
#include "rt/scene/read/line_fields.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

// Identifiers are matched by value, so a second definition would silently shadow the first.
class AttributeList {
public:
    explicit AttributeList(std::int64_t count) {
        list_.reserve(static_cast<std::size_t>(std::min<std::int64_t>(count, 4096)));
    }
    void add(Attribute attribute) {
        const auto [it, fresh] = first_line_.emplace(attribute.index, attribute.where.line);
        if (!fresh) {
            throw InputError(attribute.where, fmt::format("attribute {} is defined twice (first at "
                                                          "line {})",
                                                          attribute.index, it->second));
        }
        list_.push_back(std::move(attribute));
    }
    std::vector<Attribute> take() { return std::move(list_); }

private:
    std::vector<Attribute> list_;
    std::unordered_map<long, int> first_line_;
};

void read_refraction(LineFields& f, const ReaderDialect& dialect, Attribute& a) {
    if (dialect.rgb_refraction) {
        a.refraction_index.r = f.number("the red index of refraction (with -R)");
        a.refraction_index.g = f.number("the green index of refraction (with -R)");
        a.refraction_index.b = f.number("the blue index of refraction (with -R)");
    } else {
        const double n = f.number("the index of refraction");
        a.refraction_index = {n, n, n};
    }
}

// The manual asks for colours in 0..1 and weights adding up to about 1; old files stray a little,
// so these are warnings. An index of refraction of 0 or less cannot bend light: that is an error.
void check_attribute(const Attribute& a, Diagnostics& diagnostics) {
    const std::string at = a.where.to_string() + ": attribute " + std::to_string(a.index);
    const Rgb& c = a.color;
    if (c.r < 0 || c.r > 1 || c.g < 0 || c.g > 1 || c.b < 0 || c.b > 1) {
        diagnostics.warn(at + " has a colour outside 0..1 " + show_point(c.r, c.g, c.b));
    }
    if (a.emission < 0 || a.ambient < 0 || a.diffuse < 0 || a.specular < 0 || a.transmission < 0) {
        diagnostics.warn(at + " has a negative weight (e a d s t)");
    }
    for (int k = 0; k < 3; ++k) {
        if (a.refraction_index[k] <= 0) {
            throw InputError(a.where, fmt::format("attribute {}: the index of refraction must be "
                                                  "more than 0, found {}",
                                                  a.index, show_number(a.refraction_index[k])));
        }
    }
}

// Two numbers more than the dialect has fields: a file with pow and tpow read with -Dp or -Of, or
// one with three indices of refraction read without -R. Said so at once; the fields would
// otherwise shift along unnoticed (an index taken from a cone exponent: "defined twice"). Lines
// short of numbers name their missing field as they are read.
void check_no_extra_pair(const LineFields& f, const ReaderDialect& dialect) {
    const std::size_t expected =
        (dialect.no_power_fields ? 14 : 16) + (dialect.rgb_refraction ? 2 : 0);
    const std::size_t found = f.numbers_ahead();
    if (found != expected + 2) {
        return;
    }
    std::string readings;
    if (dialect.no_power_fields) {
        readings = "without -Dp and -Of, for pow and tpow";
    }
    if (!dialect.rgb_refraction) {
        readings += std::string(readings.empty() ? "" : ", or ") +
                    "with -R, for three indices of refraction";
    }
    if (readings.empty()) {
        return;  // -R without -Dp: no dialect has more fields; the two are the description's
    }
    throw expected_found(f.location(), fmt::format("{} numbers", expected),
                         fmt::format("{}: read the file {}", found, readings));
}

void trace_attribute(const Attribute& a, Diagnostics& diagnostics) {
    if (!diagnostics.tracing()) {
        return;
    }
    const Rgb& n = a.refraction_index;
    diagnostics.trace(fmt::format(
        "{}: attribute {}: colour {} pow {} tpow {} e {} a {} d {} s {} t {} refraction {} "
        "reflection cone {} {} refraction cone {} {}",
        a.where.to_string(), a.index, show_point(a.color.r, a.color.g, a.color.b),
        a.specular_exponent, a.transmit_exponent, a.emission, a.ambient, a.diffuse, a.specular,
        a.transmission, show_point(n.r, n.g, n.b), a.reflect_cone_degrees, a.reflect_cone_exponent,
        a.refract_cone_degrees, a.refract_cone_exponent));
}

}  // namespace

Attribute read_attribute_line(const SourceText& source, const DollarLine& line,
                              const ReaderDialect& dialect, Diagnostics& diagnostics) {
    LineFields f(source, line);
    Attribute a;
    a.where = f.location();
    check_no_extra_pair(f, dialect);
    a.color.r = f.number_within("the red intensity", kMaxIntensity);
    a.color.g = f.number_within("the green intensity", kMaxIntensity);
    a.color.b = f.number_within("the blue intensity", kMaxIntensity);
    if (!dialect.no_power_fields) {
        a.specular_exponent = f.number("the specular exponent pow");
        a.transmit_exponent = f.number("the refraction exponent tpow");
    }
    a.emission = f.number_within("the emitted weight e", kMaxIntensity);
    a.ambient = f.number_within("the ambient weight a", kMaxIntensity);
    a.diffuse = f.number_within("the diffuse weight d", kMaxIntensity);
    a.specular = f.number_within("the specular weight s", kMaxIntensity);
    a.transmission = f.number_within("the transmitted weight t", kMaxIntensity);
    read_refraction(f, dialect, a);
    a.reflect_cone_degrees = f.number("the reflection cone angle theta");
    a.reflect_cone_exponent = f.number("the reflection cone exponent n");
    a.refract_cone_degrees = f.number("the refraction cone angle theta");
    a.refract_cone_exponent = f.number("the refraction cone exponent n");
    a.index = static_cast<long>(f.integer("the attribute's index number"));
    check_attribute(a, diagnostics);
    trace_attribute(a, diagnostics);
    return a;
}

std::vector<Attribute> read_attributes_file(const SourceText& source, const ReaderDialect& dialect,
                                            Diagnostics& diagnostics) {
    CountedLines file(source, "attribute", "attributes");
    AttributeList list(file.count());
    for (std::int64_t k = 0; k < file.count(); ++k) {
        list.add(read_attribute_line(source, file.next_item(), dialect, diagnostics));
    }
    file.skip_the_rest(diagnostics);
    return list.take();
}

std::vector<Attribute> read_inline_attributes(ItemStream& scn, const ReaderDialect& dialect,
                                              Diagnostics& diagnostics) {
    const std::int64_t count = scn.count("the attribute count (-Df)", kMaxItemsPerFile);
    scn.skip_rest_of_line();
    AttributeList list(count);
    DollarLine line;
    for (std::int64_t k = 0; k < count; ++k) {
        if (!scn.take_line(line)) {
            throw InputError(scn.end_location(),
                             fmt::format("expected {} attributes, found {}", count, k));
        }
        list.add(read_attribute_line(scn.source(), line, dialect, diagnostics));
    }
    return list.take();
}

}  // namespace rt
