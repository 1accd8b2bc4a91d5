#pragma once
// What the bindings of the Python module share: the wrappers that Python objects hold (each a
// shared pointer to an immutable library object, or a copy-on-write state), the conversion of
// attribute values, name lookups that raise Python exceptions instead of tripping the library's
// assertions, diagnostics as a Python exception, and calls that release the GIL and can be
// interrupted with Ctrl-C.

#include "catplan/acset/acset.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/base/result.hpp"
#include "catplan/base/source.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/rewrite/rule.hpp"
#include "catplan/schema/schema.hpp"
#include "catplan/transfer/transfer.hpp"

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <string>
#include <vector>

namespace catplan::python {

namespace py = pybind11;

// ---- wrappers ---------------------------------------------------------------------------------

struct PySchema {
    schema::SchemaPtr ptr;
};

/// A state as Python sees it: mutable, copied on the first write after it was shared with an
/// immutable owner (a problem, a result, a call running without the GIL), so that what the
/// library holds never changes under it.
class PyState {
public:
    explicit PyState(std::shared_ptr<const acset::ACSet> x, std::string name = {})
        : ptr_(std::move(x)), name_(std::move(name)) {}

    /// A new empty state that this wrapper owns.
    static PyState empty(const schema::SchemaPtr& s, std::string name = {});
    /// A state built here and owned by this wrapper.
    static PyState owned(acset::ACSet x, std::string name = {});

    const acset::ACSet& get() const { return *ptr_; }

    /// The state for a long-lived owner; a later write through this wrapper copies first.
    std::shared_ptr<const acset::ACSet> share() {
        owner_ = false;
        return ptr_;
    }

    /// The state to write to (copied first when it is shared).
    acset::ACSet& mut();

    const std::string& name() const { return name_; }

    void set_name(std::string name) { name_ = std::move(name); }

private:
    std::shared_ptr<const acset::ACSet> ptr_;
    bool owner_ = false; // true when ptr_ was made here and shared with no one
    std::string name_;
};

struct PyRule {
    rewrite::RulePtr ptr;
};

struct PyDomain {
    plan::DomainPtr ptr;
};

struct PyProblem {
    plan::ProblemPtr ptr;
};

struct PyMap {
    std::shared_ptr<const migrate::SchemaMap> ptr;
    std::string name;
};

/// What catplan.transfer returns (catplan.Transfer): the library's result and the inputs, for
/// the report.
struct PyTransfer {
    std::shared_ptr<const transfer::TransferResult> t;
    std::shared_ptr<const transfer::Replan> replan;
    PyMap map;
    PyProblem problem;
    plan::Plan plan;
    long transfer_peak_kib = 0;
};

/// A morphism with its domain and codomain when they are known (for labels and pictures).
struct PyMorphism {
    hom::ACSetMorphism m;
    std::shared_ptr<const acset::ACSet> dom, codom;
};

/// An attribute variable of a state: its attribute type, index (0-based) and name.
struct PyVar {
    std::string type;
    std::uint32_t index = 0;
    std::string name;
};

// ---- names ------------------------------------------------------------------------------------

/// The object, hom, attribute type or attribute with this name; KeyError when there is none.
ObId ob_named(const schema::Schema& s, const std::string& name);
HomId hom_named(const schema::Schema& s, const std::string& name);
AttrTypeId attr_type_named(const schema::Schema& s, const std::string& name);
/// A hom or an attribute; KeyError for any other name.
schema::Generator hom_or_attr_named(const schema::Schema& s, const std::string& name);

/// A part of ob given as an index (0-based; negative counts from the end) or a name; IndexError
/// or KeyError when there is no such part.
Part part_arg(const acset::ACSet& x, ObId ob, const py::handle& part);

/// ValueError unless x and y are on the same schema (or schemas of the same shape).
void require_same_schema(const acset::ACSet& x, const acset::ACSet& y);

/// Whether x and y are isomorphic (names ignored), computed without the GIL.
bool isomorphic(PyState& x, PyState& y);

// ---- values -----------------------------------------------------------------------------------

/// The Python value of an attribute cell: bool, int, float, str, Var, or None (unset).
py::object to_python(const acset::ACSet& x, AttrTypeId t, const acset::Value& v);
/// The attribute value of a Python object for type t of x (None unsets); TypeError on a value
/// of the wrong kind, IndexError on a variable x does not have.
acset::Value from_python(const acset::ACSet& x, AttrTypeId t, const py::handle& v);

// ---- errors -----------------------------------------------------------------------------------

/// A diagnostic as Python sees it.
struct PyDiagnostic {
    std::string severity; // "error", "warning", "note"
    std::string message;
    std::optional<std::string> file;
    std::optional<std::uint32_t> line, column, end_line, end_column;
    /// Follow-up notes: (file, line, column, message); unlocated notes have None for all three.
    std::vector<std::tuple<std::optional<std::string>, std::optional<std::uint32_t>,
                           std::optional<std::uint32_t>, std::string>>
        notes;
    std::string rendered; // GNU style, with the source line and a caret
};

/// Every diagnostic of a sink, in rendering order.
std::vector<PyDiagnostic> diagnostics_of(const SourceManager& sources, const DiagnosticSink& sink);

/// A loaded file (catplan.Module): its declarations, the text they were read from (where a
/// transfer with PDDL inputs also reads its problem and plan) and the warnings.
struct PyModule {
    std::shared_ptr<SourceManager> sources;
    lang::Module module;
    std::vector<PyDiagnostic> warnings;
};

/// Thrown (with the GIL held or not) to raise catplan.CatplanError(message) carrying diagnostics.
struct CatplanError : std::exception {
    CatplanError(std::string m, std::vector<PyDiagnostic> d)
        : message(std::move(m)), diagnostics(std::move(d)) {}

    const char* what() const noexcept override { return message.c_str(); }

    std::string message;
    std::vector<PyDiagnostic> diagnostics;
};

/// A CatplanError with every diagnostic of the sink, the message being them all rendered.
CatplanError error_from(const SourceManager& sources, const DiagnosticSink& sink);
/// A CatplanError with one unlocated diagnostic (an algorithm's failure to produce a value that
/// the caller asked for, such as a rule that does not migrate).
CatplanError error_from(std::string message);

/// The value of a library Result, or a CatplanError with its reason.
template <class T>
T value_or_raise(Result<T> r) {
    if (!r) {
        throw error_from(r.error());
    }
    return std::move(r).value();
}

/// Registers catplan.CatplanError and its translation.
void register_errors(py::module_& m);

// ---- interruptible calls without the GIL ------------------------------------------------------

/// Releases the GIL for the lifetime of the object. poll() may be called from the library's
/// callbacks on the same thread: about every 50 ms it takes the GIL and runs Python's signal
/// handlers (so Ctrl-C raises KeyboardInterrupt); once a handler raised, poll() returns true
/// and the call should stop. finish() takes the GIL back and re-raises what a handler raised.
class Interruptible {
public:
    Interruptible();
    ~Interruptible();
    Interruptible(const Interruptible&) = delete;
    Interruptible& operator=(const Interruptible&) = delete;

    /// Whether the call should stop (a signal handler raised); cheap enough for a hot loop.
    bool poll();
    /// Like poll, for callers that are called rarely (a progress report): no call counting.
    bool check();
    /// Runs fn with the GIL held (after a poll, or from a progress report); an exception it
    /// raises stops the call as a signal would.
    bool with_gil(const std::function<void()>& fn);

    /// Whether poll() asked the call to stop.
    bool stopped() const { return error_.has_value(); }

    /// Takes the GIL back; raises the Python exception a handler raised, if any.
    void finish();

private:
    std::optional<py::gil_scoped_release> release_;
    std::optional<py::error_already_set> error_;
    std::chrono::steady_clock::time_point next_;
    std::uint32_t calls_ = 0;
};

/// Thrown out of a library callback to unwind a call that poll() stopped.
struct Interrupted {};

// ---- shared by several files ------------------------------------------------------------------

/// A plan given as a Plan, a str (plan text, as a .plan file holds) or a list of steps (Step,
/// "unstack(E, D)" or ("unstack", ["E", "D"])); CatplanError on a syntax error.
plan::Plan plan_arg(const py::handle& plan);

/// An IPC plan given as its text (as Fast Downward writes it) or a list of tuples (action,
/// [args]); CatplanError on a syntax error, TypeError on another shape.
pddl::IpcPlan ipc_plan_arg(const py::handle& plan);

/// An IPC plan as a list of tuples (action, [args]).
py::list ipc_tuples(const pddl::IpcPlan& p);

/// Search settings as the Python functions take them.
struct SearchArgs {
    std::string search = "bfs";
    std::string heuristic = "hff";
    std::uint64_t max_nodes = 0;
    double max_time = 0;
    double max_memory_mb = 0;
    py::object progress; // None, or called with a dict of statistics
    double progress_interval = 1.0;
};

/// The library's search options for args (which must outlive them); its progress callback polls
/// `inter` (and calls the Python progress function) and throws Interrupted to stop the search.
/// ValueError on an unknown search or heuristic name.
plan::SearchOptions search_options(const SearchArgs& args, Interruptible& inter);

/// The statistics of a search as a dict.
py::dict stats_dict(const plan::SearchStats& s);

/// The bind_* functions, one per file.
void bind_values(py::module_& m);
void bind_schema(py::module_& m);
void bind_state(py::module_& m);
void bind_module(py::module_& m);
void bind_plan(py::module_& m);
void bind_hom(py::module_& m);
void bind_migrate(py::module_& m);
void bind_io(py::module_& m);
void bind_transfer(py::module_& m);
void bind_pddl_transfer(py::module_& m);

} // namespace catplan::python
