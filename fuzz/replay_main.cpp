// The main of a harness built without libFuzzer: runs LLVMFuzzerTestOneInput once on every file
// named or found (one level deep) in the directories named, as libFuzzer does on a crash input. A
// directory that does not exist holds no input (fuzz/regressions/<name>/ until a crash is found).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

void replay(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::printf("replaying %s (%zu bytes)\n", path.c_str(), bytes.size());
    std::fflush(stdout);
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

} // namespace

int main(int argc, char** argv) {
    std::size_t n = 0;
    for (int i = 1; i < argc; ++i) {
        std::filesystem::path arg(argv[i]);
        if (std::filesystem::is_directory(arg)) {
            std::vector<std::filesystem::path> files;
            for (const auto& e : std::filesystem::directory_iterator(arg)) {
                if (e.is_regular_file() && e.path().filename() != "README.md") {
                    files.push_back(e.path());
                }
            }
            std::sort(files.begin(), files.end()); // the same order on every run
            for (const auto& f : files) {
                replay(f);
                ++n;
            }
        } else if (std::filesystem::exists(arg)) {
            replay(arg);
            ++n;
        }
    }
    std::printf("%zu input(s) replayed without a crash\n", n);
    return 0;
}
