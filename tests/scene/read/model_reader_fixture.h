// The fixture of the model reader's tests: writes a model file into a temporary folder and reads
// it as filetype 3, or gives the message of the error it throws.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/model_reader.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {

class ModelReader : public ::testing::Test {
protected:
    SurfaceMesh read(const std::string& name, const std::string& text) {
        const std::filesystem::path path = dir_.write(name, text);
        return read_model_file(path, name, {"s.scn", 21, 0}, diagnostics_);
    }
    std::string error(const std::string& name, const std::string& text) {
        return local(input_error([&] { read(name, text); }));
    }
    std::string local(const std::string& message) const {
        return without(message, dir_.path().string() + "/");
    }
    std::vector<std::string> warnings() const {
        std::vector<std::string> out;
        for (const std::string& w : diagnostics_.warnings()) {
            out.push_back(local(w));
        }
        return out;
    }
    static std::vector<std::uint32_t> corner_counts(const SurfaceMesh& m) {
        std::vector<std::uint32_t> counts;
        for (const MeshPolygon& p : m.polygons) {
            counts.push_back(p.corner_count);
        }
        return counts;
    }

    TempDir dir_;
    Diagnostics diagnostics_;
};

}  // namespace rt::test
