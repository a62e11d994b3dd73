// Optical surface filetype 0 (manual 2.5), read both without and with -M (marks and shapes).
#include "rt/core/diagnostics.h"
#include "rt/scene/read/polygon_file_reader.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    const std::string_view text = fuzz::as_text(data, size);
    for (const bool marks : {false, true}) {
        fuzz::expect_value_or_input_error([&] {
            Diagnostics diagnostics;
            return read_polygon_file(fuzz::scratch_source("surface", text), marks, diagnostics);
        });
    }
    return 0;
}
