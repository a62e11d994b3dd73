// The .gro picture file (docs/formats.md): the whole reader, and the header-only reader of
// show --info. The pixel block has no lines, so an error there may name the file alone.
#include "rt/image/gro_format.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    const std::filesystem::path path =
        fuzz::write_scratch_file("picture.gro", fuzz::as_text(data, size));
    fuzz::expect_value_or_input_error([&] { return read_gro_header_only(path); },
                                      fuzz::Where::File);
    fuzz::expect_value_or_input_error([&] { return read_gro(path); }, fuzz::Where::File);
    return 0;
}
