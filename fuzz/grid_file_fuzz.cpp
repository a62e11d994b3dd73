// The polygon file of a -V texture-mapped surface: a grid of points. The rows and columns the
// .scn would give are taken from the input's own first record, so that mutations get past it.
#include "rt/core/diagnostics.h"
#include "rt/scene/read/grid_file_reader.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    const std::string_view text = fuzz::as_text(data, size);
    const fuzz::GridSize grid = fuzz::grid_size_of(text);
    fuzz::expect_value_or_input_error([&] {
        Diagnostics diagnostics;
        return read_grid_file(fuzz::scratch_source("grid.dat", text), grid.rows, grid.columns,
                              SourceLocation{"fuzz.scn", 1, 0}, diagnostics);
    });
    return 0;
}
