# Thin wrapper around CMake/CTest. `make render` and `make test` are all a newcomer needs.
BUILD ?= build
FUZZ_BUILD ?= build-fuzz
TSAN_BUILD ?= build-tsan
JOBS ?= 2
FUZZ_SECONDS ?= 600
WERROR := $(if $(filter true,$(CI)),ON,OFF)

.PHONY: all deps configure build render test corpus fuzz tsan bench bench-radiosity clean

all: build

deps:
	@tools/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DLUMEN_WERROR=$(WERROR) >/dev/null

build: configure
	cmake --build $(BUILD) -j$(JOBS)

render: configure
	cmake --build $(BUILD) --target lumen -j$(JOBS)
	$(BUILD)/lumen examples/showcase.pov +W640 +H480 +A0.3 +O$(BUILD)/showcase.png
	@echo "showcase image: $(abspath $(BUILD))/showcase.png"

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

# The corpus report: POV-Ray's 396 sample scenes rendered by lumen and POV-Ray at 160x120
# (build/corpus/index.html, corpus.tsv; POV-Ray's images cached there). CORPUS_ARGS passes
# options and scene-path filters to tools/corpus, e.g. CORPUS_ARGS="--jobs 1 radiosity/".
corpus: configure
	cmake --build $(BUILD) --target lumen differential -j$(JOBS)
	tools/corpus --lumen $(BUILD)/lumen --compare $(BUILD)/tests/differential/differential \
	    --out $(BUILD)/corpus --jobs $(JOBS) $(CORPUS_ARGS)

fuzz: deps
	@cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
	    -DLUMEN_FUZZ=ON -DLUMEN_TESTS=OFF >/dev/null
	cmake --build $(FUZZ_BUILD) --target parse_fuzz -j$(JOBS)
	tests/fuzz/run.sh $(FUZZ_BUILD)/tests/fuzz/parse_fuzz $(FUZZ_SECONDS)

# ThreadSanitizer build (clang) and multithreaded renders that must give no report. Not part
# of `make test`: the instrumented build alone takes longer than the whole suite.
tsan: deps
	@cmake -S . -B $(TSAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
	    -DLUMEN_SANITIZE=thread -DLUMEN_TESTS=OFF >/dev/null
	cmake --build $(TSAN_BUILD) --target lumen -j$(JOBS)
	tools/tsan-check.sh $(TSAN_BUILD)/lumen

bench: configure
	cmake --build $(BUILD) --target lumen parse_includes -j$(JOBS)
	$(BUILD)/bench/parse_includes
	bench/render_vs_povray.sh $(BUILD)/lumen
	bench/render_vs_povray.sh $(BUILD)/lumen $$(nproc) 3 bench/algebraic.pov

# Radiosity error against time (about 18 minutes on a shared 2-core machine; writes
# docs/radiosity_*.csv and .png).
# QUICK=1: a few points, written to $(BUILD)/radiosity-bench instead.
bench-radiosity: configure
	@tools/install-deps.sh --bench
	cmake --build $(BUILD) --target lumen radiosity_sweep_library -j$(JOBS)
	bench/radiosity_sweep.sh $(if $(QUICK),--quick --out $(BUILD)/radiosity-bench) \
	    --lumen $(BUILD)/lumen --library $(BUILD)/bench/radiosity_sweep_library

clean:
	rm -rf $(BUILD) $(FUZZ_BUILD) $(TSAN_BUILD)
