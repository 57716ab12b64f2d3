# strike: make test runs luacheck and the busted suite under every Lua VM.
VMS ?= lua5.1 lua5.2 lua5.3 lua5.4 luajit

.PHONY: test deps lint spec copy-check bench

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
