#pragma once
// UTF-8 as the readers see it: decoding one code point at a time, the identifier classes of
// Unicode (UAX #31), and the check every text reader runs first, so that no ill-formed byte
// sequence gets into a name, a string or an output file.
//
// An identifier starts with `_` or a code point of XID_Start (the letters: Unicode categories Lu,
// Ll, Lt, Lm, Lo and the letter numbers Nl) and goes on with XID_Continue (also the digits Nd,
// the combining marks Mn and Mc, the connector punctuation Pc such as `_`). Emoji, symbols and
// punctuation are in neither class. ASCII is answered here; ICU answers the property look-ups
// of other code points, loaded at the first one (its library is not linked). Where ICU cannot be
// loaded, no such code point is in either class, and identifier_classes_unavailable says why.

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace catplan {

/// One decoded code point: its value and how many bytes it takes; `valid` is false for an
/// ill-formed sequence, whose `length` is then the bytes to skip (at least 1).
struct CodePoint {
    char32_t value = 0;
    std::size_t length = 1;
    bool valid = true;
};

/// The code point that starts at byte i of text (i < text.size()).
CodePoint decode_utf8(std::string_view text, std::size_t i);

/// Whether the whole text is well-formed UTF-8.
bool is_valid_utf8(std::string_view text);

/// Whether c may start an identifier: `_` or XID_Start.
bool is_identifier_start(char32_t c);

/// Whether c may go on an identifier: XID_Continue (which holds `_` and the digits).
bool is_identifier_continue(char32_t c);

/// Why the identifier classes of code points beyond ASCII are unknown (ICU cannot be loaded),
/// empty when they are known; tries to load ICU.
std::string identifier_classes_unavailable();

/// Reports every ill-formed UTF-8 sequence of a buffer as a located error (the first ten, then a
/// count of the rest, so a binary file gives a short answer); returns whether there was none.
bool check_utf8(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink);

} // namespace catplan
