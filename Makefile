# Nome: `make run` and `make test` are all a new machine needs (Debian 12, as root).
# The package list lives here and only here.
PACKAGES := build-essential cmake pkg-config clang-format lib3mf-dev libglfw3-dev libimgui-dev libstb-dev libglm-dev \
            python3-glad libtinyobjloader-dev libtinygltf-dev libgif-dev catch2 libegl-dev libgl1-mesa-dri libosmesa6-dev xvfb xauth \
            libbenchmark-dev libopenmesh-dev libcgal-dev libosd-dev clang-14 libclang-rt-14-dev clang-tidy \
            file desktop-file-utils shared-mime-info graphviz tcl8.6-dev

# The browser build's packages (make web, make test); desktop-only runs never install them.
WEB_PACKAGES := emscripten node-acorn nlohmann-json3-dev chromium

JOBS    ?= 2
# Builds run as sub-makes of this one: under a parallel make they share its job slots (make test runs the
# test build and both web builds side by side, so no core idles while one of them links); on their own they
# take JOBS.
PARALLEL = $(if $(findstring jobserver,$(MAKEFLAGS)),,-j$(JOBS))
EXAMPLE ?= assets/funnel_cube.nome
RELEASE := build/release
TESTDIR := build/test
FUZZDIR := build/fuzz
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 1
FUZZ_TARGETS ?=
# Any sanitizer report fails the run: abort (never exit status 1, which a test of a refused input
# expects), leaks included. Child processes (the CLI under test) inherit these.
SANITIZER_ENV := ASAN_OPTIONS=abort_on_error=1:halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1 \
                 UBSAN_OPTIONS=abort_on_error=1:halt_on_error=1:print_stacktrace=1
SOURCES  = $(shell git ls-files '*.cpp' '*.hpp' 2>/dev/null | grep -v '^third_party/')

GALLERY_SIZE ?= 640x480

PREFIX     ?= /usr/local
PACKAGEDIR := build/package

.PHONY: web web-one web-threads web-deps serve web-bench gltf-validator run test sanitize-full deps release test-build format format-check lint bench clean soak fuzz fuzz-build tsan references gallery layers \
        install package package-test icon hardening mutants mutants-sample

deps:
	@missing=""; for p in $(PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi

# The web page: the same kernel and viewer through Debian's Emscripten, ImGui from Debian's source package
# (a deb-src entry for bookworm main is added when missing), in two builds: one thread, and pthreads for a
# page served with cross-origin isolation (make serve). Debian's emscripten finds its JS optimizer's acorn
# through NODE_PATH; its HTML output step fails, so the page is web/page's own.
WEBDIR     := build/web
IMGUI_SRC  := build/web-deps/imgui-1.86
WEB_SCENES := build/web-deps/scenes
WEB_PORT   ?= 8040
EMSDK_ENV  := NODE_PATH=/usr/share/nodejs
WEB_CMAKE  := -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON -DNOME_IMGUI_SOURCE_DIR=$(CURDIR)/$(IMGUI_SRC) \
              -DNOME_WEB_SCENES=$(CURDIR)/$(WEB_SCENES)
web-deps: deps
	@missing=""; for p in $(WEB_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi
	@if [ ! -f $(IMGUI_SRC)/imgui.cpp ]; then \
	  if ! grep -rqs "deb-src" /etc/apt/sources.list /etc/apt/sources.list.d/; then \
	    printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
	      > /etc/apt/sources.list.d/nome-deb-src.sources; \
	    apt-get update -qq; \
	  fi; \
	  mkdir -p build/web-deps && cd build/web-deps && apt-get source --download-only -qq imgui=1.86+ds-1 2>/dev/null \
	    && tar xf imgui_1.86+ds.orig.tar.xz; \
	fi
	@test -f $(IMGUI_SRC)/imgui.cpp || { echo "ImGui 1.86's sources could not be fetched (apt-get source imgui)"; exit 1; }
	@rm -rf $(WEB_SCENES) && mkdir -p $(WEB_SCENES)
	@cp assets/*.nome assets/*.obj assets/*.stl assets/*.sif assets/*.slf $(WEB_SCENES)/ 2>/dev/null || true
	@if [ -d ../shared/examples/jipcad ]; then mkdir -p $(WEB_SCENES)/jipcad && cp ../shared/examples/jipcad/*.nom $(WEB_SCENES)/jipcad/; fi

web-one: web-deps
	$(EMSDK_ENV) emcmake cmake -S . -B build/web-one $(WEB_CMAKE) >/dev/null
	+$(EMSDK_ENV) $(MAKE) --no-print-directory -C build/web-one $(PARALLEL)

web-threads: web-deps
	$(EMSDK_ENV) emcmake cmake -S . -B build/web-threads $(WEB_CMAKE) -DNOME_WEB_THREADS=ON \
	  -DCMAKE_CXX_FLAGS=-pthread -DCMAKE_C_FLAGS=-pthread >/dev/null
	+$(EMSDK_ENV) $(MAKE) --no-print-directory -C build/web-threads $(PARALLEL)

web: web-one web-threads
	@rm -rf $(WEBDIR) && mkdir -p $(WEBDIR)
	@cp web/page/* build/web-one/web/nome.js build/web-one/web/nome.wasm build/web-one/web/nome.data \
	  build/web-threads/web/nome-threads.* $(WEBDIR)/
	@cd $(WEB_SCENES) && find . -type f | sed 's#^\./##' | sort | python3 -c 'import json,sys; print(json.dumps(sys.stdin.read().splitlines()))' \
	  > $(CURDIR)/$(WEBDIR)/scenes.json
	@echo "Built $(WEBDIR): $$(du -h $(WEBDIR)/nome.wasm | cut -f1) nome.wasm; \`make serve\` serves it"

# Catmull-Clark level 4 of the funnel cube natively and as WebAssembly under node, in one run.
web-bench: web
	cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DNOME_TESTS=OFF -DNOME_BENCH=ON >/dev/null
	cmake --build build/bench -j$(JOBS) --target nome_bench_web_kernel
	+$(EMSDK_ENV) $(MAKE) --no-print-directory -C build/web-one $(PARALLEL) nome_web_kernel_bench
	@native=$$(build/bench/bench/nome_bench_web_kernel); web=$$(node build/web-one/web/nome-kernel-bench.js); \
	echo "native:      $$native"; echo "WebAssembly: $$web"; \
	n=$$(echo "$$native" | awk '{ print $$(NF - 1) }'); w=$$(echo "$$web" | awk '{ print $$(NF - 1) }'); \
	awk -v n=$$n -v w=$$w 'BEGIN { printf "WebAssembly / native: %.2f (target <= 3)\n", w / n }'
	@python3 web/serve.py $(WEBDIR) $(WEB_PORT) >/dev/null 2>&1 & server=$$!; sleep 1; \
	for query in "scene=funnel_cube.nome" "threads=0&scene=funnel_cube.nome"; do \
	  node --experimental-websocket tests/app/web_page_driver.js "http://127.0.0.1:$(WEB_PORT)/?$$query" \
	    build/web-bench.png | grep -E "page: (threads|one-thread|first)" | tr '\n' ' '; echo "(target <= 3000 ms)"; \
	done; kill $$server

serve: web
	python3 web/serve.py $(WEBDIR) $(WEB_PORT)

# A unity build, grouped as the test build below: a fresh clone's first picture in about half the time of
# compiling its files one by one (docs/architecture.md).
release: deps
	cmake -S . -B $(RELEASE) -DCMAKE_BUILD_TYPE=Release -DNOME_TESTS=OFF -DCMAKE_UNITY_BUILD=ON >/dev/null
	cmake --build $(RELEASE) -j$(JOBS)

run: release
	@if [ -n "$$DISPLAY" ]; then \
	  $(RELEASE)/app/nome $(EXAMPLE); \
	else \
	  out=build/run/$$(basename $(EXAMPLE) | sed 's/\.[^.]*$$//').png; mkdir -p build/run; \
	  echo "No DISPLAY: rendering $(EXAMPLE) headless instead of opening the viewer."; \
	  $(RELEASE)/app/nome info $(EXAMPLE) && \
	  $(RELEASE)/app/nome render $(EXAMPLE) -o $$out --verbose && echo "Picture: $$PWD/$$out"; \
	fi

# The sanitized test build compiles as unity builds (eight files a unit: about 45 % less compile time), so
# names in anonymous namespaces must differ across a target's files. UBSan's null and alignment checks are
# left out here (CMakeLists.txt says why); `make sanitize-full` builds and runs the suite with all of them.
test-build: deps gltf-validator
	cmake -S . -B $(TESTDIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNOME_SANITIZE=ON -DCMAKE_UNITY_BUILD=ON \
	  "-DNOME_SANITIZE_SKIP=alignment;null" >/dev/null
	+$(MAKE) --no-print-directory -C $(TESTDIR) $(PARALLEL)

# A test case that cannot find the shared examples, llvmpipe, node or the web page fails under CI (`CI` set);
# elsewhere it skips, writes why to the skip log and is counted here. The web page's tests open build/web in
# headless Chromium. The three builds run side by side in JOBS slots. Then the cases that read ../shared run
# again with an empty shared folder (skips allowed): a clone without it passes too.
test:
	+@$(MAKE) --no-print-directory $(PARALLEL) format-check test-build web
	@rm -f $(TESTDIR)/skipped_tests.log $(TESTDIR)/shared_use.log
	cd $(TESTDIR) && $(SANITIZER_ENV) ctest --output-on-failure -j$(JOBS)
	@if [ -s $(TESTDIR)/skipped_tests.log ]; then \
	  echo "Skipped test cases: $$(wc -l < $(TESTDIR)/skipped_tests.log) (the CI run fails them)"; \
	  sort $(TESTDIR)/skipped_tests.log | sed 's/^/  /'; \
	else echo "Skipped test cases: 0"; fi
	$(SANITIZER_ENV) python3 tests/without_shared.py $(TESTDIR)

# The Khronos glTF validator (npm's gltf-validator) that the .glb export test runs with node; without npm
# or the network the test skips and says so.
VALIDATOR := build/tools/node_modules/gltf-validator
gltf-validator:
	@if [ -d $(VALIDATOR) ]; then :; \
	elif command -v npm >/dev/null 2>&1; then \
	  npm install --prefix build/tools --no-audit --no-fund gltf-validator >/dev/null 2>&1 \
	    || echo "gltf-validator could not be installed: the .glb validation test will skip"; \
	else echo "no npm: the .glb validation test will skip"; fi

# Every UBSan check, files compiled one by one: slower to build than `make test`, not part of it.
sanitize-full: deps
	cmake -S . -B build/sanitize-full -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNOME_SANITIZE=ON -DNOME_SANITIZE_SKIP= >/dev/null
	cmake --build build/sanitize-full -j$(JOBS)
	cd build/sanitize-full && $(SANITIZER_ENV) ctest --output-on-failure -j$(JOBS)

# `make install PREFIX=/opt/nome` (DESTDIR=/stage as well, to stage it). Every installed path is listed in
# build/release/install_manifest.txt: `xargs rm < build/release/install_manifest.txt` uninstalls.
install: release
	cmake --install $(RELEASE) --prefix $(PREFIX)

# The Debian packages nome and nome-dev (CPack DEB, packaging/cpack.cmake) in build/package/.
package: release
	rm -rf $(PACKAGEDIR)
	cd $(RELEASE) && cpack -B $(CURDIR)/$(PACKAGEDIR)
	@for deb in $(PACKAGEDIR)/*.deb; do echo "$$deb: $$(du -k $$deb | cut -f1) KB"; done

# Checks the packages' control data and file lists, extracts them (dpkg-deb -x, never dpkg -i) into a
# temporary folder and runs nome and a find_package(Nome) program from there. Not part of `make test`.
package-test: package
	tests/install/package_test.sh $(PACKAGEDIR) $(CURDIR)

# The desktop icon: a Möbius band drawn by nome render (look at it before committing).
icon: release
	$(RELEASE)/app/nome render assets/mobius_band.obj -o packaging/nome.png --size 256x256 --transparent \
	  --view 25,-25 --subdiv 2

# The long property runs (10,000 random manifolds each), hidden from `make test` by their [.] tag.
soak: test-build
	$(SANITIZER_ENV) $(TESTDIR)/tests/nome_kernel_tests "[soak]" --durations yes

# ThreadSanitizer: the kernel tests and the app tests that start threads (tag [threads]: the viewer's
# background computation). The rest of the app tests drive Mesa, whose own threads TSan cannot see into.
TSAN_TESTS ?= [threads]
tsan: deps
	cmake -S . -B build/tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNOME_TSAN=ON >/dev/null
	cmake --build build/tsan -j$(JOBS)
	cd build/tsan && TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 tests/nome_kernel_tests
	cd build/tsan && TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 tests/nome_app_tests "$(TSAN_TESTS)"

# libFuzzer targets (clang-14): each runs FUZZ_SECONDS (FUZZ_JOBS at a time), keeps its corpus in $(FUZZDIR)/corpus and
# writes crashes to $(FUZZDIR)/artifacts (turn each into a test: tests/data/fuzz/README.md).
fuzz-build: deps
	cmake -S . -B $(FUZZDIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 \
	  -DCMAKE_CXX_COMPILER=clang++-14 -DNOME_FUZZ=ON -DNOME_APP=OFF -DNOME_TESTS=OFF >/dev/null
	cmake --build $(FUZZDIR) -j$(JOBS)

fuzz: fuzz-build
	FUZZ_JOBS=$(FUZZ_JOBS) FUZZ_TARGETS="$(FUZZ_TARGETS)" tests/fuzz/run_fuzzers.sh $(FUZZDIR) $(FUZZ_SECONDS)

# Everything that does not fit beside `make test` in CI: soak, a short fuzz of every target
# (FUZZ_SECONDS=120 each, two at a time: 12 minutes for the 12 targets, after the clang build) and
# ThreadSanitizer. Measured on the 2-core machine: soak 722 s of CPU on one thread (25 min wall at load 9,
# about 12 min quiet); fuzz 12 min after the clang build; tsan's build 1,470 s of CPU (about 13 min on two
# cores) and its tests under 2 min. About 45 minutes in all on a quiet machine: too long to sit beside
# `make test` in CI's 90.
hardening:
	$(MAKE) soak
	$(MAKE) fuzz FUZZ_SECONDS=$(or $(HARDENING_FUZZ_SECONDS),120) FUZZ_JOBS=2
	$(MAKE) tsan

# Mutation check: each mutation of tests/mutants/*.toml is applied alone, its tests run, and every one
# must be caught. Checks first that every mutation still applies and names each stale one. Edits the
# source while it runs (restored after each mutation): commit first.
mutants: deps
	tests/mutants/mutants.py --build build/mutants

# Sampled mutations: MUTANTS mutants drawn at random (random.Random(SEED)) from the lines of kernel/ and
# app/, half from each, each run against the test files that execute its line (a coverage build maps them,
# cached until the sources change). Edits the source while it runs (restored after each mutant): commit
# first. Report in build/mutants-sample/report-seed$(SEED).txt.
SEED    ?= 1
MUTANTS ?= 60
mutants-sample: deps
	tests/mutants/sample.py --seed $(SEED) --mutants $(MUTANTS) --jobs $(JOBS)

format-check: deps
	@clang-format --dry-run --Werror $(SOURCES) && echo "clang-format: $(words $(SOURCES)) files clean"

format: deps
	clang-format -i $(SOURCES)

# clang-tidy with the checked-in .clang-tidy over the kernel and the app (not part of `make test`: it
# takes longer than the build and is not clean yet).
LINT_FILES ?= $(filter kernel/% app/%,$(filter %.cpp,$(SOURCES)))
lint: deps
	cmake -S . -B build/lint -DCMAKE_BUILD_TYPE=Debug -DNOME_TESTS=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
	clang-tidy -p build/lint --quiet $(LINT_FILES)

# Rewrites tests/render/reference/*.png after an intended change to the pictures (look at them first).
references: test-build
	NOME_UPDATE_REFERENCES=1 LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp \
	  $(TESTDIR)/tests/nome_app_tests "[reference]"

# The kernel's layer libraries and which links which (docs/architecture.md), from CMake's own target graph
# of a kernel-only configuration (without CMake's legend of target kinds): docs/kernel_layers.svg.
layers: deps
	@mkdir -p build/layers
	@printf '%s\n' 'set(GRAPHVIZ_GRAPH_NAME "nome kernel layers")' 'set(GRAPHVIZ_EXTERNAL_LIBS FALSE)' \
	  'set(GRAPHVIZ_IGNORE_TARGETS nome_kernel)' 'set(GRAPHVIZ_GENERATE_PER_TARGET FALSE)' \
	  'set(GRAPHVIZ_GENERATE_DEPENDERS FALSE)' > build/layers/CMakeGraphVizOptions.cmake
	cmake -S . -B build/layers -DNOME_APP=OFF -DNOME_TESTS=OFF --graphviz=build/layers/kernel_layers.dot >/dev/null
	sed '/^subgraph clusterLegend/,/^}/d' build/layers/kernel_layers.dot | dot -Tsvg -o docs/kernel_layers.svg

# Renders every file in assets/ into docs/gallery/ and lists them, with their topology, in docs/gallery.md.
gallery: release
	@rm -rf docs/gallery && mkdir -p docs/gallery
	@{ echo "# Gallery"; echo; \
	   echo "Every file in assets/, drawn by \`make gallery\` (\`nome render FILE --wire --size $(GALLERY_SIZE)\`):"; \
	   echo "gold is the front of a face, blue its back, so a one-sided surface shows both colours."; \
	   echo; } > docs/gallery.md
	@for f in $$(git ls-files assets | sort); do \
	  name=$$(basename $$f | sed 's/\./_/g'); \
	  $(RELEASE)/app/nome render $$f -o docs/gallery/$$name.png --wire --size $(GALLERY_SIZE) || exit 1; \
	  { echo "## $$(basename $$f)"; echo; echo '```'; $(RELEASE)/app/nome info $$f | grep -E "^(vertices|components)"; echo '```'; \
	    echo; echo "![$$(basename $$f)](gallery/$$name.png)"; echo; } >> docs/gallery.md; \
	done
	@{ echo "# Thickened into solids"; echo; \
	   echo "Catmull-Clark, then the offset: each one-sided surface becomes a closed, orientable solid (all gold)."; \
	   echo; } >> docs/gallery.md
	@while read -r name f view options; do \
	  $(RELEASE)/app/nome render $$f -o docs/gallery/$$name.png --view $$view $$options --size $(GALLERY_SIZE) \
	    || exit 1; \
	  { echo "## $$name"; echo; echo "\`nome render $$f --view $$view $$options\`"; echo; echo '```'; \
	    $(RELEASE)/app/nome info $$f $$options | grep -E "^(vertices|components)"; echo '```'; \
	    echo; echo "![$$name](gallery/$$name.png)"; echo; } >> docs/gallery.md; \
	done < docs/gallery_solids.txt
	@echo "Wrote docs/gallery.md and $$(ls docs/gallery | wc -l) pictures in docs/gallery/"

bench: deps
	cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DNOME_TESTS=OFF -DNOME_BENCH=ON >/dev/null
	cmake --build build/bench -j$(JOBS)
	for b in build/bench/bench/nome_bench_*; do $$b; done

clean:
	rm -rf build
