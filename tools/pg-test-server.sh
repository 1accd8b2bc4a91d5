#!/bin/sh
# Starts or stops a private PostgreSQL server for the tests: a cluster made by initdb in DIR,
# listening on a Unix socket in DIR only (no TCP port), stopped and removed by `stop`.
#
#   tools/pg-test-server.sh start DIR   # writes DIR/url (a postgresql:// URL) or DIR/error
#   tools/pg-test-server.sh stop DIR
#
# PostgreSQL refuses to run as root, so as root the server runs as the `postgres` user that
# Debian's package creates. `start` exits 0 even when the server cannot start and says why in
# DIR/error, so that the tests that need it can say so themselves.
set -u
cmd=${1:?start or stop}
dir=${2:?directory}

bindir=""
for d in /usr/lib/postgresql/*/bin; do
    [ -x "$d/initdb" ] && bindir=$d
done

as_owner() {
    if [ "$(id -u)" -eq 0 ]; then
        runuser -u postgres -- "$@"
    else
        "$@"
    fi
}

stop_server() {
    if [ -f "$dir/data/postmaster.pid" ] && [ -n "$bindir" ]; then
        as_owner "$bindir/pg_ctl" -D "$dir/data" -m fast -w stop >/dev/null 2>&1
    fi
}

case "$cmd" in
start)
    stop_server # one left running by a run that was killed
    rm -rf "$dir"
    mkdir -p "$dir"
    if [ -z "$bindir" ]; then
        echo "PostgreSQL is not installed (no /usr/lib/postgresql/*/bin/initdb; tools/install-deps.sh installs it)" >"$dir/error"
        cat "$dir/error" >&2
        exit 0
    fi
    if [ "$(id -u)" -eq 0 ]; then
        if ! id postgres >/dev/null 2>&1; then
            echo "running as root and there is no 'postgres' user to run the server as" >"$dir/error"
            cat "$dir/error" >&2
            exit 0
        fi
        chown postgres "$dir"
    fi
    if ! as_owner "$bindir/initdb" -D "$dir/data" -A trust -U catplan -E UTF8 --locale=C \
        --no-sync >"$dir/initdb.log" 2>&1; then
        echo "initdb failed: $(tail -n 3 "$dir/initdb.log")" >"$dir/error"
        cat "$dir/error" >&2
        exit 0
    fi
    # Settings for a throw-away server: no TCP, no fsync, small memory.
    if ! as_owner "$bindir/pg_ctl" -D "$dir/data" -l "$dir/server.log" -w -t 60 \
        -o "-k $dir -c listen_addresses= -F -c full_page_writes=off -c synchronous_commit=off -c max_connections=20 -c shared_buffers=32MB" \
        start >"$dir/pg_ctl.log" 2>&1; then
        echo "pg_ctl could not start the server: $(tail -n 3 "$dir/server.log" 2>/dev/null)" >"$dir/error"
        cat "$dir/error" >&2
        exit 0
    fi
    echo "postgresql:///postgres?host=$dir&user=catplan" >"$dir/url"
    echo "$("$bindir/postgres" --version) started: $(cat "$dir/url")"
    ;;
stop)
    stop_server
    rm -rf "$dir"
    ;;
*)
    echo "usage: $0 start|stop DIR" >&2
    exit 2
    ;;
esac
