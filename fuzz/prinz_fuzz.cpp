// Optical surface filetype 2, the Prinz polygonizer's format (manual 2.5).
#include "rt/core/diagnostics.h"
#include "rt/scene/read/prinz_reader.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    fuzz::expect_value_or_input_error([&] {
        Diagnostics diagnostics;
        return read_prinz_file(fuzz::scratch_source("surface.prinz", fuzz::as_text(data, size)),
                               diagnostics);
    });
    return 0;
}
