# Nome: `make run` and `make test` are all a new machine needs (Debian 12, as root).
# The package list lives here and only here.
PACKAGES := build-essential cmake pkg-config clang-format libglfw3-dev libimgui-dev libstb-dev libglm-dev \
            python3-glad libtinyobjloader-dev catch2 libegl-dev libgl1-mesa-dri libosmesa6-dev xvfb xauth \
            libbenchmark-dev libopenmesh-dev

JOBS    ?= 2
EXAMPLE ?= assets/mobius_band.obj
RELEASE := build/release
TESTDIR := build/test
SOURCES  = $(shell git ls-files '*.cpp' '*.hpp' 2>/dev/null | grep -v '^third_party/')

.PHONY: run test deps release test-build format format-check bench clean

deps:
	@missing=""; for p in $(PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi

release: deps
	cmake -S . -B $(RELEASE) -DCMAKE_BUILD_TYPE=Release -DNOME_TESTS=OFF >/dev/null
	cmake --build $(RELEASE) -j$(JOBS)

run: release
	@if [ -n "$$DISPLAY" ]; then \
	  $(RELEASE)/app/nome $(EXAMPLE); \
	else \
	  $(RELEASE)/app/nome info $(EXAMPLE); \
	fi

test-build: deps
	cmake -S . -B $(TESTDIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNOME_SANITIZE=ON >/dev/null
	cmake --build $(TESTDIR) -j$(JOBS)

test: format-check test-build
	cd $(TESTDIR) && ctest --output-on-failure -j$(JOBS)

format-check: deps
	@clang-format --dry-run --Werror $(SOURCES) && echo "clang-format: $(words $(SOURCES)) files clean"

format: deps
	clang-format -i $(SOURCES)

bench: deps
	cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DNOME_TESTS=OFF -DNOME_BENCH=ON >/dev/null
	cmake --build build/bench -j$(JOBS)
	for b in build/bench/bench/nome_bench_*; do $$b; done

clean:
	rm -rf build
