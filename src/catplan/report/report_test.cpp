// The HTML report of a small transfer: verdict, steps, inlined pictures, no network references,
// escaped text and balanced tags.

#include "catplan/report/explain.hpp"
#include "catplan/report/report.hpp"
#include "catplan/report/svg.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <memory>
#include <set>

namespace catplan::report {
namespace {

using acset::ACSet;
using acset::Value;
using dot::escape_html;
using migrate::Query;
using migrate::SchemaMap;
using migrate::Term;
using schema::Schema;
using schema::SchemaPtr;
using schema::ValueKind;

// Blocks stacked by On facts, each with a colour; move(b, from, to) moves b from `from` onto
// `to` (as in transfer_test.cpp).
struct Stacks {
    SchemaPtr s;
    ObId block, on;
    HomId on_l, on_r;
    AttrTypeId color_type;
    AttrId color;
};

// With `clear`, also an attribute isClear (like the case study's, which no map sees).
Stacks stacks(bool clear = false) {
    auto s = std::make_shared<Schema>("Stacks");
    Stacks t;
    t.block = s->add_ob("Block");
    t.on = s->add_ob("On");
    t.on_l = s->add_hom("on_l", t.on, t.block);
    t.on_r = s->add_hom("on_r", t.on, t.block);
    t.color_type = s->add_attr_type("Color", ValueKind::String);
    t.color = s->add_attr("hasColor", t.block, t.color_type);
    if (clear) {
        s->add_attr("isClear", t.block, s->add_attr_type("Clear", ValueKind::Bool));
    }
    t.s = s;
    return t;
}

rewrite::RulePtr move_rule(const Stacks& t) {
    auto rule = std::make_shared<rewrite::Rule>(t.s);
    rule->name = "move";
    for (ACSet* x : {&rule->L, &rule->K, &rule->R}) {
        for (const char* n : {"b", "from", "to"}) {
            x->add_part(t.block, n);
        }
    }
    Part o = rule->L.add_part(t.on, "o");
    rule->L.set_subpart(t.on_l, o, 0);
    rule->L.set_subpart(t.on_r, o, 1);
    Part o2 = rule->R.add_part(t.on, "o2");
    rule->R.set_subpart(t.on_l, o2, 0);
    rule->R.set_subpart(t.on_r, o2, 2);
    rule->l = hom::identity(rule->K);
    rule->r = hom::identity(rule->K);
    rule->parameters = {{"b", t.block, 0}, {"from", t.block, 1}, {"to", t.block, 2}};
    return rule;
}

// A on B on D, C alone; the goal: a purple block on a purple block.
struct Fixture {
    Stacks t = stacks();
    plan::ProblemPtr problem;
    plan::Plan plan;

    Fixture() {
        auto domain = std::make_shared<plan::Domain>();
        domain->name = "Moves";
        domain->schema = t.s;
        domain->rules = {move_rule(t)};
        auto p = std::make_shared<plan::Problem>();
        p->name = "P";
        p->domain = domain;
        ACSet x(t.s);
        const char* names[] = {"A", "B", "C", "D"};
        const char* colors[] = {"purple", "red", "purple", "green"};
        for (int i = 0; i < 4; ++i) {
            x.set_subpart(t.color, x.add_part(t.block, names[i]), Value::string(colors[i]));
        }
        for (auto [top, below] : {std::pair<Part, Part>{0, 1}, {1, 3}}) {
            Part o = x.add_part(t.on);
            x.set_subpart(t.on_l, o, top);
            x.set_subpart(t.on_r, o, below);
        }
        p->initial = std::make_shared<ACSet>(std::move(x));
        ACSet goal(t.s);
        Part a = goal.add_part(t.block, "a");
        Part c = goal.add_part(t.block, "c");
        goal.set_subpart(t.color, a, Value::string("purple"));
        goal.set_subpart(t.color, c, Value::string("purple"));
        Part o = goal.add_part(t.on, "o");
        goal.set_subpart(t.on_l, o, a);
        goal.set_subpart(t.on_r, o, c);
        p->goal = std::make_shared<ACSet>(std::move(goal));
        problem = p;
        plan.steps = {{"move", {"A", "B", "C"}, {}}, {"move", {"B", "D", "A"}, {}}};
    }
};

// Items in receptacles, the purple blocks also BreadSliced (a conjunctive map).
SchemaMap kitchen_map(const Stacks& t) {
    auto s = std::make_shared<Schema>("Kitchen");
    ObId item = s->add_ob("Item");
    ObId bread = s->add_ob("BreadSliced");
    ObId in = s->add_ob("InReceptacle");
    HomId in_l = s->add_hom("in_l", in, item);
    HomId in_r = s->add_hom("in_r", in, item);
    HomId bread_is_item = s->add_hom("breadIsItem", bread, item);
    SchemaMap f(s, t.s);
    f.map_ob(item, t.block);
    f.map_ob(in, t.on);
    f.map_hom_path(in_l, {t.on_l});
    f.map_hom_path(in_r, {t.on_r});
    Query q(t.s);
    q.add_variable("block", t.block);
    q.add_equation(Term::path("block", {}, t.color), Term::constant(Value::string("purple")));
    f.map_ob(bread, std::move(q));
    f.map_hom(bread_is_item, {Term::path("block")});
    EXPECT_TRUE(f.finish().empty());
    return f;
}

bool contains(const std::string& text, std::string_view part) {
    return text.find(part) != std::string::npos;
}

std::size_t count(const std::string& text, std::string_view part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos;
         at = text.find(part, at + part.size())) {
        ++n;
    }
    return n;
}

// Checks that every element is closed in order (HTML void elements and XML `/>` aside); returns
// the first problem, or "" when the tags balance. Attribute values hold no '>' (it is escaped).
std::string unbalanced_tags(const std::string& html) {
    static const std::set<std::string> kVoid = {"meta", "br", "hr", "img", "input", "link"};
    std::vector<std::string> open;
    for (std::size_t at = html.find('<'); at != std::string::npos; at = html.find('<', at + 1)) {
        if (html.compare(at, 4, "<!--") == 0) {
            at = html.find("-->", at);
            if (at == std::string::npos) {
                return "an unclosed comment";
            }
            continue;
        }
        std::size_t end = html.find('>', at);
        if (end == std::string::npos) {
            return "an unclosed tag";
        }
        std::string tag = html.substr(at + 1, end - at - 1);
        bool closing = !tag.empty() && tag[0] == '/';
        std::size_t from = closing ? 1 : 0;
        std::size_t stop = tag.find_first_of(" \t\n/", from);
        std::string name =
            tag.substr(from, stop == std::string::npos ? std::string::npos : stop - from);
        if (name.empty() || name[0] == '!' || name[0] == '?' || tag.back() == '/' ||
            kVoid.count(name) > 0) {
            continue; // a DOCTYPE, a self-closed or a void element
        }
        if (!closing) {
            open.push_back(name);
        } else if (open.empty() || open.back() != name) {
            return "</" + name + "> closes <" + (open.empty() ? "nothing" : open.back()) + ">";
        } else {
            open.pop_back();
        }
    }
    return open.empty() ? "" : "<" + open.back() + "> is never closed";
}

// Every http(s) URL of the page, but for the SVG and XLink namespace declarations.
std::vector<std::string> network_references(const std::string& html) {
    std::vector<std::string> out;
    for (std::size_t at = html.find("http"); at != std::string::npos;
         at = html.find("http", at + 4)) {
        if (html.compare(at, 7, "http://") != 0 && html.compare(at, 8, "https://") != 0) {
            continue;
        }
        std::size_t end = html.find_first_of("\"' <>)", at);
        std::string u = html.substr(at, end - at);
        if (u != "http://www.w3.org/2000/svg" && u != "http://www.w3.org/1999/xlink") {
            out.push_back(u);
        }
    }
    return out;
}

// Every value of an id="..." attribute.
std::vector<std::string> ids(const std::string& html) {
    std::vector<std::string> out;
    for (std::size_t at = html.find(" id=\""); at != std::string::npos;
         at = html.find(" id=\"", at + 1)) {
        std::size_t start = at + 5;
        out.push_back(html.substr(start, html.find('"', start) - start));
    }
    return out;
}

struct Made {
    Fixture fx;
    SchemaMap map = kitchen_map(fx.t);
    transfer::TransferResult t;
    std::optional<transfer::Replan> rp;
    std::string html;

    explicit Made(bool with_replan = false, std::string map_name = "ToKitchen",
                  bool rename_by_type = false) {
        transfer::TransferOptions o;
        o.keep_states = true;
        o.rename_by_type = rename_by_type;
        t = transfer::transfer_plan(map, *fx.problem, fx.plan, o);
        ReportInput in;
        in.map = &map;
        in.map_name = std::move(map_name);
        in.problem = fx.problem.get();
        in.plan = &fx.plan;
        in.transfer = &t;
        if (with_replan) {
            rp = transfer::replan(t, plan::SearchOptions{});
            in.replan = &*rp;
        }
        html = html_report(in);
    }
};

TEST(Report, ShowsTheVerdictStepsAndPictures) {
    Made m;
    ASSERT_TRUE(m.t.verdict.valid()) << m.t.verdict.reason();
    const std::string& h = m.html;
    EXPECT_TRUE(contains(h, "<p class=\"verdict valid\">Valid")) << h.substr(0, 2000);
    EXPECT_TRUE(contains(h, "100%"));
    EXPECT_TRUE(contains(h, "conjunctive migration"));
    for (const auto& st : m.t.steps) {
        EXPECT_TRUE(contains(h, escape_html(st.source.to_string()))) << st.source.to_string();
        EXPECT_TRUE(contains(h, escape_html(st.target.to_string()))) << st.target.to_string();
    }
    // Schemas (2), map (1), problem (4) and four states per step, all inlined.
    EXPECT_EQ(count(h, "<svg"), 7 + 4 * m.t.steps.size());
    EXPECT_FALSE(contains(h, "<?xml"));
    EXPECT_FALSE(contains(h, "<!DOCTYPE svg"));
    EXPECT_TRUE(contains(h, "Q_BreadSliced"));                  // the map's query box
    EXPECT_TRUE(contains(h, "States before and after step 2")); // a <details> per step
    EXPECT_TRUE(contains(h, "<tr id=\"step-2\">"));             // an anchor per step
    EXPECT_EQ(count(h, "<details"), count(h, "</details>"));
    EXPECT_EQ(unbalanced_tags(h), "");
    EXPECT_EQ(network_references(h), std::vector<std::string>{});
    EXPECT_FALSE(contains(h, "<script"));
    EXPECT_FALSE(contains(h, "Efficiency")); // no replanning
    EXPECT_FALSE(contains(h, "Missing pictures"));
}

TEST(Report, BindingsOfTheCarriedPartsAreBoldAlsoWhenRenamed) {
    for (bool rename : {false, true}) {
        SCOPED_TRACE(rename);
        Made m(false, "ToKitchen", rename);
        ASSERT_TRUE(m.t.verdict.valid()) << m.t.verdict.reason();
        // Each step's three parameters, bold in both columns.
        EXPECT_GE(count(m.html, "<li class=\"shared\">"), 6 * m.t.steps.size());
    }
}

TEST(Explain, TheBriefNamesEachObjectsImageAndWhatIsLost) {
    Stacks t = stacks(true);
    SchemaMap f = kitchen_map(t);
    MapSummary brief = summarize_map(f);
    std::vector<std::string> objects;
    for (const auto& line : brief.objects) {
        objects.push_back(line.name + " ⇒ " + line.image);
    }
    EXPECT_EQ(objects, (std::vector<std::string>{
                           "Item ⇒ Block",
                           "BreadSliced ⇒ {block::Block | hasColor(block) == \"purple\"}",
                           "InReceptacle ⇒ On",
                       }));
    EXPECT_EQ(lost_names(brief, schema::GeneratorKind::Attr), "isClear");
    EXPECT_EQ(lost_names(brief, schema::GeneratorKind::AttrType), "Clear");
    EXPECT_EQ(lost_names(brief, schema::GeneratorKind::Ob), "");
    EXPECT_EQ(lost_names(brief, schema::GeneratorKind::Hom), "");
    // The page's brief says the same.
    EXPECT_TRUE(contains(Made().html, "<h2>In brief</h2>"));
}

TEST(Explain, EachBindingComesWithItsReason) {
    Made m;
    ASSERT_TRUE(m.t.verdict.valid()) << m.t.verdict.reason();
    const auto& st = m.t.steps[0]; // move(A, B, C): A is purple, so also BreadSliced
    auto reasons = binding_reasons(m.map, *m.fx.problem->domain->find_rule("move"),
                                   *m.t.target_domain.domain->find_rule("move"), st,
                                   m.t.source_states[0], m.t.target_states[0]);
    auto has = [&](const std::string& r) {
        return std::find(reasons.begin(), reasons.end(), r) != reasons.end();
    };
    EXPECT_TRUE(has("A ↦ BreadSliced A because hasColor(A) == \"purple\" and BreadSliced ⇒ "
                    "{block::Block | hasColor(block) == \"purple\"}"))
        << fmt::format("{}", fmt::join(reasons, "\n"));
    EXPECT_TRUE(has("A ↦ Item A because Block A and Item ⇒ Block"))
        << fmt::format("{}", fmt::join(reasons, "\n"));
    // B is red: not BreadSliced, and no reason says it is.
    for (const auto& r : reasons) {
        EXPECT_FALSE(contains(r, "BreadSliced B")) << r;
        EXPECT_FALSE(contains(r, "#")) << r; // no internal labels
    }
    EXPECT_TRUE(contains(m.html, escape_html(reasons.front())));
}

TEST(Explain, StatePicturesMarkWhatTheStepDeletesAndCreates) {
    Made m;
    ASSERT_TRUE(m.t.verdict.valid()) << m.t.verdict.reason();
    const auto& st = m.t.steps[0]; // move(A, B, C): deletes On A B, creates On A C
    const auto* rule = m.fx.problem->domain->find_rule("move");
    StepMarks marks = step_marks(rule, m.t.target_domain.domain->find_rule("move"), st);
    auto of_class = [](const std::vector<dot::PartClass>& all, std::string_view css) {
        std::vector<dot::PartClass> out;
        std::copy_if(all.begin(), all.end(), std::back_inserter(out),
                     [&](const dot::PartClass& c) { return c.css_class == css; });
        return out;
    };
    ASSERT_EQ(of_class(marks.source_after, "created").size(), 1U);
    const auto created = of_class(marks.source_after, "created")[0];
    EXPECT_EQ(created.ob, m.fx.t.on);
    EXPECT_EQ(created.css_class, "created");
    const ACSet& after = m.t.source_states[1];
    EXPECT_EQ(after.subpart(m.fx.t.on_l, created.part), *after.find_part(m.fx.t.block, "A"));
    EXPECT_EQ(after.subpart(m.fx.t.on_r, created.part), *after.find_part(m.fx.t.block, "C"));
    // Drawn as a node (relation edges off), the created part's node carries the class.
    dot::DotOptions nodes;
    nodes.relation_edges = false;
    std::string picture = dot::state_to_dot(after, "X1", nodes, marks.source_after);
    std::string node = fmt::format("On_{} [", created.part + 1);
    std::size_t at = picture.find(node);
    ASSERT_NE(at, std::string::npos) << picture;
    EXPECT_TRUE(contains(picture.substr(at, picture.find('\n', at) - at), "class=\"created\""))
        << picture;
    // The deleted On is marked in the state before, on both sides, and the target's created
    // InReceptacle in the target's state after.
    ASSERT_EQ(of_class(marks.source_before, "deleted").size(), 1U);
    EXPECT_EQ(of_class(marks.source_before, "deleted")[0].ob, m.fx.t.on);
    // The blocks the match binds are kept: marked as matched before and after, and nothing else.
    const ACSet& before = m.t.source_states[0];
    std::set<std::string> matched;
    for (const auto& c : of_class(marks.source_before, "matched")) {
        EXPECT_EQ(c.ob, m.fx.t.block);
        matched.insert(std::string(before.part_name(c.ob, c.part)));
    }
    EXPECT_EQ(matched, (std::set<std::string>{"A", "B", "C"}));
    EXPECT_EQ(of_class(marks.source_after, "matched").size(), 3U);
    EXPECT_EQ(marks.source_before.size(), 4U);
    EXPECT_FALSE(marks.target_before.empty());
    EXPECT_FALSE(marks.target_after.empty());
    // On the page, as SVG classes (On is drawn as an edge there), with a legend.
    EXPECT_GE(count(m.html, "class=\"edge created\""), 2 * m.t.steps.size());
    EXPECT_GE(count(m.html, "class=\"edge deleted\""), 2 * m.t.steps.size());
    EXPECT_TRUE(contains(m.html, "<span class=\"swatch created\">"));
    EXPECT_TRUE(contains(m.html, "<span class=\"swatch matched\">"));
    EXPECT_GE(count(m.html, "class=\"node matched\""), 2 * m.t.steps.size());
}

TEST(Explain, ValuesEveryPartSharesAreSaidOnce) {
    Stacks t = stacks(/*clear=*/true);
    ACSet x(t.s);
    AttrId clear = *t.s->find_attr("isClear");
    for (const char* n : {"A", "B"}) {
        Part p = x.add_part(t.block, n);
        x.set_subpart(clear, p, Value::boolean(true));
        x.set_subpart(t.color, p, Value::string("red"));
    }
    auto u = uniform_values(x);
    ASSERT_EQ(u.size(), 1U);
    EXPECT_EQ(u[0].ob, t.block);
    EXPECT_EQ(u[0].values, (std::vector<std::string>{"hasColor = \"red\"", "isClear = true"}));
    x.set_subpart(t.color, 1, Value::string("blue"));
    EXPECT_TRUE(uniform_values(x).empty()); // one attribute differs: every row is drawn
}

TEST(Explain, MadeUpNamesAreNotShown) {
    Stacks t = stacks();
    ACSet x(t.s);
    Part a = x.add_part(t.block, "A");
    Part made = x.add_part(t.block, "block@2"); // a block a step created
    Part below = x.add_part(t.block, "");       // an unnamed part: its label is #3
    Part on = x.add_part(t.on, "on1");
    x.set_subpart(t.on_l, on, a);
    x.set_subpart(t.on_r, on, below);
    (void)made;
    auto labels = readable_labels(x);
    auto label_of = [&](Part p) -> std::string {
        for (const auto& l : labels) {
            if (l.ob == t.block && l.part == p) {
                return l.label;
            }
        }
        return "(none)";
    };
    EXPECT_EQ(label_of(a), "(none)");        // a person's name stays
    EXPECT_EQ(label_of(made), "a Block");    // nothing reaches it: its object
    EXPECT_EQ(label_of(below), "on_r(on1)"); // reached by a hom from a named part
}

TEST(Report, SvgIdsAreUniqueOnThePage) {
    Made m;
    std::set<std::string> seen;
    for (const auto& id : ids(m.html)) {
        EXPECT_TRUE(seen.insert(id).second) << "duplicate id " << id;
    }
    EXPECT_FALSE(seen.empty());
}

TEST(Report, InvalidTransferShowsWhyAndTheUnsatisfiedStatements) {
    Fixture fx;
    SchemaMap map = kitchen_map(fx.t);
    plan::Plan one;
    one.steps = {{"move", {"B", "D", "A"}, {}}}; // B (red) onto A: no purple on purple
    transfer::TransferOptions o;
    o.keep_states = true;
    auto t = transfer::transfer_plan(map, *fx.problem, one, o);
    ASSERT_FALSE(t.verdict.valid());
    ReportInput in;
    in.map = &map;
    in.map_name = "ToKitchen";
    in.problem = fx.problem.get();
    in.plan = &one;
    in.transfer = &t;
    std::string h = html_report(in);
    EXPECT_TRUE(
        contains(h, "<p class=\"verdict invalid\">Invalid: " + escape_html(t.verdict.reason())));
    ASSERT_FALSE(t.verdict.goal.unsatisfied.empty());
    for (const auto& u : t.verdict.goal.unsatisfied) {
        EXPECT_TRUE(contains(h, "<li><code>" + escape_html(u) + "</code></li>")) << u;
    }
    EXPECT_EQ(unbalanced_tags(h), "");
}

TEST(Report, FailedStepIsMarked) {
    Fixture fx;
    SchemaMap map = kitchen_map(fx.t);
    plan::Plan bad;
    bad.steps = {{"move", {"A", "C", "D"}, {}}, {"move", {"B", "D", "A"}, {}}};
    transfer::TransferOptions o;
    o.keep_states = true;
    auto t = transfer::transfer_plan(map, *fx.problem, bad, o);
    ASSERT_FALSE(t.verdict.valid());
    ReportInput in;
    in.map = &map;
    in.map_name = "ToKitchen";
    in.problem = fx.problem.get();
    in.plan = &bad;
    in.transfer = &t;
    std::string h = html_report(in);
    EXPECT_TRUE(contains(h, "verdict invalid"));
    EXPECT_TRUE(contains(h, "move(A, C, D)"));
    if (t.verdict.failed_step()) {
        EXPECT_TRUE(contains(h, "not transferred: "));
    } else {
        EXPECT_TRUE(contains(h, "The source plan itself is invalid"));
    }
    EXPECT_EQ(unbalanced_tags(h), "");
}

TEST(Report, ReplanningAddsTheEfficiencyFigures) {
    Made m(/*with_replan=*/true);
    ASSERT_TRUE(m.rp);
    EXPECT_TRUE(contains(m.html, "Efficiency: transfer against replanning"));
    EXPECT_TRUE(contains(m.html, "edit distance"));
    EXPECT_TRUE(contains(m.html, "replanning time"));
    EXPECT_TRUE(contains(m.html, "peak memory after replanning"));
    EXPECT_EQ(unbalanced_tags(m.html), "");
}

TEST(Report, EscapesUserText) {
    Made m(false, "<script>alert('x')</script> & \"co\"");
    EXPECT_FALSE(contains(m.html, "<script"));
    EXPECT_TRUE(contains(m.html, "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; "
                                 "&quot;co&quot;"));
    EXPECT_EQ(unbalanced_tags(m.html), "");
}

TEST(Report, TheBalanceCheckCatchesUnclosedTags) {
    EXPECT_EQ(unbalanced_tags("<p><b>x</b></p><br><svg><g/></svg>"), "");
    EXPECT_NE(unbalanced_tags("<p><b>x</p>"), "");
    EXPECT_NE(unbalanced_tags("<details><summary>x</summary>"), "");
    EXPECT_EQ(network_references("<a href=\"https://example.org/x\">"),
              std::vector<std::string>{"https://example.org/x"});
}

TEST(Svg, RendersAndInlinesWithPrefixedIds) {
    SvgRenderer r;
    auto svg = r.render("digraph G { a -> b; }");
    ASSERT_TRUE(svg) << svg.error();
    EXPECT_TRUE(contains(*svg, "<svg"));
    std::string in = inline_svg(*svg, "p7");
    EXPECT_EQ(in.rfind("<svg", 0), 0u);
    EXPECT_FALSE(contains(in, "<!--"));
    EXPECT_TRUE(contains(in, "id=\"p7_graph0\""));
}

// Graphviz orders subgraphs by id, and its default id of a name is the name's address: clusters
// came out in an order that changed from run to run. They must come out in the order written.
TEST(Svg, ClustersComeOutInTheOrderWrittenWhateverTheHeap) {
    std::string dot = "digraph G {\n";
    std::vector<std::string> names;
    for (int i = 0; i < 24; ++i) {
        // Names of many lengths land in different allocator size classes.
        names.push_back("cluster_" + std::string(static_cast<std::size_t>(1 + (i * 7) % 40), 'z') +
                        std::to_string(i));
        dot += fmt::format("subgraph {} {{ n{}; }}\n", names.back(), i);
    }
    dot += "}\n";
    SvgRenderer r;
    std::vector<std::unique_ptr<char[]>> churn;
    std::string first;
    for (int round = 0; round < 3; ++round) {
        for (int k = 0; k < 50 * (round + 1); ++k) {
            churn.push_back(std::make_unique<char[]>(static_cast<std::size_t>(8 + k % 64)));
        }
        auto svg = r.render(dot);
        ASSERT_TRUE(svg) << svg.error();
        std::size_t at = 0;
        for (const auto& n : names) {
            std::size_t next = svg->find("<title>" + n + "</title>", at);
            ASSERT_NE(next, std::string::npos) << n << " out of order";
            at = next;
        }
        if (round == 0) {
            first = *svg;
        }
        EXPECT_EQ(*svg, first);
    }
}

TEST(Svg, BadDotIsAFailureNotACrash) {
    SvgRenderer r;
    auto svg = r.render("digraph { a -> ");
    ASSERT_FALSE(svg);
    EXPECT_TRUE(contains(svg.error(), "Graphviz")) << svg.error();
    // The renderer still works afterwards.
    EXPECT_TRUE(r.render("digraph G { a; }"));
}

TEST(Escape, HtmlText) {
    EXPECT_EQ(escape_html("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
}

} // namespace
} // namespace catplan::report
