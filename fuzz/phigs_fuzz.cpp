// Optical surface filetype 1, the Phigs+ subset (docs/formats.md).
#include "rt/core/diagnostics.h"
#include "rt/scene/read/phigs_reader.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    fuzz::expect_value_or_input_error([&] {
        Diagnostics diagnostics;
        return read_phigs_file(fuzz::scratch_source("surface.phigs", fuzz::as_text(data, size)),
                               diagnostics);
    });
    return 0;
}
