#include "catplan/schema/schema.hpp"

#include "catplan/base/assert.hpp"

#include <deque>
#include <fmt/format.h>
#include <set>

namespace catplan::schema {

std::string_view to_string(ValueKind kind) {
    switch (kind) {
    case ValueKind::Unknown:
        return "Unknown";
    case ValueKind::Bool:
        return "Bool";
    case ValueKind::Int:
        return "Int";
    case ValueKind::Float:
        return "Float";
    case ValueKind::String:
        return "String";
    }
    return "Unknown";
}

const char* kind_noun(GeneratorKind k) {
    switch (k) {
    case GeneratorKind::Ob:
        return "an object";
    case GeneratorKind::Hom:
        return "a hom";
    case GeneratorKind::AttrType:
        return "an attribute type";
    case GeneratorKind::Attr:
        return "an attribute";
    }
    return "a generator";
}

std::optional<ValueKind> parse_value_kind(std::string_view name) {
    if (name == "Bool") {
        return ValueKind::Bool;
    }
    if (name == "Int" || name == "Int64" || name == "Integer") {
        return ValueKind::Int;
    }
    if (name == "Float" || name == "Float64" || name == "Real") {
        return ValueKind::Float;
    }
    if (name == "String" || name == "Symbol") {
        return ValueKind::String;
    }
    return std::nullopt;
}

ObId Schema::add_ob(std::string name, SourceRange range) {
    CATPLAN_ASSERT(!find(name), "duplicate generator name");
    ObId id(static_cast<std::uint32_t>(obs_.size()));
    names_.emplace(name, Generator{GeneratorKind::Ob, id.index()});
    obs_.push_back({std::move(name), range});
    homs_from_.emplace_back();
    homs_into_.emplace_back();
    attrs_from_.emplace_back();
    return id;
}

HomId Schema::add_hom(std::string name, ObId dom, ObId codom, SourceRange range) {
    CATPLAN_ASSERT(!find(name), "duplicate generator name");
    CATPLAN_ASSERT(dom.index() < obs_.size() && codom.index() < obs_.size(), "bad hom ends");
    HomId id(static_cast<std::uint32_t>(homs_.size()));
    names_.emplace(name, Generator{GeneratorKind::Hom, id.index()});
    homs_.push_back({std::move(name), dom, codom, range});
    homs_from_[dom.index()].push_back(id);
    homs_into_[codom.index()].push_back(id);
    return id;
}

AttrTypeId Schema::add_attr_type(std::string name, ValueKind kind, SourceRange range) {
    CATPLAN_ASSERT(!find(name), "duplicate generator name");
    AttrTypeId id(static_cast<std::uint32_t>(attr_types_.size()));
    names_.emplace(name, Generator{GeneratorKind::AttrType, id.index()});
    attr_types_.push_back({std::move(name), kind, range});
    attrs_into_.emplace_back();
    return id;
}

AttrId Schema::add_attr(std::string name, ObId dom, AttrTypeId codom, SourceRange range) {
    CATPLAN_ASSERT(!find(name), "duplicate generator name");
    CATPLAN_ASSERT(dom.index() < obs_.size() && codom.index() < attr_types_.size(),
                   "bad attr ends");
    AttrId id(static_cast<std::uint32_t>(attrs_.size()));
    names_.emplace(name, Generator{GeneratorKind::Attr, id.index()});
    attrs_.push_back({std::move(name), dom, codom, range});
    attrs_from_[dom.index()].push_back(id);
    attrs_into_[codom.index()].push_back(id);
    return id;
}

void Schema::add_equation(Equation eq) {
    CATPLAN_ASSERT(is_well_formed(eq.lhs) && is_well_formed(eq.rhs), "ill-formed path");
    CATPLAN_ASSERT(eq.lhs.dom == eq.rhs.dom, "equation sides start at different objects");
    CATPLAN_ASSERT(eq.lhs.attr.has_value() == eq.rhs.attr.has_value(), "equation sides differ");
    equations_.push_back(std::move(eq));
}

std::optional<Generator> Schema::find(std::string_view name) const {
    auto it = names_.find(std::string(name));
    if (it == names_.end()) {
        return std::nullopt;
    }
    return it->second;
}

namespace {

template <class IdT>
std::optional<IdT> find_kind(const Schema& s, std::string_view name, GeneratorKind kind) {
    auto g = s.find(name);
    if (!g || g->kind != kind) {
        return std::nullopt;
    }
    return IdT(g->index);
}

} // namespace

std::optional<ObId> Schema::find_ob(std::string_view name) const {
    return find_kind<ObId>(*this, name, GeneratorKind::Ob);
}

std::optional<HomId> Schema::find_hom(std::string_view name) const {
    return find_kind<HomId>(*this, name, GeneratorKind::Hom);
}

std::optional<AttrTypeId> Schema::find_attr_type(std::string_view name) const {
    return find_kind<AttrTypeId>(*this, name, GeneratorKind::AttrType);
}

std::optional<AttrId> Schema::find_attr(std::string_view name) const {
    return find_kind<AttrId>(*this, name, GeneratorKind::Attr);
}

ObId Schema::path_codom_ob(const Path& p) const {
    CATPLAN_ASSERT(!p.attr, "path ends in an attribute type");
    return p.homs.empty() ? p.dom : hom(p.homs.back()).codom;
}

bool Schema::is_well_formed(const Path& p) const {
    ObId at = p.dom;
    for (HomId f : p.homs) {
        if (hom(f).dom != at) {
            return false;
        }
        at = hom(f).codom;
    }
    return !p.attr || attr(*p.attr).dom == at;
}

bool Schema::is_cyclic() const {
    // Kahn's algorithm on the hom graph.
    std::vector<std::size_t> indegree(obs_.size(), 0);
    for (const auto& h : homs_) {
        ++indegree[h.codom.index()];
    }
    std::vector<std::uint32_t> ready;
    for (std::uint32_t i = 0; i < obs_.size(); ++i) {
        if (indegree[i] == 0) {
            ready.push_back(i);
        }
    }
    std::size_t seen = 0;
    while (!ready.empty()) {
        auto x = ready.back();
        ready.pop_back();
        ++seen;
        for (HomId f : homs_from_[x]) {
            if (--indegree[hom(f).codom.index()] == 0) {
                ready.push_back(hom(f).codom.index());
            }
        }
    }
    return seen != obs_.size();
}

namespace {

// A path as a word over arrows: homs are their index, the final attribute is num_homs + index.
using Word = std::vector<std::uint32_t>;

Word to_word(const Schema& s, const Path& p) {
    Word w;
    for (HomId f : p.homs) {
        w.push_back(f.index());
    }
    if (p.attr) {
        w.push_back(static_cast<std::uint32_t>(s.num_homs()) + p.attr->index());
    }
    return w;
}

} // namespace

bool Schema::paths_equal(const Path& a, const Path& b) const {
    if (a == b) {
        return true;
    }
    if (a.dom != b.dom || a.attr.has_value() != b.attr.has_value()) {
        return false;
    }
    if (equations_.empty()) {
        return false;
    }
    // Breadth-first search over the words reachable from a by replacing an occurrence of one side
    // of an equation with the other. The equation's start object is implied by its first arrow,
    // except for an identity side, which we never rewrite from (it would match everywhere).
    std::vector<std::pair<Word, Word>> rules;
    std::size_t longest = 0;
    for (const auto& eq : equations_) {
        Word l = to_word(*this, eq.lhs), r = to_word(*this, eq.rhs);
        longest = std::max({longest, l.size(), r.size()});
        if (!l.empty()) {
            rules.emplace_back(l, r);
        }
        if (!r.empty()) {
            rules.emplace_back(r, l);
        }
    }
    Word start = to_word(*this, a), goal = to_word(*this, b);
    // Acyclic: every path is shorter than the number of objects, so the bound is exact.
    std::size_t bound =
        is_cyclic() ? std::max(start.size(), goal.size()) + 2 * longest : obs_.size() + 1;
    constexpr std::size_t kMaxWords = 200000;
    std::set<Word> seen{start};
    std::deque<Word> queue{start};
    while (!queue.empty() && seen.size() < kMaxWords) {
        Word w = std::move(queue.front());
        queue.pop_front();
        for (const auto& [from, to] : rules) {
            if (from.size() > w.size()) {
                continue;
            }
            for (std::size_t i = 0; i + from.size() <= w.size(); ++i) {
                if (!std::equal(from.begin(), from.end(), w.begin() + static_cast<long>(i))) {
                    continue;
                }
                Word next(w.begin(), w.begin() + static_cast<long>(i));
                next.insert(next.end(), to.begin(), to.end());
                next.insert(next.end(), w.begin() + static_cast<long>(i + from.size()), w.end());
                if (next.size() > bound || !seen.insert(next).second) {
                    continue;
                }
                if (next == goal) {
                    return true;
                }
                queue.push_back(std::move(next));
            }
        }
    }
    return false;
}

std::string Schema::path_to_string(const Path& p) const {
    if (p.homs.empty() && !p.attr) {
        return fmt::format("id({})", ob(p.dom).name);
    }
    std::string out;
    for (HomId f : p.homs) {
        if (!out.empty()) {
            out += " ⋅ ";
        }
        out += hom(f).name;
    }
    if (p.attr) {
        if (!out.empty()) {
            out += " ⋅ ";
        }
        out += attr(*p.attr).name;
    }
    return out;
}

} // namespace catplan::schema
