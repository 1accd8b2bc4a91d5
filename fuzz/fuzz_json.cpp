// Fuzzes Catlab's ACSet JSON: the input read as a schema, and as an instance of two fixed schemas
// (the graph schema, and ColorBlocksworld with its attributes), written back when it reads.

#include "catplan/json/json.hpp"
#include "catplan/lang/module.hpp"

#include <cstdio>
#include <cstdlib>

#include "fuzz_input.hpp"

namespace {

struct Schemas {
    catplan::schema::SchemaPtr graph, blocks;
};

// Read once from the repository; the harness is useless without them, so it stops loudly.
const Schemas& schemas() {
    static const Schemas s = [] {
        Schemas r;
        catplan::SourceManager sources;
        catplan::DiagnosticSink sink{sources};
        auto g = sources.add_buffer("schgraph.json",
                                    catplan::fuzz::repo_file("tests/cli/data/schgraph.json"));
        r.graph = catplan::json::read_schema("Graph", g, sources, sink);
        auto m = catplan::lang::load_file(std::string(CATPLAN_SOURCE_DIR) +
                                              "/examples/colorblocksworld/colorblocksworld.cp",
                                          sources, sink);
        if (const auto* d = m.find("ColorBlocksworld")) {
            r.blocks = d->schema;
        }
        if (r.graph == nullptr || r.blocks == nullptr) {
            std::fprintf(stderr, "fuzz_json: cannot read the schemas of the repository\n%s",
                         sink.render().c_str());
            std::abort();
        }
        return r;
    }();
    return s;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto& s = schemas();
    catplan::fuzz::Input in(data, size, "input.json");
    auto file = in.add();
    if (auto sch = catplan::json::read_schema("S", file, in.sources, in.sink)) {
        static_cast<void>(catplan::json::write_schema(*sch));
    }
    for (const auto& schema : {s.graph, s.blocks}) {
        if (auto x = catplan::json::read_acset(schema, file, in.sources, in.sink)) {
            static_cast<void>(catplan::json::write_acset(*x));
        }
    }
    in.drain();
    return 0;
}
