#include "common.hpp"

namespace catplan::python {

namespace {

std::string_view severity_name(Severity s) {
    switch (s) {
    case Severity::Error:
        return "error";
    case Severity::Warning:
        return "warning";
    case Severity::Note:
        return "note";
    }
    return "error";
}

// The class object of catplan.CatplanError, created once when the module is imported.
PyObject* g_error_type = nullptr;

} // namespace

std::vector<PyDiagnostic> diagnostics_of(const SourceManager& sources, const DiagnosticSink& sink) {
    std::vector<PyDiagnostic> out;
    for (const auto& d : sink.diagnostics()) {
        PyDiagnostic p;
        p.severity = severity_name(d.severity);
        p.message = d.message;
        if (d.range.valid()) {
            auto begin = sources.line_col(d.range.file, d.range.begin);
            auto end = sources.line_col(d.range.file, d.range.end);
            p.file = std::string(sources.name(d.range.file));
            p.line = begin.line;
            p.column = begin.col;
            p.end_line = end.line;
            p.end_column = end.col;
        }
        for (const auto& [range, note] : d.notes) {
            if (range.valid()) {
                auto at = sources.line_col(range.file, range.begin);
                p.notes.emplace_back(std::string(sources.name(range.file)), at.line, at.col, note);
            } else {
                p.notes.emplace_back(std::nullopt, std::nullopt, std::nullopt, note);
            }
        }
        p.rendered = sink.render(d);
        out.push_back(std::move(p));
    }
    return out;
}

CatplanError error_from(const SourceManager& sources, const DiagnosticSink& sink) {
    auto text = sink.render();
    while (!text.empty() && text.back() == '\n') {
        text.pop_back();
    }
    return CatplanError{std::move(text), diagnostics_of(sources, sink)};
}

CatplanError error_from(std::string message) {
    PyDiagnostic d;
    d.severity = "error";
    d.message = message;
    d.rendered = "error: " + message + "\n";
    return CatplanError{std::move(message), {std::move(d)}};
}

void register_errors(py::module_& m) {
    py::class_<PyDiagnostic>(m, "Diagnostic", R"doc(
One located message about bad input, as the command line prints it GNU style
(``file:line:column: error: message`` with the source line and a caret).

``file``, ``line`` and ``column`` (1-based, counted in characters) are None for a message that
belongs to no source text, such as a file that cannot be read.)doc")
        .def_readonly("severity", &PyDiagnostic::severity, "'error', 'warning' or 'note'.")
        .def_readonly("message", &PyDiagnostic::message)
        .def_readonly("file", &PyDiagnostic::file)
        .def_readonly("line", &PyDiagnostic::line)
        .def_readonly("column", &PyDiagnostic::column)
        .def_readonly("end_line", &PyDiagnostic::end_line)
        .def_readonly("end_column", &PyDiagnostic::end_column)
        .def_readonly("notes", &PyDiagnostic::notes,
                      "Follow-up notes as (file, line, column, message) tuples.")
        .def_readonly("rendered", &PyDiagnostic::rendered,
                      "GNU style, with the source line and a caret, as the command line prints.")
        .def("__str__", [](const PyDiagnostic& d) { return d.rendered; })
        .def("__repr__", [](const PyDiagnostic& d) {
            std::string where = d.file ? *d.file + ":" + std::to_string(*d.line) + ":" +
                                             std::to_string(*d.column) + ": "
                                       : std::string();
            return "<Diagnostic " + where + d.severity + ": " + d.message + ">";
        });

    g_error_type = PyErr_NewExceptionWithDoc(
        "catplan.CatplanError",
        "Bad input: every diagnostic of the failed phase is in `diagnostics` (a list of "
        "Diagnostic), and str() of the exception renders them all GNU style.",
        PyExc_Exception, nullptr);
    m.add_object("CatplanError", py::handle(g_error_type));
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) {
                std::rethrow_exception(p);
            }
        } catch (const CatplanError& e) {
            py::object type = py::reinterpret_borrow<py::object>(g_error_type);
            py::object err = type(e.message);
            err.attr("diagnostics") = py::cast(e.diagnostics);
            PyErr_SetObject(g_error_type, err.ptr());
        }
    });
}

} // namespace catplan::python
