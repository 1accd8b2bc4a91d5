#!/usr/bin/env python3
"""The database commands of catplan end to end on one engine (sqlite or postgresql).

    cli_test.py CATPLAN ROOT ENGINE

For postgresql the server is the test server of CATPLAN_TEST_PG_DIR (tools/pg-test-server.sh);
when it could not start, the test says why and is skipped (exit 77), or fails under CI.
Each step checks the exit code and what was printed; the bad-input steps also check that
nothing was written.
"""
import json
import os
import pathlib
import subprocess
import sys
import tempfile

CATPLAN, ROOT, ENGINE = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
CB = "examples/colorblocksworld/colorblocksworld.cp"
MAP = "examples/colorblocks_to_kitchen/appendix_map.cp"
failures = []


def run(*args, code=0, out=None, err=None):
    """Runs catplan from the repository root and checks its exit code and output."""
    p = subprocess.run([CATPLAN, *args], cwd=ROOT, capture_output=True, text=True, timeout=300)
    where = "catplan " + " ".join(args)
    if p.returncode != code:
        failures.append(f"{where}: exit {p.returncode}, expected {code}\n{p.stdout}{p.stderr}")
    for text, want, name in ((p.stdout, out, "stdout"), (p.stderr, err, "stderr")):
        if want is not None and want not in text:
            failures.append(f"{where}: {name} lacks {want!r}:\n{text}")
    return p.stdout


def sql(url, statement):
    """Runs SQL with the engine's own client (a database person's edit)."""
    if ENGINE == "sqlite":
        cmd = ["sqlite3", url[len("sqlite:"):], statement]
    else:
        cmd = ["psql", "-q", "-v", "ON_ERROR_STOP=1", url, "-c", statement]
    subprocess.run(cmd, check=True, capture_output=True, text=True)


def table(ns, name):
    return f'"{ns}.{name}"' if ENGINE == "sqlite" else f'"{ns}"."{name}"'


def fresh_database(tmp):
    if ENGINE == "sqlite":
        return f"sqlite:{tmp}/test.db"
    pg = os.environ.get("CATPLAN_TEST_PG_DIR")
    if not pg or not (pathlib.Path(pg) / "url").exists():
        why = (pathlib.Path(pg) / "error").read_text() if pg and (pathlib.Path(pg) / "error").exists() \
            else "CATPLAN_TEST_PG_DIR names no running server"
        print(f"the private PostgreSQL server cannot start: {why}")
        sys.exit(1 if os.environ.get("CI") else 77)
    server = (pathlib.Path(pg) / "url").read_text().strip()
    name = f"cli_{os.getpid()}"
    subprocess.run(["psql", "-q", server, "-c", f'CREATE DATABASE "{name}"'], check=True)
    return server.replace("/postgres?", f"/{name}?")


def states(url):
    # A state as tables, read back; a second export is refused; --replace replaces.
    run("db", "export", CB, "Initial", "--db", url, out="exported Initial (11 parts)")
    run("db", "export", CB, "Initial", "--db", url, code=2,
        err="the database already holds tables of 'ColorBlocksworld'")
    run("db", "export", CB, "Initial", "--db", url, "--replace")
    text = run("db", "import", CB, "ColorBlocksworld", "--db", url, "--name", "Back")
    for want in ('(A, B, C, D, E, F, _Block7)::Block', 'hasColor(D) == "purple"', "on_l(x1) == E"):
        if want not in text:
            failures.append(f"db import lacks {want!r}:\n{text}")
    back = ROOT / "build" / f"db-cli-{os.getpid()}.cp"
    back.write_text(f'@import "../{CB}"\n' + text)
    try:
        run("check", str(back))  # what import prints loads again
    finally:
        back.unlink()


def migration(url):
    run("migrate", MAP, "--map", "ColorToKitchen", "--db", url,
        out="migrated the tables of ColorBlocksworld along ColorToKitchen into the tables of KitchenWorld")
    text = run("db", "import", MAP, "KitchenWorld", "--db", url)
    # The BreadSliced parts are named D and E, as the Object parts are: the printer writes them
    # as D_BreadSliced and E_BreadSliced.
    for want in ("(D_BreadSliced, E_BreadSliced)::BreadSliced", "breadSlicedIsObject(D_BreadSliced) == D",
                 "breadSlicedIsObject(E_BreadSliced) == E"):
        if want not in text:
            failures.append(f"db import of the migration lacks {want!r}:\n{text}")
    run("migrate", MAP, "--map", "ColorToKitchen", "--db", url, code=2,
        err="already holds tables of 'KitchenWorld'")
    # A foreign key that points nowhere: a clear error, and nothing written.
    if ENGINE == "postgresql":
        sql(url, f'ALTER TABLE {table("ColorBlocksworld", "On")} DROP CONSTRAINT "On_on_l_fkey"')
    sql(url, f'UPDATE {table("ColorBlocksworld", "On")} SET on_l = 42 WHERE _id = 2')
    run("migrate", MAP, "--map", "ColorToKitchen", "--db", url, "--to", "K2", code=2,
        err=f'table {table("ColorBlocksworld", "On")}, row 2, column "on_l": 42 points to no row of '
            f'{table("ColorBlocksworld", "Block")}')
    run("db", "import", MAP, "KitchenWorld", "--db", url, "--as", "K2", code=2,
        err=f"the database has no table {table('K2', 'Gripper')}")
    run("db", "import", CB, "ColorBlocksworld", "--db", url, code=2,
        err='row 2, column "on_l": 42 points to no row')


def library(url):
    out = run("library", "add", CB, "--problem", "CaseStudy", "examples/colorblocksworld/paper.plan",
              "tests/cli/data/short.plan", "--db", url)
    plans = [json.loads(l) for l in out.splitlines()]
    if [p["steps"] for p in plans] != [8, 3]:
        failures.append(f"library add printed {out}")
    # Resumable: one plan, then the rest; nothing is transferred twice.
    out = run("library", "transfer", MAP, "--map", "ColorToKitchen", "--db", url, "--limit", "1",
              err="transferred 1 plan(s) along ColorToKitchen (1 valid)")
    first = json.loads(out or "{}")
    if not (first.get("valid") and first["goal"]["satisfied"] == first["goal"]["total"]
            and first["target_plan"][0] == "unstack(E, D)"):
        failures.append(f"the case study's transfer: {out}")
    out = run("library", "transfer", MAP, "--map", "ColorToKitchen", "--db", url, "--jobs", "2",
              err="transferred 1 plan(s) along ColorToKitchen (0 valid) in")
    run("library", "transfer", MAP, "--map", "ColorToKitchen", "--db", url,
        err="transferred 0 plan(s) along ColorToKitchen (0 valid)")
    failed = [json.loads(l) for l in run("library", "query", "--db", url, "--failed").splitlines()]
    if len(failed) != 1 or failed[0]["label"] != "tests/cli/data/short.plan" or failed[0]["source_valid"]:
        failures.append(f"library query --failed: {failed}")
    listed = run("library", "query", "--db", url, "--plans", "--problem", "CaseStudy")
    if len(listed.splitlines()) != 2:
        failures.append(f"library query --plans: {listed}")
    # A plan with a syntax error stores nothing.
    run("library", "add", CB, "--problem", "CaseStudy", "tests/cli/data/syntax.plan", "--db", url,
        code=2, err="syntax.plan:")
    listed = run("library", "query", "--db", url, "--plans")
    if len(listed.splitlines()) != 2:
        failures.append(f"a refused add stored plans: {listed}")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        url = fresh_database(tmp)
        states(url)
        migration(url)
        library(url)
        run("db", "import", CB, "ColorBlocksworld", "--db", "sqlite:/nonexistent-dir/x.db", code=2,
            err="cannot open SQLite database")
        run("db", "export", CB, "Initial", "--db", "mysql://x", code=2,
            err="is not a database URL: write sqlite:PATH or postgresql://")
    for f in failures:
        print(f)
    print(f"{ENGINE}: {'ok' if not failures else str(len(failures)) + ' failure(s)'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
