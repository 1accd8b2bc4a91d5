#include "catplan/hom/hom_search.hpp"

#include "catplan/hom/detail/search_engine.hpp"

namespace catplan::hom {

HomSearchResult find_homomorphisms(const ACSet& x, const ACSet& y,
                                   const HomSearchOptions& options) {
    return detail::run_search(x, y, options, detail::SearchMode::Collect);
}

Result<ACSetMorphism> find_homomorphism(const ACSet& x, const ACSet& y,
                                        const HomSearchOptions& options) {
    HomSearchOptions first = options;
    first.max_results = 1;
    HomSearchResult r = detail::run_search(x, y, first, detail::SearchMode::Collect);
    if (!r.error.empty()) {
        return fail(r.error);
    }
    if (r.morphisms.empty()) {
        return fail(r.complete ? "no homomorphism exists"
                               : "the search limit was reached before a homomorphism was found");
    }
    return std::move(r.morphisms.front());
}

HomSearchResult count_homomorphisms(const ACSet& x, const ACSet& y,
                                    const HomSearchOptions& options) {
    return detail::run_search(x, y, options, detail::SearchMode::Count);
}

bool is_homomorphic(const ACSet& x, const ACSet& y, const HomSearchOptions& options) {
    HomSearchOptions first = options;
    first.max_results = 1;
    return detail::run_search(x, y, first, detail::SearchMode::Count).count > 0;
}

HomSearchResult for_each_homomorphism(const ACSet& x, const ACSet& y,
                                      const HomSearchOptions& options,
                                      const std::function<bool(const ACSetMorphism&)>& fn) {
    return detail::run_search(x, y, options, detail::SearchMode::Callback, &fn);
}

} // namespace catplan::hom
