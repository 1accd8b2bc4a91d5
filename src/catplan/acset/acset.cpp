#include "catplan/acset/acset.hpp"

#include "catplan/base/assert.hpp"

#include <fmt/format.h>

namespace catplan::acset {

ACSet::ACSet(SchemaPtr schema) : schema_(std::move(schema)) {
    CATPLAN_ASSERT(schema_ != nullptr, "ACSet needs a schema");
    nparts_.assign(schema_->num_obs(), 0);
    homs_.resize(schema_->num_homs());
    attrs_.resize(schema_->num_attrs());
    nvars_.assign(schema_->num_attr_types(), 0);
    names_.resize(schema_->num_obs());
    var_names_.resize(schema_->num_attr_types());
    index_.resize(schema_->num_homs());
    var_index_.resize(schema_->num_attr_types());
    attr_slot_.resize(schema_->num_attrs());
    for (std::uint32_t t = 0; t < schema_->num_attr_types(); ++t) {
        auto into = schema_->attrs_into(AttrTypeId(t));
        for (std::size_t i = 0; i < into.size(); ++i) {
            attr_slot_[into[i].index()] = i;
        }
    }
}

Part ACSet::add_part(ObId x, std::string_view name) {
    return add_part(x, name.empty() ? Symbol() : Symbol::intern(name));
}

Part ACSet::add_part(ObId x, Symbol name) {
    auto p = static_cast<Part>(nparts_[x.index()]++);
    for (HomId f : schema_->homs_from(x)) {
        homs_[f.index()].push_back(kNoPart);
        if (index_[f.index()]) {
            index_[f.index()]->pos.push_back(0);
        }
    }
    for (HomId g : schema_->homs_into(x)) {
        if (index_[g.index()]) {
            index_[g.index()]->lists.emplace_back();
        }
    }
    for (AttrId a : schema_->attrs_from(x)) {
        attrs_[a.index()].emplace_back();
        if (auto* vx = var_index_if_built(schema_->attr(a).codom)) {
            vx->pos[attr_slot(a)].push_back(0);
        }
    }
    auto& names = names_[x.index()];
    if (name != Symbol() || !names.empty()) {
        names.resize(p); // the first name: every earlier part is unnamed
        names.push_back(name);
    }
    return p;
}

Part ACSet::add_parts(ObId x, std::size_t n) {
    std::size_t first = nparts_[x.index()];
    std::size_t total = first + n;
    CATPLAN_ASSERT(total <= kNoPart, "add_parts: too many parts");
    // Column by column, as add_part does part by part.
    for (HomId f : schema_->homs_from(x)) {
        homs_[f.index()].resize(total, kNoPart);
        if (index_[f.index()]) {
            index_[f.index()]->pos.resize(total, 0);
        }
    }
    for (HomId g : schema_->homs_into(x)) {
        if (index_[g.index()]) {
            index_[g.index()]->lists.resize(total);
        }
    }
    for (AttrId a : schema_->attrs_from(x)) {
        attrs_[a.index()].resize(total);
        if (auto* vx = var_index_if_built(schema_->attr(a).codom)) {
            vx->pos[attr_slot(a)].resize(total, 0);
        }
    }
    if (!names_[x.index()].empty()) {
        names_[x.index()].resize(total);
    }
    nparts_[x.index()] = total;
    return static_cast<Part>(first);
}

void ACSet::reserve(ObId x, std::size_t n) {
    for (HomId f : schema_->homs_from(x)) {
        homs_[f.index()].reserve(n);
    }
    for (AttrId a : schema_->attrs_from(x)) {
        attrs_[a.index()].reserve(n);
    }
    if (!names_[x.index()].empty()) {
        names_[x.index()].reserve(n);
    }
}

void ACSet::index_insert(HomId f, Part p, Part q) {
    auto& ix = *index_[f.index()];
    ix.lists[q].push_back(p);
    ix.pos[p] = static_cast<std::uint32_t>(ix.lists[q].size() - 1);
}

void ACSet::index_erase(HomId f, Part p, Part q) {
    auto& ix = *index_[f.index()];
    auto& list = ix.lists[q];
    std::uint32_t i = ix.pos[p];
    CATPLAN_ASSERT(i < list.size() && list[i] == p, "preimage index out of step");
    Part moved = list.back();
    list[i] = moved;
    ix.pos[moved] = i;
    list.pop_back();
}

void ACSet::set_subpart(HomId f, Part p, Part q) {
    const auto& info = schema_->hom(f);
    CATPLAN_ASSERT(p < nparts_[info.dom.index()], "set_subpart: part out of range");
    CATPLAN_ASSERT(q == kNoPart || q < nparts_[info.codom.index()],
                   "set_subpart: value out of range");
    Part& cell = homs_[f.index()][p];
    if (index_[f.index()]) {
        if (cell != kNoPart) {
            index_erase(f, p, cell);
        }
        if (q != kNoPart) {
            index_insert(f, p, q);
        }
    }
    cell = q;
}

void ACSet::set_column(HomId f, std::span<const Part> values) {
    const auto& info = schema_->hom(f);
    CATPLAN_ASSERT(values.size() == nparts_[info.dom.index()], "set_column: wrong length");
    // Copy and check in one pass: q is in range when q + 1 <= n (kNoPart wraps to 0). The check
    // is an or-reduction of compares, so that it vectorises with the copy.
    const auto n = static_cast<Part>(nparts_[info.codom.index()]);
    Part* col = homs_[f.index()].data();
    Part out_of_range = 0;
    for (std::size_t p = 0; p < values.size(); ++p) {
        Part q = values[p];
        out_of_range |= static_cast<Part>(static_cast<Part>(q + 1) > n);
        col[p] = q;
    }
    CATPLAN_ASSERT(out_of_range == 0, "set_column: value out of range");
    index_[f.index()].reset();
}

const ACSet::Preimage& ACSet::index(HomId f) const {
    auto& slot = index_[f.index()];
    if (!slot) {
        const auto& info = schema_->hom(f);
        Preimage ix;
        ix.lists.resize(nparts_[info.codom.index()]);
        const auto& col = homs_[f.index()];
        ix.pos.assign(col.size(), 0);
        for (Part p = 0; p < col.size(); ++p) {
            if (col[p] != kNoPart) {
                ix.pos[p] = static_cast<std::uint32_t>(ix.lists[col[p]].size());
                ix.lists[col[p]].push_back(p);
            }
        }
        slot = std::move(ix);
    }
    return *slot;
}

std::span<const Part> ACSet::incident(HomId f, Part q) const {
    CATPLAN_ASSERT(q < nparts_[schema_->hom(f).codom.index()], "incident: part out of range");
    return index(f).lists[q];
}

void ACSet::build_indexes() const {
    for (std::uint32_t f = 0; f < schema_->num_homs(); ++f) {
        index(HomId(f));
    }
}

Part ACSet::remove_part(ObId x, Part p) {
    auto n = nparts_[x.index()];
    CATPLAN_ASSERT(p < n, "remove_part: part out of range");
    auto last = static_cast<Part>(n - 1);
    // Incoming references: to p become unset, to last are redirected to p.
    for (HomId g : schema_->homs_into(x)) {
        index(g);
        std::vector<Part> refs(index(g).lists[p].begin(), index(g).lists[p].end());
        for (Part r : refs) {
            set_subpart(g, r, kNoPart);
        }
        if (p != last) {
            refs.assign(index(g).lists[last].begin(), index(g).lists[last].end());
            for (Part r : refs) {
                set_subpart(g, r, p);
            }
        }
    }
    // Outgoing columns: move last into p, then drop the last row.
    for (HomId f : schema_->homs_from(x)) {
        set_subpart(f, p, kNoPart);
        if (p != last) {
            Part w = homs_[f.index()][last];
            set_subpart(f, last, kNoPart);
            set_subpart(f, p, w);
        }
        homs_[f.index()].pop_back();
        if (index_[f.index()]) {
            index_[f.index()]->pos.pop_back();
        }
    }
    for (HomId g : schema_->homs_into(x)) {
        auto& lists = index_[g.index()]->lists;
        CATPLAN_ASSERT(lists.back().empty(), "remove_part: stale references to the last part");
        lists.pop_back();
    }
    for (AttrId a : schema_->attrs_from(x)) {
        set_subpart(a, p, Value());
        if (p != last) {
            Value moved = attrs_[a.index()][last];
            set_subpart(a, last, Value());
            set_subpart(a, p, moved);
        }
        attrs_[a.index()].pop_back();
        if (auto* vx = var_index_if_built(schema_->attr(a).codom)) {
            vx->pos[attr_slot(a)].pop_back();
        }
    }
    if (auto& names = names_[x.index()]; !names.empty()) {
        names[p] = names[last];
        names.pop_back();
    }
    --nparts_[x.index()];
    return p == last ? kNoPart : last;
}

void ACSet::set_subpart(AttrId a, Part p, Value v) {
    const auto& info = schema_->attr(a);
    CATPLAN_ASSERT(p < nparts_[info.dom.index()], "set_subpart: part out of range");
    CATPLAN_ASSERT(!v.is_var() || v.var_index() < nvars_[info.codom.index()],
                   "set_subpart: no such attribute variable");
    Value& cell = attrs_[a.index()][p];
    if (var_index_if_built(info.codom) != nullptr) {
        if (cell.is_var()) {
            var_index_erase(a, p, cell.var_index());
        }
        if (v.is_var()) {
            var_index_insert(a, p, v.var_index());
        }
    }
    cell = v;
}

void ACSet::set_column(AttrId a, std::span<const Value> values) {
    const auto& info = schema_->attr(a);
    CATPLAN_ASSERT(values.size() == nparts_[info.dom.index()], "set_column: wrong length");
    const std::uint32_t n = nvars_[info.codom.index()];
    Value* col = attrs_[a.index()].data();
    bool vars_exist = true;
    for (std::size_t p = 0; p < values.size(); ++p) {
        const Value& v = values[p];
        vars_exist &= !v.is_var() || v.var_index() < n;
        col[p] = v;
    }
    CATPLAN_ASSERT(vars_exist, "set_column: no such attribute variable");
    var_index_[info.codom.index()].reset();
}

const ACSet::VarIndex& ACSet::var_index(AttrTypeId t) const {
    auto& slot = var_index_[t.index()];
    if (!slot) {
        VarIndex ix;
        ix.lists.resize(nvars_[t.index()]);
        for (AttrId a : schema_->attrs_into(t)) {
            const auto& col = attrs_[a.index()];
            std::vector<std::uint32_t> pos(col.size(), 0);
            for (Part p = 0; p < col.size(); ++p) {
                if (col[p].is_var()) {
                    auto& list = ix.lists[col[p].var_index()];
                    pos[p] = static_cast<std::uint32_t>(list.size());
                    list.push_back({a, p});
                }
            }
            ix.pos.push_back(std::move(pos));
        }
        slot = std::move(ix);
    }
    return *slot;
}

void ACSet::var_index_insert(AttrId a, Part p, std::uint32_t var) {
    auto& ix = *var_index_[schema_->attr(a).codom.index()];
    ix.lists[var].push_back({a, p});
    ix.pos[attr_slot(a)][p] = static_cast<std::uint32_t>(ix.lists[var].size() - 1);
}

void ACSet::var_index_erase(AttrId a, Part p, std::uint32_t var) {
    auto& ix = *var_index_[schema_->attr(a).codom.index()];
    auto& list = ix.lists[var];
    std::uint32_t i = ix.pos[attr_slot(a)][p];
    CATPLAN_ASSERT(i < list.size() && list[i] == (Cell{a, p}), "variable index out of step");
    Cell moved = list.back();
    list[i] = moved;
    ix.pos[attr_slot(moved.attr)][moved.part] = i;
    list.pop_back();
}

std::span<const ACSet::Cell> ACSet::var_incident(AttrTypeId t, std::uint32_t j) const {
    CATPLAN_ASSERT(j < nvars_[t.index()], "var_incident: variable out of range");
    return var_index(t).lists[j];
}

Value ACSet::add_var(AttrTypeId t, std::string_view name) {
    auto j = nvars_[t.index()]++;
    var_names_[t.index()].push_back(name.empty() ? Symbol() : Symbol::intern(name));
    if (auto* vx = var_index_if_built(t)) {
        vx->lists.emplace_back();
    }
    return Value::var(j);
}

std::uint32_t ACSet::remove_var(AttrTypeId t, std::uint32_t j) {
    auto n = nvars_[t.index()];
    CATPLAN_ASSERT(j < n, "remove_var: variable out of range");
    std::uint32_t last = n - 1;
    var_index(t);
    std::vector<Cell> cells(var_index(t).lists[j].begin(), var_index(t).lists[j].end());
    for (const Cell& c : cells) {
        set_subpart(c.attr, c.part, Value());
    }
    if (j != last) {
        cells.assign(var_index(t).lists[last].begin(), var_index(t).lists[last].end());
        for (const Cell& c : cells) {
            set_subpart(c.attr, c.part, Value::var(j));
        }
    }
    auto& lists = var_index_[t.index()]->lists;
    CATPLAN_ASSERT(lists.back().empty(), "remove_var: stale references to the last variable");
    lists.pop_back();
    auto& names = var_names_[t.index()];
    names[j] = names[last];
    names.pop_back();
    --nvars_[t.index()];
    return j == last ? UINT32_MAX : last;
}

void ACSet::set_part_name(ObId x, Part p, std::string_view name) {
    CATPLAN_ASSERT(p < nparts_[x.index()], "set_part_name: part out of range");
    auto& names = names_[x.index()];
    if (name.empty() && names.empty()) {
        return;
    }
    names.resize(nparts_[x.index()]);
    names[p] = name.empty() ? Symbol() : Symbol::intern(name);
}

void ACSet::set_part_names(ObId x, std::vector<Symbol> names) {
    CATPLAN_ASSERT(names.empty() || names.size() == nparts_[x.index()],
                   "set_part_names: wrong length");
    names_[x.index()] = std::move(names);
}

void ACSet::set_var_name(AttrTypeId t, std::uint32_t j, std::string_view name) {
    var_names_[t.index()][j] = Symbol::intern(name);
}

std::optional<Part> ACSet::find_part(ObId x, std::string_view name) const {
    if (name.empty()) {
        return std::nullopt;
    }
    Symbol s = Symbol::intern(name);
    const auto& names = names_[x.index()];
    for (Part p = 0; p < names.size(); ++p) {
        if (names[p] == s) {
            return p;
        }
    }
    return std::nullopt;
}

std::string ACSet::part_label(ObId x, Part p) const {
    if (p == kNoPart) {
        return "_";
    }
    auto name = part_name(x, p);
    return name.empty() ? fmt::format("#{}", p + 1) : std::string(name);
}

std::string ACSet::value_label(AttrTypeId t, const Value& v) const {
    if (v.is_var() && v.var_index() < nvars_[t.index()]) {
        auto name = var_name(t, v.var_index());
        if (!name.empty()) {
            return fmt::format("?{}", name);
        }
    }
    return v.to_string();
}

std::size_t ACSet::total_parts() const {
    std::size_t total = 0;
    for (auto n : nparts_) {
        total += n;
    }
    return total;
}

bool operator==(const ACSet& a, const ACSet& b) {
    if (a.schema_ != b.schema_) {
        const auto& s = *a.schema_;
        const auto& t = *b.schema_;
        if (s.num_obs() != t.num_obs() || s.num_homs() != t.num_homs() ||
            s.num_attrs() != t.num_attrs() || s.num_attr_types() != t.num_attr_types()) {
            return false;
        }
    }
    return a.nparts_ == b.nparts_ && a.homs_ == b.homs_ && a.attrs_ == b.attrs_ &&
           a.nvars_ == b.nvars_;
}

} // namespace catplan::acset
