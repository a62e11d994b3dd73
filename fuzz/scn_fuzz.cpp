// The .scn reader (manual 2.2) alone: header, view, attributes block, entities, -V lines. A first
// line "# fuzz-switches: -M -V -Df ..." picks the reader switches.
#include "rt/core/diagnostics.h"
#include "rt/scene/read/scn_reader.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    const std::string_view text = fuzz::as_text(data, size);
    fuzz::expect_value_or_input_error([&] {
        Diagnostics diagnostics;
        return read_scn(fuzz::scratch_source("fuzz.scn", text), fuzz::dialect_of_input(text),
                        diagnostics);
    });
    return 0;
}
