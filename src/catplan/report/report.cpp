#include "catplan/report/report.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/migrate/describe.hpp"
#include "catplan/report/explain.hpp"
#include "catplan/report/svg.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <set>
#include <vector>

namespace catplan::report {

namespace {

using dot::escape_html;
using transfer::Fault;
using transfer::TransferResult;
using transfer::Verdict;

constexpr std::string_view kStyle = R"(
body { font-family: system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif;
       margin: 0 auto; max-width: 1400px; padding: 1em 2em; color: #222; background: #fff; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; }
h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; padding-bottom: 0.2em; margin-top: 1.6em; }
.verdict { font-size: 1.3em; font-weight: bold; padding: 0.5em 0.8em; border-radius: 6px; }
.valid { background: #e3f4e1; color: #1d5e1a; border: 1px solid #9ccf97; }
.invalid { background: #fbe3e3; color: #8a1f1f; border: 1px solid #e0a0a0; }
.diverged { background: #fdf3d8; color: #6b4b00; border: 1px solid #e3c77a; }
.muted { color: #666; }
.bar { background: #eee; border-radius: 4px; height: 14px; width: 320px; display: inline-block;
       vertical-align: middle; overflow: hidden; }
.bar > span { display: block; height: 100%; background: #4a8f43; }
table { border-collapse: collapse; }
th, td { border: 1px solid #ddd; padding: 0.35em 0.6em; text-align: left; vertical-align: top; }
th { background: #f4f4f4; }
table.steps { width: 100%; }
table.steps td.num { text-align: right; color: #666; width: 2em; }
code, .step { font-family: ui-monospace, "DejaVu Sans Mono", Menlo, monospace; }
.step { font-weight: bold; }
ul.bindings { margin: 0.3em 0 0 0; padding-left: 1.2em; font-family: ui-monospace, monospace;
              font-size: 0.9em; }
ul.bindings li.shared { font-weight: bold; }
ul.reasons { margin: 0.3em 0 0 0; padding-left: 1.2em; font-size: 0.85em; color: #333; }
.brief { background: #f6f8fb; border: 1px solid #d5deea; border-radius: 6px; padding: 0.2em 1em; }
/* What a step deletes and creates, in its state pictures (classes set by explain.hpp). */
.deleted polygon, .deleted path, .deleted ellipse { stroke: #c0392b; stroke-width: 3px;
                                                    stroke-dasharray: 6 3; }
.created polygon, .created path, .created ellipse { stroke: #1e8a3a; stroke-width: 3px; }
.matched polygon, .matched path, .matched ellipse { stroke: #1f5fbf; stroke-width: 3px; }
.legend { font-size: 0.85em; color: #444; }
p.values { font-size: 0.8em; color: #555; margin: 0.2em 0 0 0; }
.swatch { display: inline-block; width: 1.4em; height: 0.8em; vertical-align: middle;
          border-radius: 3px; margin-left: 0.6em; }
.swatch.deleted { border: 3px dashed #c0392b; }
.swatch.matched { border: 3px solid #1f5fbf; }
.swatch.created { border: 3px solid #1e8a3a; }
.note { color: #8a5a00; font-size: 0.9em; }
.failed { color: #8a1f1f; font-weight: bold; }
.pictures { display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; }
.grid { display: grid; grid-template-columns: 1fr 1fr; gap: 0.8em; }
figure { margin: 0; border: 1px solid #e4e4e4; border-radius: 4px; padding: 0.4em;
         background: #fff; overflow: auto; }
figure.wide { max-width: 100%; }
figcaption { font-size: 0.85em; color: #555; margin-bottom: 0.3em; }
svg { max-width: 100%; height: auto; }
details { margin: 0.4em 0; }
summary { cursor: pointer; color: #1b4f8a; }
.error { color: #8a1f1f; font-style: italic; }
footer { margin-top: 2em; font-size: 0.8em; color: #777; }
)";

/// Pictures made on demand, rendered once per DOT text and inlined with fresh ids each time.
class Pictures {
public:
    /// A <figure> with the picture of `dot` and a caption.
    std::string figure(const std::string& dot, std::string_view caption,
                       std::string_view css_class = {}, std::string_view note = {}) {
        std::string body;
        auto it = std::find_if(cache_.begin(), cache_.end(),
                               [&](const auto& e) { return e.first == dot; });
        if (it == cache_.end()) {
            auto svg = renderer_.render(dot);
            cache_.emplace_back(dot, svg ? *svg : std::string());
            // One line per reason: without Graphviz every picture fails for the same one.
            if (!svg && std::find(errors_.begin(), errors_.end(), svg.error()) == errors_.end()) {
                errors_.push_back(svg.error());
            }
            it = std::prev(cache_.end());
        }
        if (it->second.empty()) {
            body = "<p class=\"error\">(no picture: Graphviz failed)</p>";
        } else {
            body = inline_svg(it->second, fmt::format("p{}", ++count_));
        }
        if (!note.empty()) {
            body += fmt::format("<p class=\"values\">{}</p>", escape_html(note));
        }
        return fmt::format("<figure{}><figcaption>{}</figcaption>{}</figure>\n",
                           css_class.empty() ? "" : fmt::format(" class=\"{}\"", css_class),
                           escape_html(caption), body);
    }

    /// Why pictures are missing, if any are.
    const std::vector<std::string>& errors() const { return errors_; }

private:
    SvgRenderer renderer_;
    std::vector<std::pair<std::string, std::string>> cache_; // DOT text, SVG ("" on failure)
    std::vector<std::string> errors_;
    std::size_t count_ = 0;
};

std::string header_section(const ReportInput& in) {
    const TransferResult& t = *in.transfer;
    const Verdict& v = t.verdict;
    const auto& f = *in.map;
    std::string o;
    o += fmt::format("<h1>Plan transfer of {} along {}</h1>\n", escape_html(in.problem->name),
                     escape_html(in.map_name));
    o += fmt::format("<p class=\"muted\">{} : {} → {} ({} migration); source domain {}, "
                     "{} source steps</p>\n",
                     escape_html(in.map_name), escape_html(f.target()->name()),
                     escape_html(f.source()->name()), transfer::to_string(t.migration),
                     escape_html(in.problem->domain->name), in.plan->steps.size());
    // A valid transfer whose trajectory diverges is shown as a caveat, not as plainly valid.
    const char* tone = !v.valid() ? "invalid" : (v.diverged() ? "diverged" : "valid");
    std::string summary = v.summary();
    summary[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(summary[0])));
    o += fmt::format("<p class=\"verdict {}\">{}</p>\n", tone, escape_html(summary));
    if (const auto* source = v.find(Fault::Kind::SourcePlan)) {
        o += fmt::format("<p class=\"failed\">The source plan itself is invalid: {}</p>\n",
                         escape_html(source->to_string()));
    }
    for (const auto& d : v.divergences) {
        o += fmt::format("<p class=\"failed\">Diverged: {}</p>\n", escape_html(d.to_string()));
    }
    const auto& claim = v.claim(transfer::Claim::Kind::ValidByConstruction);
    if (const auto* no = claim.failing()) {
        o += fmt::format("<p class=\"muted\">Not valid by construction: paper Appendix A assumes "
                         "{}, but {}. Every step was checked.</p>\n",
                         escape_html(no->statement), escape_html(no->why_not));
    } else {
        o += "<p class=\"muted\">A delta migration preserves pushouts: the transferred plan is "
             "valid by construction (paper, Appendix A); it was checked anyway.</p>\n";
    }
    return o;
}

/// "In brief": what each target object is sent to and what the map does not see, in words.
std::string brief_section(const ReportInput& in) {
    const auto& f = *in.map;
    MapSummary brief = summarize_map(f);
    std::string o = "<section class=\"brief\">\n<h2>In brief</h2>\n";
    o += fmt::format("<p>The map {} sends each {} object to a {} object or to a set of them (a "
                     "query); a target step is the source step read through these images.</p>"
                     "\n<ul>\n",
                     escape_html(in.map_name), escape_html(f.target()->name()),
                     escape_html(f.source()->name()));
    for (const auto& line : brief.objects) {
        o += fmt::format("<li><code>{} ⇒ {}</code></li>\n", escape_html(line.name),
                         escape_html(line.image));
    }
    o += "</ul>\n";
    if (brief.lost.empty()) {
        o += "<p>Every source generator has an image: the map loses nothing.</p>\n";
        return o + "</section>\n";
    }
    o += "<p>What the map loses (no target generator maps onto these source generators, so "
         "the target states and plan say nothing of them):</p>\n<ul>\n";
    using schema::GeneratorKind;
    for (auto [kind, noun] :
         {std::pair{GeneratorKind::Ob, "objects"}, std::pair{GeneratorKind::Hom, "homs"},
          std::pair{GeneratorKind::AttrType, "attribute types"},
          std::pair{GeneratorKind::Attr, "attributes"}}) {
        if (auto names = lost_names(brief, kind); !names.empty()) {
            o += fmt::format("<li>{}: <code>{}</code></li>\n", noun, escape_html(names));
        }
    }
    return o + "</ul>\n</section>\n";
}

std::string goal_section(const Verdict& v) {
    const auto& g = v.goal;
    std::string o = "<h2>Goal satisfaction</h2>\n";
    double pct = 100 * g.fraction();
    o += fmt::format("<p><span class=\"bar\"><span style=\"width: {:.1f}%\"></span></span> "
                     "<b>{:.0f}%</b> ({} of {} goal statements{})</p>\n",
                     pct, pct, g.satisfied, g.total,
                     g.exact ? "" : ", at least: the search was cut short");
    if (g.unsatisfied.empty()) {
        o += "<p>Every goal statement holds in the last target state.</p>\n";
        return o;
    }
    o += "<p>Unsatisfied statements:</p>\n<ul>\n";
    for (const auto& u : g.unsatisfied) {
        o += fmt::format("<li><code>{}</code></li>\n", escape_html(u));
    }
    o += "</ul>\n";
    return o;
}

std::string ontology_section(const ReportInput& in, Pictures& pictures) {
    const auto& f = *in.map;
    std::string o = "<h2>The ontologies and the map</h2>\n<div class=\"pictures\">\n";
    // Left to right: an ontology with many attributes is unreadably wide top to bottom.
    dot::DotOptions lr = in.dot;
    lr.left_to_right = true;
    o += pictures.figure(dot::schema_to_dot(*f.source(), lr),
                         fmt::format("source ontology {}", f.source()->name()));
    o += pictures.figure(dot::schema_to_dot(*f.target(), lr),
                         fmt::format("target ontology {}", f.target()->name()));
    o += "</div>\n";
    o += pictures.figure(
        dot::map_to_dot(f, in.map_name, in.dot),
        fmt::format("the map {}: dashed blue edges go from each target object to its "
                    "image, through a query box for a conjunctive image",
                    in.map_name),
        "wide");
    o += "<details><summary>The map in words (one line per target generator)</summary>\n"
         "<table><tr><th>target generator</th><th>image</th></tr>\n";
    for (const auto& line : migrate::describe_map(f)) {
        o += fmt::format("<tr><td><code>{}</code></td><td><code>{}</code></td></tr>\n",
                         escape_html(line.name), escape_html(line.image));
    }
    o += "</table></details>\n";
    return o;
}

/// The part names a binding text "a ↦ E, b ↦ D" binds ({E, D}).
std::vector<std::string> split_bindings(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find(", ", start);
        if (end == std::string::npos) {
            end = text.size();
        }
        out.push_back(text.substr(start, end - start));
        start = end + 2;
    }
    return out;
}

// The rule generator a binding "block ↦ E" binds ("block"); "" when it is not a binding.
std::string bound_generator(const std::string& binding) {
    static constexpr std::string_view kArrow = " ↦ ";
    std::size_t at = binding.find(kArrow);
    return at == std::string::npos ? std::string() : binding.substr(0, at);
}

/// A list of bindings; those of a generator in `shared` are bold (the generators both matches
/// bind: a migrated rule's parts are named after the source rule's, so they are the parts the
/// map carries, whatever the bound parts are called in the target).
std::string bindings_list(const std::string& text, const std::set<std::string>& shared) {
    auto items = split_bindings(text);
    if (items.empty()) {
        return "<p class=\"muted\">(binds nothing)</p>";
    }
    std::string o = "<ul class=\"bindings\">";
    for (const auto& b : items) {
        bool is_shared = shared.count(bound_generator(b)) > 0;
        o += fmt::format("<li{}>{}</li>", is_shared ? " class=\"shared\"" : "", escape_html(b));
    }
    return o + "</ul>";
}

std::set<std::string> bound_generators(const std::string& text) {
    std::set<std::string> out;
    for (const auto& b : split_bindings(text)) {
        if (auto g = bound_generator(b); !g.empty()) {
            out.insert(g);
        }
    }
    return out;
}

/// The source action of step i and its migration (each null when there is none).
std::pair<const rewrite::Rule*, const rewrite::Rule*> rules_of(const ReportInput& in,
                                                               std::size_t i) {
    const TransferResult& t = *in.transfer;
    const std::string& action = t.steps[i].source.action;
    return {in.problem->domain->find_rule(action),
            t.target_domain.domain ? t.target_domain.domain->find_rule(action) : nullptr};
}

/// A state's picture: parts called by readable labels, and the attribute values that every part
/// of an object shares said once under it rather than on each part, so the picture stays
/// legible at the page's width.
std::string state_figure(const ReportInput& in, Pictures& pictures, const acset::ACSet& x,
                         std::string_view name, std::string_view caption,
                         const std::vector<dot::PartClass>& classes = {}) {
    dot::DotOptions options = in.dot;
    std::vector<std::string> notes;
    for (const auto& u : uniform_values(x)) {
        const std::string& ob = x.schema().ob(u.ob).name;
        options.attributes_hidden.push_back(ob);
        notes.push_back(fmt::format("{} {}: {}", x.num_parts(u.ob) == 1 ? "the" : "every", ob,
                                    fmt::join(u.values, ", ")));
    }
    std::string note =
        notes.empty() ? std::string() : fmt::format("Not drawn: {}.", fmt::join(notes, "; "));
    return pictures.figure(dot::state_to_dot(x, name, options, classes, readable_labels(x)),
                           caption, {}, note);
}

std::string states_details(const ReportInput& in, std::size_t i, Pictures& pictures) {
    const TransferResult& t = *in.transfer;
    if (t.source_states.size() <= i + 1 || t.target_states.size() <= i + 1) {
        return {};
    }
    std::string o =
        fmt::format("<details><summary>States before and after step {}</summary>\n", i + 1);
    o += "<p class=\"legend\"><span class=\"swatch matched\"></span> bound by the match and "
         "kept <span class=\"swatch deleted\"></span> deleted by the step (in the state before) "
         "<span class=\"swatch created\"></span> created by the step (in the state after)</p>\n"
         "<div class=\"grid\">\n";
    auto [source_rule, target_rule] = rules_of(in, i);
    StepMarks marks = step_marks(source_rule, target_rule, t.steps[i]);
    auto state = [&](const acset::ACSet& x, const std::string& name, const std::string& caption,
                     const std::vector<dot::PartClass>& classes) {
        return state_figure(in, pictures, x, name, caption, classes);
    };
    o += state(t.source_states[i], fmt::format("X{}", i), fmt::format("source before: X{}", i),
               marks.source_before);
    o += state(t.target_states[i], fmt::format("Y{}", i), fmt::format("target before: Y{}", i),
               marks.target_before);
    o += state(t.source_states[i + 1], fmt::format("X{}", i + 1),
               fmt::format("source after: X{}", i + 1), marks.source_after);
    o += state(t.target_states[i + 1], fmt::format("Y{}", i + 1),
               fmt::format("target after: Y{}", i + 1), marks.target_after);
    return o + "</div></details>\n";
}

/// Why each target part bound is the image of the source part bound (explain.hpp), as a list;
/// "" when the states were not kept or the step was not carried out by its generated action.
std::string reasons_list(const ReportInput& in, std::size_t i) {
    const TransferResult& t = *in.transfer;
    const auto& st = t.steps[i];
    auto [source_rule, target_rule] = rules_of(in, i);
    if (source_rule == nullptr || target_rule == nullptr || t.source_states.size() <= i ||
        t.target_states.size() <= i) {
        return {};
    }
    auto reasons = binding_reasons(*in.map, *source_rule, *target_rule, st, t.source_states[i],
                                   t.target_states[i]);
    if (reasons.empty()) {
        return {};
    }
    std::string o = "<ul class=\"reasons\">";
    for (const auto& r : reasons) {
        o += fmt::format("<li>{}</li>", escape_html(r));
    }
    return o + "</ul>";
}

/// The start of step i's row, anchored as `#step-N` (N counted from 1) so that a step can be
/// linked to.
std::string step_opening(std::size_t i) {
    return fmt::format("<tr id=\"step-{0}\"><td class=\"num\"><a href=\"#step-{0}\">{0}</a></td>",
                       i + 1);
}

std::string step_row(const ReportInput& in, std::size_t i, Pictures& pictures) {
    const auto& st = in.transfer->steps[i];
    auto source_generators = bound_generators(st.source_bindings);
    auto target_generators = bound_generators(st.target_bindings);
    std::set<std::string> shared;
    std::set_intersection(source_generators.begin(), source_generators.end(),
                          target_generators.begin(), target_generators.end(),
                          std::inserter(shared, shared.end()));
    std::string o = step_opening(i);
    o += fmt::format("<td><span class=\"step\">{}</span>{}</td>",
                     escape_html(st.source.to_string()), bindings_list(st.source_bindings, shared));
    o += fmt::format("<td><span class=\"step\">{}</span>{}", escape_html(st.target.to_string()),
                     bindings_list(st.target_bindings, shared));
    o += reasons_list(in, i);
    if (!st.lost_parameters.empty()) {
        std::string lost;
        for (const auto& p : st.lost_parameters) {
            lost += (lost.empty() ? "" : ", ") + p;
        }
        o += fmt::format("<p class=\"note\">The map does not see parameter(s) {} of {}.</p>",
                         escape_html(lost), escape_html(st.source.action));
    }
    o += "</td></tr>\n";
    std::string states = states_details(in, i, pictures);
    if (!states.empty()) {
        o += fmt::format("<tr><td></td><td colspan=\"2\">{}</td></tr>\n", states);
    }
    return o;
}

std::string steps_section(const ReportInput& in, Pictures& pictures) {
    const TransferResult& t = *in.transfer;
    const auto& f = *in.map;
    std::string o = "<h2>The plans, step by step</h2>\n";
    o += "<p>Each target step applies the migrated action Δ<sub>F</sub>(a) of its source step. "
         "Its match is the source match carried through part names: every part of the migrated "
         "precondition is named after the source part its tuple starts at, so the target match "
         "binds the target parts named like the source parts that the source match binds. "
         "Bold bindings are those of the generators both actions have (the parts the map carries); "
         "below them, each target part bound is given with the reason it is the image of the "
         "source part: what the source state says of that part and the map's image of its object; "
         "open a step to see the states before "
         "and after it on both sides.</p>\n";
    o += fmt::format("<table class=\"steps\"><tr><th>#</th><th>source step ({})</th>"
                     "<th>target step ({})</th></tr>\n",
                     escape_html(f.source()->name()), escape_html(f.target()->name()));
    for (std::size_t i = 0; i < t.steps.size(); ++i) {
        o += step_row(in, i, pictures);
    }
    if (const auto* failed = t.verdict.failed_step()) {
        std::size_t i = *failed->step;
        std::string source =
            i < in.plan->steps.size() ? in.plan->steps[i].to_string() : std::string("?");
        std::string why = failed->kind == Fault::Kind::SourcePlan
                              ? "the source plan fails here: " + failed->why
                              : failed->why;
        o += step_opening(i) + fmt::format("<td><span class=\"step\">{}</span></td>"
                                           "<td class=\"failed\">not transferred: {}</td></tr>\n",
                                           escape_html(source), escape_html(why));
        for (std::size_t j = i + 1; j < in.plan->steps.size(); ++j) {
            o += step_opening(j) + fmt::format("<td><span class=\"step\">{}</span>"
                                               "</td><td class=\"muted\">(not reached)</td></tr>\n",
                                               escape_html(in.plan->steps[j].to_string()));
        }
    }
    o += "</table>\n";
    return o;
}

std::string problem_section(const ReportInput& in, Pictures& pictures) {
    const TransferResult& t = *in.transfer;
    std::string o = "<h2>The problem on both sides</h2>\n<details><summary>Initial states and "
                    "goals (source I and G, target Y0 = Δ<sub>F</sub>(I) and "
                    "Δ<sub>F</sub>(G))</summary>\n<div class=\"grid\">\n";
    auto state = [&](const acset::ACSet& x, std::string_view name, std::string_view caption) {
        return state_figure(in, pictures, x, name, caption);
    };
    o += state(*in.problem->initial, "I", "source initial state I");
    o += t.target_initial ? state(*t.target_initial, "Y0", "target initial state Y0")
                          : "<p class=\"muted\">(no target initial state)</p>";
    o += state(*in.problem->goal, "G", "source goal G");
    o += t.target_goal ? state(*t.target_goal, "goal", "target goal Δ_F(G)")
                       : "<p class=\"muted\">(no target goal)</p>";
    return o + "</div></details>\n";
}

std::string efficiency_section(const ReportInput& in) {
    if (in.replan == nullptr) {
        return {};
    }
    const TransferResult& t = *in.transfer;
    const transfer::Replan& rp = *in.replan;
    std::string o = "<h2>Efficiency: transfer against replanning</h2>\n<table>\n";
    auto row = [&](std::string_view name, const std::string& value) {
        o += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", name, escape_html(value));
    };
    row("source plan length", std::to_string(in.plan->steps.size()));
    row("transferred plan length", std::to_string(t.steps.size()));
    row("replanning", std::string(plan::to_string(rp.search.status)));
    if (rp.search.plan) {
        row("replanned plan length", std::to_string(rp.steps.size()));
        row("edit distance (transferred vs replanned)", std::to_string(rp.edit_distance));
    }
    row("states expanded by replanning", std::to_string(rp.search.stats.expanded));
    if (!in.no_timing) {
        const auto& tm = t.timings;
        row("transfer time",
            fmt::format("{:.3f} ms (migrate {:.3f}, replay and apply {:.3f}, validate {:.3f})",
                        tm.total_ms, tm.migrate_ms, tm.apply_ms, tm.validate_ms));
        row("replanning time", fmt::format("{:.3f} ms", rp.ms));
        row("replanning / transfer", transfer::speedup_text(rp, tm.total_ms));
        row("peak memory after transfer",
            fmt::format("{:.1f} MB", static_cast<double>(in.transfer_peak_kib) / 1024.0));
        row("peak memory after replanning",
            fmt::format("{:.1f} MB", static_cast<double>(rp.peak_rss_kib) / 1024.0));
    }
    o += "</table>\n";
    if (!rp.steps.empty()) {
        o += "<details><summary>The replanned plan</summary><ol>\n";
        for (const auto& s : rp.steps) {
            o += fmt::format("<li><code>{}</code></li>\n", escape_html(s.to_string()));
        }
        o += "</ol></details>\n";
    }
    return o;
}

} // namespace

std::string html_report(const ReportInput& in) {
    CATPLAN_ASSERT(in.map != nullptr && in.problem != nullptr && in.plan != nullptr &&
                       in.transfer != nullptr,
                   "html_report needs a map, a problem, a plan and a transfer");
    Pictures pictures;
    std::string body;
    body += header_section(in);
    body += brief_section(in);
    body += goal_section(in.transfer->verdict);
    body += ontology_section(in, pictures);
    body += problem_section(in, pictures);
    body += steps_section(in, pictures);
    body += efficiency_section(in);
    if (!pictures.errors().empty()) {
        body += "<h2>Missing pictures</h2>\n<ul>\n";
        for (const auto& e : pictures.errors()) {
            body += fmt::format("<li class=\"error\">{}</li>\n", escape_html(e));
        }
        body += "</ul>\n";
    }
    body += fmt::format("<footer>Written by catplan; pictures laid out by {}.</footer>\n",
                        escape_html(SvgRenderer::backend()));
    return fmt::format("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
                       "<title>catplan: {} along {}</title>\n<style>{}</style>\n</head>\n<body>\n"
                       "{}</body>\n</html>\n",
                       escape_html(in.problem->name), escape_html(in.map_name), kStyle, body);
}

} // namespace catplan::report
