// The Attributes file (manual 2.3). A first line "# fuzz-switches: -Dp -R" picks its dialect.
#include "rt/core/diagnostics.h"
#include "rt/scene/read/attributes_reader.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    const std::string_view text = fuzz::as_text(data, size);
    fuzz::expect_value_or_input_error([&] {
        Diagnostics diagnostics;
        return read_attributes_file(fuzz::scratch_source("Attributes", text),
                                    fuzz::dialect_of_input(text), diagnostics);
    });
    return 0;
}
