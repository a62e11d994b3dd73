// The main() of a fuzz target built without libFuzzer: runs LLVMFuzzerTestOneInput once on each
// file named on the command line, as libFuzzer does with files, so that the normal build replays
// every kept finding (fuzz/regressions) and a few seeds. Words starting with '-' (libFuzzer's
// flags) are ignored, so one command line serves both builds.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
    int replayed = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string name = argv[i];
        if (name.empty() || name[0] == '-') {
            continue;
        }
        std::ifstream in(name, std::ios::binary);
        if (!in) {
            std::fprintf(stderr, "cannot read %s\n", name.c_str());
            return 2;
        }
        const std::vector<char> bytes{std::istreambuf_iterator<char>(in),
                                      std::istreambuf_iterator<char>()};
        std::fprintf(stderr, "replaying %s\n", name.c_str());
        try {
            LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                   bytes.size());
        } catch (const std::exception& e) {
            std::fprintf(stderr, "rt fuzz finding: %s: uncaught exception: %s\n", name.c_str(),
                         e.what());
            return 1;
        }
        ++replayed;
    }
    std::fprintf(stderr, "replayed %d inputs\n", replayed);
    return 0;
}
