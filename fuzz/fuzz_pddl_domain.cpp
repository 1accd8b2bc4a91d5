// Fuzzes the PDDL domain reader (pddl::parse_domain), then the import of what it read into schemas
// and DPO rules and the export back to PDDL.

#include "catplan/pddl/export.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/pddl.hpp"

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    catplan::fuzz::Input in(data, size, "domain.pddl");
    auto file = in.add();
    if (auto d = catplan::pddl::parse_domain(file, in.sources, in.sink)) {
        if (auto im = catplan::pddl::import_pddl(*d, nullptr, in.sink)) {
            static_cast<void>(catplan::pddl::export_domain(*im->domain));
        }
    }
    in.drain();
    return 0;
}
