#pragma once
// What every subcommand of the command line shares: loading files with their diagnostics, finding
// declarations, writing output, and the table that registers subcommands. Each group of
// subcommands lives in its own file and adds itself to the table (commands.cpp, *_commands.cpp).

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/process.hpp"
#include "catplan/base/source.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/rewrite/rule.hpp"
#include "catplan/transfer/transfer.hpp"

#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CLI {
class App;
} // namespace CLI

namespace catplan::cli {

/// Everything one command loaded: the sources outlive the diagnostics that point into them.
struct Session {
    SourceManager sources;
    DiagnosticSink sink{sources};
    /// How many of the sink's diagnostics have been printed.
    std::size_t reported = 0;
};

/// Prints the diagnostics collected since the last call (each once); returns true when there
/// were errors among them.
bool report(Session& s, std::ostream& err);

/// The exit code of input that did not load: kUnsupported when every error the session met is
/// about valid input catplan does not support (PDDL's `:conditional-effects`), else kBadInput.
int input_error(const Session& s);

/// Loads a file and its imports; nullopt (with every diagnostic printed) when it has errors.
std::optional<lang::Module> load(Session& s, const std::string& file, std::ostream& err);

/// Reads a file named on the command line ("-": standard input) into the session; nullopt with
/// `cannot read 'PATH': REASON` printed.
std::optional<std::uint32_t> read_input(Session& s, const std::string& path, std::ostream& err);

/// Reads a plan file ("-": standard input), parses it and checks it against the problem's domain
/// and initial state (plan::check_plan); nullopt with every diagnostic printed (bad input).
std::optional<plan::Plan> load_plan(Session& s, const std::string& path,
                                    const plan::Problem& problem, std::ostream& err);

/// Prints `catplan: error: message`.
void error(std::ostream& err, const std::string& message);

/// One text of a command's output and where it goes: the file `path`, or stdout when `path` is ""
/// or "-".
struct OutputText {
    std::string text;
    std::string path;
};

/// Writes every text where it goes, the files all or none (base/output_file.hpp: a new file gets
/// the usual mode, a replaced one keeps its mode, a device or FIFO is written in place); kOk, or
/// kBadInput with the error printed and nothing written or printed.
int emit(const std::vector<OutputText>& outputs, std::ostream& out, std::ostream& err);

/// emit of one text: to stdout, or to the file `output`.
int emit(const std::string& text, const std::string& output, std::ostream& out, std::ostream& err);

/// The names a module declares, comma-separated ("none" when it declares nothing).
std::string declared_names(const lang::Module& m);

/// "a schema", "an instance", ... for messages.
std::string_view kind_name(lang::DeclKind kind);

/// Every line of text indented by n spaces.
std::string indent(const std::string& text, std::size_t n);

/// The rule's summary line, then its Pre, Keep, Eff and each condition's N as tables, all
/// indented by n spaces (`show` of a rule or domain, `migrate-domain`).
std::string rule_tables(const rewrite::Rule& rule, std::size_t n);

/// The declaration `name` of the wanted kind, or nullptr with an error message on err.
const lang::Declaration* find_declaration(const lang::Module& m, const std::string& file,
                                          const std::string& name,
                                          std::optional<lang::DeclKind> kind, std::ostream& err);

/// Loads `file` into `m` and finds its declaration `name` of the wanted kind; nullptr with every
/// diagnostic printed on err.
const lang::Declaration* load_declaration(Session& s, const std::string& file,
                                          const std::string& name,
                                          std::optional<lang::DeclKind> kind,
                                          std::optional<lang::Module>& m, std::ostream& err);

/// A rule declared at top level or inside a domain of the module, or nullptr.
const rewrite::Rule* find_rule(const lang::Module& m, const std::string& name);

/// The problem `problem_name` of FILE, checked against `domain_name` when it is not empty;
/// nullptr with every error printed.
plan::ProblemPtr load_problem(Session& s, const std::string& file, const std::string& domain_name,
                              const std::string& problem_name, std::ostream& err);

/// The problem `problem_name` of a loaded module, checked against `domain_name` when it is not
/// empty; nullptr with the error printed.
plan::ProblemPtr find_problem(const lang::Module& m, const std::string& file,
                              const std::string& domain_name, const std::string& problem_name,
                              std::ostream& err);

/// The instance `name` of a loaded module as a goal on `target` (a map's target schema: the goal
/// intended in the target domain); nullptr with the error printed.
std::shared_ptr<const acset::ACSet> find_target_goal(const lang::Module& m, const std::string& file,
                                                     const std::string& name,
                                                     const schema::SchemaPtr& target,
                                                     std::ostream& err);

/// What `transfer` and `report` read from their command lines.
struct TransferArgs {
    std::string file, map, domain, problem, plan_file, goal;
    /// With PDDL inputs (pddl_transfer.hpp): where to write the target problem, and the user's
    /// own target problem to compare with.
    std::string problem_output, target_problem;
    bool rename_by_type = false;
    /// Replanning in the target domain (--replan and its search settings).
    bool replan = false;
    std::string search = "bfs", heuristic = "hff";
    /// 0: not given; the search then stops after 60 s unless max_nodes is given (a node limit
    /// alone keeps the result the same on every machine).
    double max_time = 0;
    std::uint64_t max_nodes = 0;
    /// --progress: report the replanning search's progress on stderr (also when stderr is a
    /// terminal).
    bool progress = false;
    /// --strict and --follow-source (transfer::TransferOptions).
    bool strict = false, follow_source = false;
};

/// Adds FILE, --map, --domain, --problem, --plan, --goal and --rename-by-type to cmd; with
/// `plans`, --plan may be repeated and its values go there instead of to a.plan_file.
void add_transfer_input_options(CLI::App* cmd, TransferArgs& a,
                                std::vector<std::string>* plans = nullptr);

/// Adds --strict and --follow-source (how a trajectory that leaves the migrated source states is
/// judged) to cmd.
void add_trajectory_options(CLI::App* cmd, TransferArgs& a);

/// Adds --replan (described by replan_help), --search, --heuristic, --max-time, --max-nodes and
/// --progress to cmd.
void add_replan_options(CLI::App* cmd, TransferArgs& a, const std::string& replan_help);

/// The search the replan options ask for; progress reports go to `err` with --progress or when
/// stderr is a terminal (so that captured output stays the same from run to run).
plan::SearchOptions replan_options(const TransferArgs& a, std::ostream& err);

struct PddlTransfer;

/// Everything a transfer reads: the map, the source problem (of the same loaded module, so the
/// map is on its schema), the plan, and with --goal the goal intended in the target domain.
struct TransferInputs {
    std::shared_ptr<const migrate::SchemaMap> map;
    plan::ProblemPtr problem;
    plan::Plan plan;
    std::shared_ptr<const acset::ACSet> target_goal;
    /// Conditions on target_goal's embedding (a PDDL target problem's negative goals).
    std::vector<rewrite::ApplicationCondition> target_goal_conditions;
    /// When --problem is a PDDL file: the PDDL side of the inputs (pddl_transfer.hpp).
    std::shared_ptr<const PddlTransfer> pddl;
};

/// Loads the inputs a's names; nullopt with every error printed.
std::optional<TransferInputs> load_transfer_inputs(Session& s, const TransferArgs& a,
                                                   std::ostream& err);

/// Loads what every plan of a transfer shares (the map, the problem, the goals; no plan);
/// nullopt with every error printed.
std::optional<TransferInputs> load_transfer_setting(Session& s, const TransferArgs& a,
                                                    std::ostream& err);

/// Loads the plan at `path` into in (a step list, or an IPC plan with PDDL inputs); false with
/// every error printed.
bool load_transfer_plan(Session& s, TransferInputs& in, const std::string& path, std::ostream& err);

/// The transfer a asks for: renaming, the intended goal, --strict and --follow-source.
transfer::TransferOptions transfer_options(const TransferArgs& a, const TransferInputs& in);

/// The subcommands and what runs each when it is the one parsed.
class CommandTable {
public:
    using Run = std::function<int(std::ostream& out, std::ostream& err)>;

    /// Registers `run` for the (leaf) subcommand `command`.
    void add(CLI::App* command, Run run) { entries_.emplace_back(command, std::move(run)); }

    /// Runs the parsed subcommand's function; nullopt when none was parsed.
    std::optional<int> run_parsed(std::ostream& out, std::ostream& err) const;

private:
    std::vector<std::pair<CLI::App*, Run>> entries_;
};

/// Top-level commands that one function adds to the command line, with their options.
struct CommandGroup {
    std::vector<std::string_view> names;
    void (*add)(CLI::App& app, CommandTable& table);
};

/// Every group of commands, in the order `catplan --help` lists them (commands.cpp).
const std::vector<CommandGroup>& command_groups();

/// Adds `check`, `show` and `homs` (inspect_commands.cpp).
void add_inspect_commands(CLI::App& app, CommandTable& table);
/// Adds `migrate` and `migrate-domain` (migrate_commands.cpp).
void add_migrate_commands(CLI::App& app, CommandTable& table);
/// Adds `transfer` (transfer_commands.cpp).
void add_transfer_commands(CLI::App& app, CommandTable& table);
/// Adds `report` (report_commands.cpp).
void add_report_commands(CLI::App& app, CommandTable& table);
/// Adds `pddl import|export` and PDDL input to `plan` and `validate` (pddl_commands.cpp).
void add_pddl_commands(CLI::App& app, CommandTable& table);
/// Adds `db export|import` and `library` (db_commands.cpp).
void add_db_commands(CLI::App& app, CommandTable& table);
/// Adds `--db` (migration inside a database) and its options to `migrate`; the function returned
/// runs it when `--db` was given and returns nullopt otherwise (db_commands.cpp).
std::function<std::optional<int>(std::ostream&, std::ostream&)>
add_migrate_db_options(CLI::App& migrate, const std::string& file, const std::string& map,
                       const std::string& state);

} // namespace catplan::cli
