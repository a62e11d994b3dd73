#include "rt/image/ppm_format.h"

#include <cerrno>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>

#include "rt/core/atomic_file.h"
#include "rt/core/error.h"
#include "rt/core/text.h"

#include <fmt/format.h>

namespace rt {

namespace {

// Reads the whitespace-separated header fields of a P6 file, counting lines for messages.
class PpmHeaderReader {
public:
    PpmHeaderReader(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

    /// The next field ("P6", a number); '#' starts a comment up to the end of the line.
    std::string next_field(const std::string& what) {
        skip_space_and_comments();
        std::string field;
        for (int c = in_.peek(); c != std::char_traits<char>::eof() && !is_space(c) && c != '#';
             c = in_.peek()) {
            field.push_back(static_cast<char>(in_.get()));
            ++bytes_;
            if (field.size() > 20) {
                break;
            }
        }
        if (field.empty()) {
            throw expected_found(location(), what, "the end of the file");
        }
        return field;
    }

    int next_number(const std::string& what, int low, int high) {
        const std::string field = next_field(what);
        const std::optional<std::int64_t> n = parse_integer(field);
        if (!n || *n < low || *n > high || field.find('.') != std::string::npos) {
            throw expected_found(location(), what, quote_token(field));
        }
        return static_cast<int>(*n);
    }

    /// The single whitespace character that ends the header before the binary data.
    void end_of_header() {
        const int c = in_.get();
        if (c == std::char_traits<char>::eof() || !is_space(c)) {
            throw expected_found(
                location(), "one whitespace character after maxval",
                c == std::char_traits<char>::eof() ? "the end of the file" : "binary data");
        }
        ++bytes_;
        line_ += c == '\n' ? 1 : 0;
    }

    SourceLocation location() const { return {file_, line_, 0}; }
    std::uint64_t bytes() const { return bytes_; }

private:
    static bool is_space(int c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
    }

    void skip_space_and_comments() {
        for (int c = in_.peek(); c != std::char_traits<char>::eof(); c = in_.peek()) {
            if (c == '#') {
                while (c != std::char_traits<char>::eof() && c != '\n') {
                    in_.get();
                    ++bytes_;
                    c = in_.peek();
                }
            } else if (is_space(c)) {
                line_ += c == '\n' ? 1 : 0;
                in_.get();
                ++bytes_;
            } else {
                return;
            }
        }
    }

    std::istream& in_;
    std::string file_;
    int line_ = 1;
    std::uint64_t bytes_ = 0;
};

}  // namespace

void write_ppm(const Image8& image, const std::filesystem::path& path) {
    if (image.width < 1 || image.height < 1 || image.rgb.size() != image.pixel_count() * 3) {
        throw Error("cannot write " + path.string() + ": the image is empty or inconsistent");
    }
    write_file_atomically(path, [&](std::ostream& out) {
        out << "P6\n" << image.width << ' ' << image.height << "\n255\n";
        out.write(reinterpret_cast<const char*>(image.rgb.data()),
                  static_cast<std::streamsize>(image.rgb.size()));
    });
}

Image8 read_ppm(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) {
        throw IoError("cannot read " + file + ": " + ec.message());
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw IoError("cannot open " + file + ": " + std::generic_category().message(errno));
    }
    PpmHeaderReader header(in, file);
    const std::string magic = header.next_field("'P6' (a binary PPM picture)");
    if (magic != "P6") {
        throw expected_found(header.location(), "'P6' (a binary PPM picture)", quote_token(magic));
    }
    const std::string side = fmt::format("a width from 1 to {}", kMaxImageSide);
    Image8 image;
    image.width = header.next_number(side, 1, kMaxImageSide);
    image.height =
        header.next_number(fmt::format("a height from 1 to {}", kMaxImageSide), 1, kMaxImageSide);
    header.next_number("maxval 255", 255, 255);
    header.end_of_header();
    const std::uint64_t expected = image.pixel_count() * 3;
    const std::uint64_t found = size > header.bytes() ? size - header.bytes() : 0;
    if (found != expected) {
        throw expected_found(header.location(),
                             fmt::format("{} bytes of pixel data ({} x {} pixels)", expected,
                                         image.width, image.height),
                             std::to_string(found));
    }
    image.rgb.resize(expected);
    if (!in.read(reinterpret_cast<char*>(image.rgb.data()),
                 static_cast<std::streamsize>(expected))) {
        throw IoError("cannot read " + file + ": the file changed while it was read");
    }
    return image;
}

}  // namespace rt
