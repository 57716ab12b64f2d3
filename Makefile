# strike: make test runs luacheck and the busted suite under every Lua VM.
VMS ?= lua5.1 lua5.2 lua5.3 lua5.4 luajit

.PHONY: test deps lint spec copy-check bench demo

test: deps lint copy-check spec

# Installs what the checks need (Debian packages) when it is missing and this machine can
# (root with apt-get); otherwise says exactly what to install.
deps:
	@bash tools/deps.sh $(VMS)

lint:
	@echo "== luacheck"
	@luacheck --formatter plain --codes .

spec:
	@bash tools/spec.sh $(VMS)

# The folder works wherever a game copies it.
copy-check:
	@bash tools/copy-check.sh $(VMS)

# Benchmarks, not part of test: bench/run.lua under each of BENCH_VMS, tables printed and
# saved to bench/results/<vm>.csv. STRIKE_PEERS=/path/to/peers adds the peers found there.
BENCH_VMS ?= luajit lua5.4

bench:
	@BENCH_VMS="$(BENCH_VMS)" bash bench/bench.sh

# The headless example (plain Lua, any VM): a scene's collisions, MTVs, contact points and a
# ray cast as a table, and a picture of it as SVG (DEMO_SVG=path, default strike-demo.svg).
# The interactive LÖVE demo is not written yet.
DEMO_LUA ?= $(firstword $(foreach vm,luajit lua5.4 lua5.3 lua5.2 lua5.1 lua,$(shell command -v $(vm) 2>/dev/null)))
DEMO_SVG ?= strike-demo.svg

demo:
	@$(DEMO_LUA) examples/demo.lua $(DEMO_SVG)
