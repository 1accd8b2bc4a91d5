# The two commands of the README. Both install what is missing (tools/install-deps.sh) and build
# what is needed; the CMake presets hold the build settings.
.PHONY: all deps demo test build release bench interop format check-format check-layers check-sizes clean python \
	install

JOBS ?= 2
PREFIX ?= /usr/local
PYTHON ?= /usr/bin/python3
VENV ?= build/venv

all: release

deps:
	@./tools/install-deps.sh

build: deps
	cmake --preset dev >/dev/null
	cmake --build --preset dev -j $(JOBS)

release: deps
	cmake --preset release >/dev/null
	cmake --build --preset release -j $(JOBS) --target catplan

# Every test (unit, golden, examples) under AddressSanitizer and UndefinedBehaviorSanitizer.
test: build
	ctest --preset dev -j $(JOBS)

# The main job: the paper's case study, printed readably.
demo: release
	@./tools/demo.sh build/release/src/catplan/cli/catplan

# The Python package in a virtual environment that also sees Debian's numpy and pytest (Debian 12
# marks its python3 externally managed; docs/python.md). Offline: nothing is downloaded.
python: deps
	$(PYTHON) -m venv --system-site-packages $(VENV)
	$(VENV)/bin/pip install --no-build-isolation --no-index --no-deps .
	@echo "catplan is installed in $(VENV): $(VENV)/bin/python -c 'import catplan'"

# The C++ library, its headers and CMake package (find_package(catplan)), the catplan command,
# its man page and its bash completion.
install: deps
	cmake --preset release >/dev/null
	cmake --build --preset release -j $(JOBS) --target catplan catplan_cli_docs
	cmake --install build/release --prefix $(PREFIX)

# `pddl export` against Fast Downward and VAL (tools/interop.sh): not part of `test`, since the
# peers are not part of the product; skipped, with a message, when PEERS has none.
PEERS ?=
interop: release
	PEERS=$(PEERS) ./tools/interop.sh build/release/src/catplan/cli/catplan

bench: deps
	cmake --preset release >/dev/null
	cmake --build --preset release -j $(JOBS)
	./tools/run-benchmarks.sh build/release

format:
	find src tests bench fuzz python/src -name '*.[ch]pp' | xargs clang-format -i

check-format:
	find src tests bench fuzz python/src -name '*.[ch]pp' | xargs clang-format --dry-run --Werror

check-layers:
	python3 tools/check_layers.py

check-sizes:
	python3 tools/check_sizes.py

clean:
	rm -rf build
