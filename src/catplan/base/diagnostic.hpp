#pragma once
// Diagnostics for bad user input, rendered GNU style:
//
//   kitchen.cp:12:17: error: unknown object 'Ingredient'
//      12 |   on::Hom(Ingredient, Thing)
//         |           ^~~~~~~~~~
//
// A phase appends every error it finds to a DiagnosticSink and keeps going; the driver renders them
// all at once, sorted by location, and exits with code 2 (3 when every error is about valid input
// that uses something catplan does not support, such as PDDL's `:conditional-effects`).

#include "catplan/base/source.hpp"

#include <string>
#include <vector>

namespace catplan {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceRange range;
    std::string message;
    /// Follow-up notes, each optionally located ("note: first declared here").
    std::vector<std::pair<SourceRange, std::string>> notes;
    /// An error about valid input that uses something catplan does not support (exit 3, not 2).
    bool unsupported = false;
};

class DiagnosticSink {
public:
    explicit DiagnosticSink(const SourceManager& sources) : sources_(&sources) {}

    /// Records an error at a range (an invalid range renders without location).
    Diagnostic& error(SourceRange range, std::string message);
    /// Records an error about valid input that uses something catplan does not support.
    Diagnostic& unsupported(SourceRange range, std::string message);
    /// Records a warning at a range.
    Diagnostic& warning(SourceRange range, std::string message);
    /// Records a note at a range (information that is neither an error nor a warning).
    Diagnostic& note(SourceRange range, std::string message);
    /// Records a diagnostic made elsewhere (counted as an error if it is one).
    Diagnostic& add(Diagnostic d);

    /// Records an error that belongs to no source text (a missing file, a bad option).
    Diagnostic& error(std::string message) { return error(SourceRange{}, std::move(message)); }

    bool has_errors() const { return num_errors_ > 0; }

    std::size_t num_errors() const { return num_errors_; }

    /// Whether there are errors and every one is about something catplan does not support.
    bool only_unsupported() const;

    const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

    /// All diagnostics, stably sorted by file and offset, with source lines and carets.
    std::string render() const { return render_from(0); }

    /// The diagnostics recorded from the first-th on, sorted and rendered as render() does.
    std::string render_from(std::size_t first) const;
    /// One diagnostic with its notes.
    std::string render(const Diagnostic& d) const;

private:
    std::string render_one(Severity severity, SourceRange range, const std::string& message) const;

    const SourceManager* sources_;
    std::vector<Diagnostic> diagnostics_;
    std::size_t num_errors_ = 0;
};

} // namespace catplan
