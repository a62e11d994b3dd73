// The shape file of -M (manual 2.4).
#include "rt/core/diagnostics.h"
#include "rt/scene/read/shape_reader.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    fuzz::expect_value_or_input_error([&] {
        Diagnostics diagnostics;
        return read_shape_file(fuzz::scratch_source("shapes", fuzz::as_text(data, size)),
                               diagnostics);
    });
    return 0;
}
