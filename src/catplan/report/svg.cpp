#include "catplan/report/svg.hpp"

#include "catplan/base/dynamic_library.hpp"
#include "catplan/base/sanitizers.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <unistd.h>
#include <vector>

#ifdef CATPLAN_HAVE_GVC
#include <graphviz/cgraph.h>
#include <graphviz/graphviz_version.h>
#include <graphviz/gvc.h>
#endif

#if defined(CATPLAN_HAVE_GVC) && defined(CATPLAN_ASAN)
// Graphviz 2.42 and the font libraries under it (fontconfig, pango, glib, cairo) keep caches and
// leak small blocks on every layout; LeakSanitizer in our sanitizer builds would fail every
// program that draws. Only leaks allocated inside those libraries are suppressed. The names are
// the sanitizer runtime's hooks, reserved identifiers by design.
// NOLINTNEXTLINE(bugprone-reserved-identifier)
extern "C" const char* __lsan_default_suppressions();
// NOLINTNEXTLINE(bugprone-reserved-identifier)
extern "C" const char* __lsan_default_options();

// Without this, every run that draws ends with LeakSanitizer's table of suppressed leaks.
extern "C" const char* __lsan_default_options() {
    return "print_suppressions=0";
}

extern "C" const char* __lsan_default_suppressions() {
    return "leak:libgvc.so\nleak:libcgraph.so\nleak:libgvplugin_\nleak:libfontconfig.so\n"
           "leak:libpango\nleak:libglib-2.0.so\nleak:libcairo.so\nleak:libgobject-2.0.so\n";
}
#endif

namespace catplan::report {

#ifdef CATPLAN_HAVE_GVC

namespace {

// Graphviz's two libraries are loaded at the first picture rather than linked: with what they
// bring (cdt, pathplan, ltdl, expat, zlib) they cost every catplan command two milliseconds of
// start-up, and only the report draws. The types are those of Graphviz's headers
// (libgraphviz-dev); the sonames are those of Debian's libgvc6 and libcgraph6.
struct Gvc {
    decltype(&::gvContext) context = nullptr;
    decltype(&::gvLayout) layout = nullptr;
    decltype(&::gvRenderData) render_data = nullptr;
    decltype(&::gvFreeRenderData) free_render_data = nullptr;
    decltype(&::gvFreeLayout) free_layout = nullptr;
};

struct Cgraph {
    decltype(&::agread) read = nullptr;
    decltype(&::agseterr) seterr = nullptr;
    decltype(&::agseterrf) seterrf = nullptr;
    decltype(&::agclose) close = nullptr;
    Agmemdisc_t* mem_disc = nullptr; // AgMemDisc: Graphviz's own allocator
    Agiodisc_t* io_disc = nullptr;   // AgIoDisc: its output functions
};

void bind_gvc(SymbolBinder& b, Gvc& f) {
    b.function(f.context, "gvContext");
    b.function(f.layout, "gvLayout");
    b.function(f.render_data, "gvRenderData");
    b.function(f.free_render_data, "gvFreeRenderData");
    b.function(f.free_layout, "gvFreeLayout");
}

void bind_cgraph(SymbolBinder& b, Cgraph& f) {
    b.function(f.read, "agread");
    b.function(f.seterr, "agseterr");
    b.function(f.seterrf, "agseterrf");
    b.function(f.close, "agclose");
    b.data(f.mem_disc, "AgMemDisc");
    b.data(f.io_disc, "AgIoDisc");
}

// Both libraries, loaded on the first call; false, with the reason in `why`, when one of them
// or one of their symbols cannot be found.
bool load_graphviz(const Gvc*& gvc, const Cgraph*& cgraph, std::string& why) {
    static LazyLibrary<Gvc> gvc_lib("libgvc.so.6", "Graphviz's libgvc (Debian's libgvc6)",
                                    bind_gvc);
    static LazyLibrary<Cgraph> cgraph_lib(
        "libcgraph.so.6", "Graphviz's libcgraph (Debian's libcgraph6)", bind_cgraph);
    gvc = gvc_lib.load(why);
    cgraph = gvc != nullptr ? cgraph_lib.load(why) : nullptr;
    return cgraph != nullptr;
}

// Graphviz reports problems through a global callback; the renderer collects them per call.
std::string* g_errors = nullptr;

int collect_error(char* message) {
    if (g_errors != nullptr && message != nullptr) {
        *g_errors += message;
    }
    return 0;
}

// One context for the whole process, never freed: Graphviz 2.42's pango plugin caches a font
// name across contexts, and a second context after gvFreeContext reads it after it was freed.
// The mutex serialises renderers (the context and the error callback are not thread-safe).
std::mutex g_mutex;

GVC_t* shared_context(const Gvc& gv) {
    static GVC_t* gvc = gv.context();
    return gvc;
}

// Object ids in the order names are first read. Graphviz's default id of a named object is the
// address of its interned name, and it keeps subgraphs ordered by id: clusters were laid out and
// written in an order that changed from run to run. Named ids are even, anonymous ones odd, as
// Graphviz's own allocator has them (its printing of names relies on that).
struct ReadOrderIds {
    std::vector<std::unique_ptr<char[]>> names; // id 2k+2 is names[k]
    std::map<std::string, IDTYPE, std::less<>> ids;
    IDTYPE next_anonymous = 1;
};

void* ids_open(Agraph_t*, Agdisc_t*) {
    return new ReadOrderIds;
}

long ids_map(void* state, int, char* str, IDTYPE* id, int create) {
    auto& s = *static_cast<ReadOrderIds*>(state);
    if (str == nullptr) {
        *id = s.next_anonymous;
        s.next_anonymous += 2;
        return 1;
    }
    if (auto it = s.ids.find(std::string_view(str)); it != s.ids.end()) {
        *id = it->second;
        return 1;
    }
    if (create == 0) {
        return 0;
    }
    std::size_t n = std::strlen(str) + 1;
    s.names.push_back(std::make_unique<char[]>(n));
    std::memcpy(s.names.back().get(), str, n);
    *id = 2 * static_cast<IDTYPE>(s.names.size());
    s.ids.emplace(str, *id);
    return 1;
}

long ids_alloc(void*, int, IDTYPE) {
    return 0; // no ids chosen by the caller
}

void ids_free(void*, int, IDTYPE) {}

char* ids_print(void* state, int, IDTYPE id) {
    auto& s = *static_cast<ReadOrderIds*>(state);
    if (id % 2 != 0 || id == 0 || id / 2 > s.names.size()) {
        return nullptr;
    }
    return s.names[id / 2 - 1].get();
}

void ids_close(void* state) {
    delete static_cast<ReadOrderIds*>(state);
}

void ids_register(void*, int, void*) {}

Agiddisc_t g_read_order_ids = {ids_open,  ids_map,   ids_alloc,   ids_free,
                               ids_print, ids_close, ids_register};

// The DOT text read from memory (agmemread's channel, with our ids).
struct TextChannel {
    std::string_view text;
    std::size_t at = 0;
};

int text_read(void* chan, char* buf, int size) {
    auto& c = *static_cast<TextChannel*>(chan);
    // One line per call, as Graphviz's own readers give it.
    std::size_t n = 0;
    while (c.at < c.text.size() && n + 1 < static_cast<std::size_t>(size)) {
        char ch = c.text[c.at++];
        buf[n++] = ch;
        if (ch == '\n') {
            break;
        }
    }
    buf[n] = '\0';
    return static_cast<int>(n);
}

Agraph_t* read_graph(const Cgraph& cg, std::string_view dot) {
    static Agiodisc_t io = {text_read, cg.io_disc->putstr, cg.io_disc->flush};
    static Agdisc_t disc = {cg.mem_disc, &g_read_order_ids, &io};
    TextChannel chan{dot};
    return cg.read(&chan, &disc);
}

} // namespace

struct SvgRenderer::Impl {};

SvgRenderer::SvgRenderer() : impl_(std::make_unique<Impl>()) {}

SvgRenderer::~SvgRenderer() = default;

Result<std::string> SvgRenderer::render(std::string_view dot) {
    const Gvc* gv = nullptr;
    const Cgraph* cg = nullptr;
    std::string missing;
    if (!load_graphviz(gv, cg, missing)) {
        return fail(missing);
    }
    std::lock_guard lock(g_mutex);
    GVC_t* gvc = shared_context(*gv);
    std::string errors;
    g_errors = &errors;
    cg->seterr(AGERR);
    cg->seterrf(collect_error);
    Result<std::string> out = fail("");
    if (Agraph_t* g = read_graph(*cg, dot); g == nullptr) {
        out = fail("Graphviz could not read the picture: " + errors);
    } else {
        if (gv->layout(gvc, g, "dot") != 0) {
            out = fail("Graphviz could not lay the picture out: " + errors);
        } else {
            char* data = nullptr;
            unsigned int length = 0;
            if (gv->render_data(gvc, g, "svg", &data, &length) == 0 && data != nullptr) {
                out = std::string(data, length);
            } else {
                out = fail("Graphviz could not render SVG: " + errors);
            }
            gv->free_render_data(data);
            gv->free_layout(gvc, g);
        }
        cg->close(g);
    }
    cg->seterrf(nullptr);
    g_errors = nullptr;
    return out;
}

std::string SvgRenderer::backend() {
    const Gvc* gv = nullptr;
    const Cgraph* cg = nullptr;
    std::string missing;
    if (!load_graphviz(gv, cg, missing)) {
        return "nothing (Graphviz's libraries cannot be loaded)";
    }
    return fmt::format("libgvc {}", PACKAGE_VERSION);
}

#else // the dot program

struct SvgRenderer::Impl {};

SvgRenderer::SvgRenderer() : impl_(std::make_unique<Impl>()) {}

SvgRenderer::~SvgRenderer() = default;

namespace {

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

Result<std::string> SvgRenderer::render(std::string_view dot) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path dir = fs::temp_directory_path(ec);
    if (ec) {
        return fail("no temporary directory for Graphviz: " + ec.message());
    }
    // A name per process and call, so that concurrent reports do not share files.
    static std::atomic<unsigned> counter = 0;
    std::string stem = fmt::format("catplan-{}-{}", static_cast<long>(::getpid()), ++counter);
    fs::path in = dir / (stem + ".dot"), out = dir / (stem + ".svg"), err = dir / (stem + ".err");
    std::ofstream(in, std::ios::binary) << dot;
    std::string command =
        fmt::format("dot -Tsvg '{}' -o '{}' 2>'{}'", in.string(), out.string(), err.string());
    int status = std::system(command.c_str());
    std::string svg = read_file(out), errors = read_file(err);
    fs::remove(in, ec);
    fs::remove(out, ec);
    fs::remove(err, ec);
    if (status != 0 || svg.empty()) {
        return fail(errors.empty() ? "cannot run Graphviz's `dot` program (install graphviz)"
                                   : "Graphviz's dot failed: " + errors);
    }
    return svg;
}

std::string SvgRenderer::backend() {
    return "Graphviz's dot program";
}

#endif

std::string inline_svg(std::string_view svg, std::string_view prefix) {
    std::size_t start = svg.find("<svg");
    std::string_view body = start == std::string_view::npos ? svg : svg.substr(start);
    std::string out;
    out.reserve(body.size() + 64);
    std::size_t i = 0;
    while (i < body.size()) {
        if (body.compare(i, 4, "<!--") == 0) {
            std::size_t end = body.find("-->", i + 4);
            i = end == std::string_view::npos ? body.size() : end + 3;
            continue;
        }
        // Ids and the references to them (gradients, clip paths, links) get the prefix.
        bool matched = false;
        for (std::string_view key : {"id=\"", "url(#", "href=\"#"}) {
            if (body.compare(i, key.size(), key) == 0) {
                out += key;
                out += prefix;
                out += '_';
                i += key.size();
                matched = true;
                break;
            }
        }
        if (!matched) {
            out += body[i++];
        }
    }
    return out;
}

} // namespace catplan::report
