// The batch transfer of a plan library (library.hpp): batches read, transferred on every core,
// written in one transaction each.

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/parallel.hpp"
#include "catplan/db/detail/library_tables.hpp"
#include "catplan/db/library.hpp"
#include "catplan/json/json.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/plan/actions.hpp"
#include "catplan/transfer/transfer.hpp"

#include <chrono>
#include <fmt/format.h>
#include <map>
#include <nlohmann/json.hpp>

namespace catplan::db {

using detail::library_table;

namespace {

// One worker's own copy of the map and its source domains (the library's objects build caches
// on first use, so threads share none of them).
struct Worker {
    SourceManager sources;
    DiagnosticSink sink{sources};
    lang::Module module;
    const migrate::SchemaMap* map = nullptr;
    std::map<std::string, plan::DomainPtr, std::less<>> domains; // on the map's source schema
};

Result<std::unique_ptr<Worker>> load_worker(const std::string& file, const std::string& name) {
    auto w = std::make_unique<Worker>();
    w->module = lang::load_file(file, w->sources, w->sink);
    if (w->sink.has_errors()) {
        return fail("'" + file + "' has errors:\n" + w->sink.render());
    }
    const auto* d = w->module.find(name);
    if (d == nullptr || d->kind != lang::DeclKind::Map) {
        return fail("'" + file + "' declares no map '" + name + "'");
    }
    w->map = d->map.get();
    for (const auto& decl : w->module.declarations()) {
        if (decl.kind == lang::DeclKind::Domain && decl.schema == w->map->source()) {
            w->domains.emplace(decl.name, decl.domain);
        }
    }
    return w;
}

// A stored plan to transfer, as read from the library.
struct Job {
    std::int64_t plan = 0;
    std::string domain, problem, label, steps, initial, goal;
};

StoredTransfer failed_job(const Job& j, const std::string& map, std::string reason) {
    StoredTransfer t;
    t.plan = j.plan;
    t.domain = j.domain;
    t.problem = j.problem;
    t.label = j.label;
    t.map = map;
    t.migration = "none";
    t.reason = std::move(reason);
    return t;
}

StoredTransfer run(const Worker& w, const Job& j, const std::string& map) {
    const migrate::SchemaMap& f = *w.map;
    auto d = w.domains.find(j.domain);
    CATPLAN_ASSERT(d != w.domains.end(), "the domains were checked before the batches");
    auto initial = state_from_text(f.source(), j.initial);
    auto goal = state_from_text(f.source(), j.goal);
    if (!initial || !goal) {
        return failed_job(j, map,
                          "the stored problem: " + (initial ? goal.error() : initial.error()));
    }
    plan::Problem p{j.problem,
                    d->second,
                    std::make_shared<const acset::ACSet>(std::move(*initial)),
                    std::make_shared<const acset::ACSet>(std::move(*goal)),
                    {}};
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer(j.label, j.steps);
    auto plan = plan::parse_plan(file, sources, sink);
    if (!plan) {
        return failed_job(j, map, "the stored plan: " + sink.render());
    }
    // A stored plan names actions as the user wrote them; the transfer reads rule steps.
    transfer::TransferResult r =
        transfer::transfer_plan(f, p, plan::rule_plan(*p.domain, *p.initial, *plan));
    const transfer::Verdict& v = r.verdict;
    StoredTransfer t = failed_job(j, map, v.reason());
    t.migration = std::string(transfer::to_string(r.migration));
    t.source_valid = v.source_valid();
    t.valid = v.valid();
    t.goal_satisfied = v.goal.satisfied;
    t.goal_total = v.goal.total;
    t.unsatisfied = v.goal.unsatisfied;
    for (const auto& s : r.steps) {
        t.target_plan.push_back(s.target.to_string());
    }
    if (const auto* failed = v.failed_step(); failed != nullptr && failed->step) {
        t.failed_step = *failed->step + 1;
    }
    t.ms = r.timings.total_ms;
    return t;
}

// The library's domains on the map's source schema; each must be one the workers have, on the
// same schema.
Result<std::vector<std::string>> source_domains(Connection& c, const Worker& w) {
    const auto& s = *w.map->source();
    std::string schema = catplan::json::write_schema(s);
    std::vector<std::string> names;
    std::string problem;
    auto st = c.query("SELECT name, schema FROM " + library_table(c.engine(), "domains") +
                          " WHERE schema_name = " + quote_literal(s.name()) + " ORDER BY name",
                      [&](const Row& r) {
                          std::string name = r.text(0).value_or("");
                          if (!w.domains.contains(name)) {
                              problem = "the library holds plans of domain " + name + " (on " +
                                        s.name() + "), which the map's file does not declare";
                          } else if (r.text(1).value_or("") != schema) {
                              problem = "the library's domain " + name + " is on another " +
                                        "version of schema " + s.name() + " than the map's";
                          }
                          names.push_back(std::move(name));
                          return problem.empty();
                      });
    if (!st) {
        return fail(st.error());
    }
    if (!problem.empty()) {
        return fail(problem);
    }
    return names;
}

// The next batch: plans after `after` of the given domains with no result for the map.
Result<std::vector<Job>> next_batch(Connection& c, const std::vector<std::string>& domains,
                                    const std::string& map, std::int64_t after, std::size_t n) {
    Engine e = c.engine();
    std::string in;
    for (const auto& d : domains) {
        in += (in.empty() ? "" : ", ") + quote_literal(d);
    }
    std::string sql =
        "SELECT p.\"_id\", d.name, pr.name, p.label, p.steps, pr.initial, pr.goal FROM " +
        library_table(e, "plans") + " AS p JOIN " + library_table(e, "problems") +
        " AS pr ON pr.\"_id\" = p.problem JOIN " + library_table(e, "domains") +
        " AS d ON d.\"_id\" = pr.domain WHERE d.name IN (" + in + ") AND p.\"_id\" > " +
        std::to_string(after) + " AND NOT EXISTS (SELECT 1 FROM " + library_table(e, "transfers") +
        " AS t WHERE t.plan = p.\"_id\" AND t.map = " + quote_literal(map) +
        ") ORDER BY p.\"_id\" LIMIT " + std::to_string(n);
    std::vector<Job> jobs;
    auto st = c.query(sql, [&](const Row& r) {
        jobs.push_back({r.integer(0).value_or(0), r.text(1).value_or(""), r.text(2).value_or(""),
                        r.text(3).value_or(""), r.text(4).value_or(""), r.text(5).value_or(""),
                        r.text(6).value_or("")});
        return true;
    });
    if (!st) {
        return fail(st.error());
    }
    return jobs;
}

Status store(Connection& c, const std::vector<StoredTransfer>& results) {
    std::vector<std::string> columns{"plan",        "map",         "migration",      "source_valid",
                                     "valid",       "reason",      "goal_satisfied", "goal_total",
                                     "unsatisfied", "target_plan", "failed_step",    "ms"};
    std::vector<std::string> unsatisfied, plans;
    for (const auto& t : results) {
        unsatisfied.push_back(nlohmann::ordered_json(t.unsatisfied).dump());
        std::string p;
        for (const auto& s : t.target_plan) {
            p += s + "\n";
        }
        plans.push_back(std::move(p));
    }
    Transaction tx(c);
    if (!tx.status()) {
        return tx.status();
    }
    auto st =
        c.insert(library_table(c.engine(), "transfers"), columns, results.size(),
                 [&](std::size_t i, std::vector<SqlValue>& cells) {
                     const StoredTransfer& t = results[i];
                     cells = {t.plan,
                              std::string_view(t.map),
                              std::string_view(t.migration),
                              t.source_valid,
                              t.valid,
                              std::string_view(t.reason),
                              static_cast<std::int64_t>(t.goal_satisfied),
                              static_cast<std::int64_t>(t.goal_total),
                              std::string_view(unsatisfied[i]),
                              std::string_view(plans[i]),
                              t.failed_step ? SqlValue(static_cast<std::int64_t>(*t.failed_step))
                                            : SqlValue(),
                              t.ms};
                 });
    if (!st) {
        return st;
    }
    return tx.commit();
}

} // namespace

Result<LibraryTransferSummary>
transfer_library(Connection& c, const std::string& map_file, const std::string& map_name,
                 const LibraryTransferOptions& options,
                 const std::function<void(const StoredTransfer&)>& each) {
    auto start = std::chrono::steady_clock::now();
    std::size_t jobs = options.jobs != 0 ? options.jobs : default_jobs();
    std::vector<std::unique_ptr<Worker>> workers;
    for (std::size_t i = 0; i < jobs; ++i) {
        auto w = load_worker(map_file, map_name);
        if (!w) {
            return fail(w.error());
        }
        workers.push_back(std::move(*w));
    }
    if (auto st = open_library(c); !st) {
        return fail(st.error());
    }
    auto domains = source_domains(c, *workers[0]);
    if (!domains) {
        return fail(domains.error());
    }
    LibraryTransferSummary summary;
    auto done = c.query_integer("SELECT count(*) FROM " + library_table(c.engine(), "transfers") +
                                " WHERE map = " + quote_literal(map_name));
    if (!done) {
        return fail(done.error());
    }
    summary.already_done = static_cast<std::size_t>(*done);
    std::int64_t after = 0;
    while (!domains->empty() && (options.limit == 0 || summary.transferred < options.limit)) {
        std::size_t n = std::max<std::size_t>(1, options.batch);
        if (options.limit != 0) {
            n = std::min(n, options.limit - summary.transferred);
        }
        auto batch = next_batch(c, *domains, map_name, after, n);
        if (!batch) {
            return fail(batch.error());
        }
        if (batch->empty()) {
            break;
        }
        std::vector<StoredTransfer> results(batch->size());
        parallel_for(batch->size(), workers.size(), [&](std::size_t k, std::size_t i) {
            results[i] = run(*workers[k], (*batch)[i], map_name);
        });
        if (auto st = store(c, results); !st) {
            return fail(st.error());
        }
        for (const auto& r : results) {
            summary.valid += r.valid ? 1 : 0;
            each(r);
        }
        summary.transferred += results.size();
        after = batch->back().plan;
    }
    summary.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

} // namespace catplan::db
