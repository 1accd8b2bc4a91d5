#pragma once
// Test fixtures of the db layer: a fresh database per test, SQLite (a file in a temporary
// directory) or PostgreSQL (a database made on the private test server).
//
// The PostgreSQL server is started by tools/pg-test-server.sh: by ctest's fixture (the directory
// in CATPLAN_TEST_PG_DIR), or, when a test binary runs on its own, once for the process. When
// it cannot start, a test that needs it is skipped with the reason, except under CI (CI set),
// where it fails, so that CI never passes without having run them.

#include "catplan/db/connection.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace catplan::db::testing {

namespace fs = std::filesystem;

/// A temporary directory, removed with everything in it at the end.
class TempDir {
public:
    TempDir() {
        std::string tmpl = (fs::temp_directory_path() / "catplan-db-XXXXXX").string();
        CATPLAN_ASSERT(::mkdtemp(tmpl.data()) != nullptr, "mkdtemp failed");
        path_ = tmpl;
    }

    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }

    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

inline std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    std::string t = s.str();
    while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) {
        t.pop_back();
    }
    return t;
}

/// The URL of the test server's maintenance database, or why there is none.
inline const Result<std::string>& postgresql_server() {
    // A server of this process (when ctest's fixture did not start one), stopped at exit.
    struct Own {
        TempDir dir;
        fs::path script = fs::path(CATPLAN_SOURCE_DIR) / "tools" / "pg-test-server.sh";

        ~Own() {
            std::string stop = script.string() + " stop " + (dir.path() / "pg").string();
            (void)std::system(stop.c_str());
        }
    };

    static const Result<std::string> url = []() -> Result<std::string> {
        fs::path dir;
        if (const char* d = std::getenv("CATPLAN_TEST_PG_DIR")) {
            dir = d;
        } else {
            static Own own;
            // The server may run as another user (postgres, under root), who must reach it.
            fs::permissions(own.dir.path(),
                            fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
            dir = own.dir.path() / "pg";
            std::string start = own.script.string() + " start " + dir.string() + " >/dev/null";
            (void)std::system(start.c_str());
        }
        if (fs::exists(dir / "url")) {
            return read_text(dir / "url");
        }
        if (fs::exists(dir / "error")) {
            return fail(read_text(dir / "error"));
        }
        return fail("the test server in " + dir.string() + " did not start");
    }();
    return url;
}

/// A fresh database for one test: a SQLite file, or a PostgreSQL database dropped at the end.
class FreshDatabase {
public:
    explicit FreshDatabase(Engine engine) : engine_(engine) {
        if (engine == Engine::SQLite) {
            url_ = "sqlite:" + (dir_.path() / "test.db").string();
            return;
        }
        const auto& server = postgresql_server();
        if (!server) {
            why_ = "the private PostgreSQL server cannot start: " + server.error();
            return;
        }
        static std::atomic<int> counter{0};
        name_ = "test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
        auto c = connect(*server);
        if (!c) {
            why_ = c.error();
            return;
        }
        if (auto st = (*c)->exec("CREATE DATABASE " + quote(name_)); !st) {
            why_ = st.error();
            return;
        }
        url_ = *server;
        url_.replace(url_.find("/postgres?"), 10, "/" + name_ + "?");
    }

    FreshDatabase(const FreshDatabase&) = delete;
    FreshDatabase& operator=(const FreshDatabase&) = delete;

    ~FreshDatabase() {
        if (!name_.empty() && postgresql_server()) {
            if (auto c = connect(*postgresql_server())) {
                (void)(*c)->exec("DROP DATABASE IF EXISTS " + quote(name_) + " WITH (FORCE)");
            }
        }
    }

    /// Empty when the database could not be made (then why() says why).
    const std::string& url() const { return url_; }

    const std::string& why() const { return why_; }

    const fs::path& dir() const { return dir_.path(); }

private:
    Engine engine_;
    TempDir dir_;
    std::string url_, name_, why_;
};

/// Skips the test (fails it under CI) when the database could not be made.
#define CATPLAN_REQUIRE_DATABASE(db)                                                               \
    do {                                                                                           \
        if ((db).url().empty()) {                                                                  \
            if (std::getenv("CI") != nullptr) {                                                    \
                FAIL() << (db).why();                                                              \
            }                                                                                      \
            GTEST_SKIP() << (db).why();                                                            \
        }                                                                                          \
    } while (false)

/// "SQLite" / "PostgreSQL" as a test name suffix.
inline std::string engine_name(const ::testing::TestParamInfo<Engine>& info) {
    return std::string(to_string(info.param));
}

} // namespace catplan::db::testing
