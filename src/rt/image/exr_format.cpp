#include "rt/image/exr_format.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <system_error>
#include <vector>

#include "rt/core/atomic_file.h"
#include "rt/core/error.h"
#include "rt/image/gro_format.h"
#include "rt/image/image8.h"

#include <fmt/format.h>

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

namespace rt {

namespace {

// rt's own attributes: what a .gro header holds beyond the pixels and the two windows.
constexpr const char* kMultiplier = "rtMultiplier";
constexpr const char* kClip = "rtClip";
constexpr const char* kFirstFinishedRow = "rtFirstFinishedRow";
constexpr const char* kScene = "rtScene";
constexpr const char* kSwitches = "rtSwitches";
constexpr const char* kProgram = "rtProgram";
constexpr const char* kCreated = "rtCreated";
constexpr const char* kArguments = "rtArguments";
constexpr const char* kSeed = "rtSeed";
constexpr const char* kInputs = "rtInputs";
constexpr const char* kChannels[3] = {"R", "G", "B"};

// OpenEXR writes through its own stream interface; this one forwards to the temporary file that
// write_file_atomically opened, so the picture appears under its name only once complete.
class ForwardingStream : public Imf::OStream {
public:
    ForwardingStream(std::ostream& out, const std::string& name)
        : Imf::OStream(name.c_str()), out_(out) {}
    void write(const char c[], int n) override {
        if (!out_.write(c, n)) {
            throw IoError("cannot write " + std::string(fileName()) + ": write failed");
        }
    }
    std::uint64_t tellp() override { return static_cast<std::uint64_t>(out_.tellp()); }
    void seekp(std::uint64_t pos) override { out_.seekp(static_cast<std::streamoff>(pos)); }

private:
    std::ostream& out_;
};

Imf::Header header_for(const Film& film) {
    const PixelRect& w = film.window();
    const Imath::Box2i display({0, 0}, {film.view_width() - 1, film.view_height() - 1});
    const Imath::Box2i data({w.left, w.top}, {w.right, w.bottom});
    Imf::Header header(display, data, 1.0F, Imath::V2f(0, 0), 1.0F, Imf::INCREASING_Y,
                       Imf::ZIP_COMPRESSION);
    for (const char* name : kChannels) {
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    }
    header.insert(kMultiplier, Imf::DoubleAttribute(film.mapping.multiplier));
    header.insert(kClip, Imf::IntAttribute(film.mapping.clip ? 1 : 0));
    header.insert(kFirstFinishedRow, Imf::IntAttribute(film.first_finished_row()));
    header.insert(kScene, Imf::StringAttribute(film.provenance.scene));
    header.insert(kSwitches, Imf::StringAttribute(film.provenance.switches));
    header.insert(kProgram, Imf::StringAttribute(film.provenance.program));
    header.insert(kCreated, Imf::StringAttribute(film.provenance.created));
    if (!film.provenance.arguments.empty()) {  // as in the .gro: only when known
        header.insert(kArguments, Imf::StringAttribute(film.provenance.arguments));
        header.insert(kSeed, Imf::StringAttribute(film.provenance.seed));
        header.insert(kInputs, Imf::StringAttribute(film.provenance.inputs));
    }
    return header;
}

// The three channels as slices of interleaved RGB floats laid out over the data window.
Imf::FrameBuffer interleaved(const float* pixels, const Imath::Box2i& data) {
    const std::size_t x_stride = 3 * sizeof(float);
    const std::size_t y_stride = x_stride * static_cast<std::size_t>(data.max.x - data.min.x + 1);
    Imf::FrameBuffer buffer;
    for (int c = 0; c < 3; ++c) {
        buffer.insert(kChannels[c],
                      Imf::Slice::Make(Imf::FLOAT, pixels + c, data, x_stride, y_stride));
    }
    return buffer;
}

template <class Attribute>
const Attribute* find(const Imf::Header& header, const char* name) {
    return header.findTypedAttribute<Attribute>(name);
}

std::string text_of(const Imf::Header& header, const char* name) {
    const auto* a = find<Imf::StringAttribute>(header, name);
    return a != nullptr ? a->value() : std::string();
}

// The windows a film can hold: a display window from (0, 0), the data window inside it.
void check_windows(const Imath::Box2i& display, const Imath::Box2i& data, const std::string& file) {
    const auto box = [](const Imath::Box2i& b) {
        return fmt::format("({}, {}) to ({}, {})", b.min.x, b.min.y, b.max.x, b.max.y);
    };
    const std::int64_t width = std::int64_t{display.max.x} - display.min.x + 1;
    const std::int64_t height = std::int64_t{display.max.y} - display.min.y + 1;
    if (display.min.x != 0 || display.min.y != 0 || width < 1 || height < 1 ||
        width > kMaxImageSide || height > kMaxImageSide) {
        throw expected_found(
            {file, 0, 0},
            fmt::format("a display window from (0, 0), at most {} pixels a side", kMaxImageSide),
            box(display));
    }
    if (data.min.x < 0 || data.min.y < 0 || data.max.x >= width || data.max.y >= height ||
        data.min.x > data.max.x || data.min.y > data.max.y) {
        throw expected_found({file, 0, 0},
                             "a data window inside the display window " + box(display), box(data));
    }
}

void check_channels(const Imf::Header& header, const std::string& file) {
    for (const char* name : kChannels) {
        const Imf::Channel* channel = header.channels().findChannel(name);
        if (channel == nullptr) {
            throw expected_found({file, 0, 0}, "R, G and B channels",
                                 fmt::format("no {} channel", name));
        }
        if (channel->xSampling != 1 || channel->ySampling != 1) {
            throw expected_found({file, 0, 0}, "channels with a sample in every pixel",
                                 fmt::format("a subsampled {} channel", name));
        }
    }
}

void check_finite(const Film& film, const std::string& file) {
    const PixelRect& w = film.window();
    const std::vector<float>& data = film.data();
    for (std::size_t i = 0; i < data.size(); ++i) {
        if (!std::isfinite(data[i])) {
            const std::size_t pixel = i / 3;
            const auto width = static_cast<std::size_t>(w.width());
            throw expected_found({file, 0, 0}, "finite pixel values",
                                 fmt::format("{} in pixel ({}, {})", data[i],
                                             w.left + static_cast<int>(pixel % width),
                                             w.top + static_cast<int>(pixel / width)));
        }
    }
}

// What rt wrote besides the pixels; a file from elsewhere keeps the defaults.
void restore_attributes(const Imf::Header& header, Film& film, const std::string& file) {
    if (const auto* m = find<Imf::DoubleAttribute>(header, kMultiplier)) {
        if (!std::isfinite(m->value()) || m->value() < 0.0) {
            throw expected_found({file, 0, 0}, "a non-negative display multiplier",
                                 fmt::format("{}", m->value()));
        }
        film.mapping.multiplier = m->value();
    }
    if (const auto* c = find<Imf::IntAttribute>(header, kClip)) {
        film.mapping.clip = c->value() != 0;
    }
    if (const auto* f = find<Imf::IntAttribute>(header, kFirstFinishedRow)) {
        const PixelRect& w = film.window();
        if (f->value() < w.top || f->value() > w.bottom + 1) {
            throw expected_found(
                {file, 0, 0},
                fmt::format("a first finished row from {} to {}", w.top, w.bottom + 1),
                std::to_string(f->value()));
        }
        film.set_first_finished_row(f->value());
    }
    film.provenance = {text_of(header, kScene),     text_of(header, kSwitches),
                       text_of(header, kProgram),   text_of(header, kCreated),
                       text_of(header, kArguments), text_of(header, kSeed),
                       text_of(header, kInputs)};
}

Film read_exr_file(const std::string& file) {
    Imf::InputFile in(file.c_str());
    const Imf::Header& header = in.header();
    const Imath::Box2i display = header.displayWindow();
    const Imath::Box2i data = header.dataWindow();
    check_windows(display, data, file);
    check_channels(header, file);
    Film film(display.max.x + 1, display.max.y + 1,
              PixelRect{data.min.x, data.min.y, data.max.x, data.max.y});
    in.setFrameBuffer(interleaved(film.data().data(), data));
    in.readPixels(data.min.y, data.max.y);
    check_finite(film, file);
    film.set_first_finished_row(data.min.y);  // a picture from elsewhere is whole
    restore_attributes(header, film, file);
    return film;
}

}  // namespace

void write_exr(const Film& film, const std::filesystem::path& path) {
    try {
        check_storable(film);
    } catch (const Error& e) {
        throw Error("cannot write " + path.string() + ": " + e.what());
    }
    const Imf::Header header = header_for(film);
    try {
        write_file_atomically(path, [&](std::ostream& out) {
            ForwardingStream stream(out, path.string());
            Imf::OutputFile exr(stream, header);
            exr.setFrameBuffer(interleaved(film.data().data(), header.dataWindow()));
            exr.writePixels(film.height());
        });
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw IoError("cannot write " + path.string() + ": " + e.what());
    }
}

Film read_exr(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw IoError("cannot read " + file + ": it is a folder");
    }
    if (!std::filesystem::exists(path, ec)) {
        throw IoError("cannot open " + file + ": " + std::generic_category().message(ENOENT));
    }
    try {
        return read_exr_file(file);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        // OpenEXR's own words for a damaged or foreign file, on one line.
        std::string why = e.what();
        std::replace(why.begin(), why.end(), '\n', ' ');
        throw InputError({file, 0, 0}, "not an OpenEXR picture rt can read: " + why);
    }
}

}  // namespace rt
