// The texture map of a -V texture-mapped surface. The rows and columns the .scn would give are
// taken from the input's own first record, so that mutations get past it.
#include "rt/core/diagnostics.h"
#include "rt/scene/read/texture_map_reader.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    const std::string_view text = fuzz::as_text(data, size);
    const fuzz::GridSize grid = fuzz::grid_size_of(text);
    fuzz::expect_value_or_input_error([&] {
        Diagnostics diagnostics;
        return read_texture_map(fuzz::scratch_source("map.dat", text), grid.rows, grid.columns,
                                SourceLocation{"fuzz.scn", 1, 0}, diagnostics);
    });
    return 0;
}
