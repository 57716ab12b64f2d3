# strike: make test runs luacheck, the LuaLS annotation check, the copy check, the rockspec
# check, the LÖVE screenshot checks and the busted suite under every Lua VM.
VMS ?= lua5.1 lua5.2 lua5.3 lua5.4 luajit

.PHONY: test deps lint annotations annotations-fix api spec copy-check rockspec-check love-check bench bench-space bench-move bench-movers bench-narrow demo

test: deps lint annotations copy-check rockspec-check love-check spec

# Installs what the checks need (Debian packages) when it is missing and this machine can
# (root with apt-get); otherwise says exactly what to install.
deps:
	@bash tools/deps.sh $(VMS)

lint:
	@echo "== luacheck"
	@luacheck --formatter plain --codes .

# Every public function in strike/ has LuaLS annotations the language server can read: one
# tag per line, a ---@param per parameter in order, ---@return when it returns a value
# (rules: tools/annotations.lua). `make annotations-fix` splits lines carrying several tags.
ANNOTATIONS_LUA ?= $(firstword $(VMS))

annotations:
	@echo "== annotations"
	@$(ANNOTATIONS_LUA) tools/annotations.lua $$(find strike -name '*.lua' | sort)

annotations-fix:
	@$(ANNOTATIONS_LUA) tools/annotations.lua --fix $$(find strike -name '*.lua' | sort)

# docs/api.md, the API reference, generated from those annotations (tools/apidoc.lua); the
# suite fails while it is out of date (spec/docs_api_spec.lua).
api:
	@$(ANNOTATIONS_LUA) tools/apidoc.lua --write docs/api.md $$(find strike -name '*.lua' | LC_ALL=C sort)

# The screenshot spec reads SHOTS when love-check completed a set there (SHOTS/ok).
spec:
	@if [ -f $(SHOTS)/ok ]; then export STRIKE_SCREENSHOTS=$(SHOTS); fi; bash tools/spec.sh $(VMS)

# LÖVE: screenshots of every demo scene, under xvfb-run (installs love and xvfb when it
# can; says so and skips otherwise).
SHOTS ?= build/screenshots

love-check:
	@bash tools/love-check.sh $(SHOTS)

# The folder works wherever a game copies it.
copy-check:
	@bash tools/copy-check.sh $(VMS)

# strike-scm-1.rockspec: luarocks lint, luarocks make into a temporary tree (offline), the tree
# holds every file of strike/, and require 'strike' from it works under every VM.
rockspec-check:
	@bash tools/rockspec-check.sh $(VMS)

# Benchmarks, not part of test: bench/run.lua, bench/move.lua, bench/movers.lua,
# bench/tiled.lua (S.tiled's first load in fresh processes) and bench/space.lua (the world
# beside the peers) under each of BENCH_VMS (bench/bench.sh), tables printed and saved to
# bench/results/<vm>.csv, move-, movers-, tiled- and space-<vm>.csv (LuaJIT: also the
# -luajit-stock.csv of the runs under the standalone limits); then, once, when love is on the
# PATH, bench/narrow.lua (bench/results/narrow-love.csv). STRIKE_PEERS=/path/to/peers adds
# the peers found there.
BENCH_VMS ?= luajit lua5.4

bench:
	@BENCH_VMS="$(BENCH_VMS)" bash bench/bench.sh

# bench/space.lua under each of BENCH_VMS in turn: S.pace on issue 11's world workloads (frames,
# rays, build + add, churn, memory) beside HC and bump (STRIKE_PEERS) and Box2D through LÖVE
# (when love is on the PATH); tables printed and saved to bench/results/space-<vm>.csv.
# SPACE_ARGS="--n 1000,5000 --frames 30" for a shorter run.
SPACE_ARGS ?=

bench-space:
	@status=0; for vm in $(BENCH_VMS); do \
	  echo "== bench/space.lua under $$vm"; $$vm bench/space.lua --save $(SPACE_ARGS) || status=1; echo; \
	done; exit $$status

# bench/narrow.lua: the narrow phase at 10,000 pairs (poly-poly, circle-poly), strike's S.AT and
# S.triking beside Box2D's contact update, both timed inside LÖVE (love on the PATH; the VM
# here only reads LÖVE's lines), with issue 21's target 5 (strike at half Box2D's rate or more);
# the tables printed and saved to bench/results/narrow-love.csv. NARROW_ARGS="--pairs 2000".
NARROW_ARGS ?=

bench-narrow:
	@$(firstword $(BENCH_VMS)) bench/narrow.lua --save $(NARROW_ARGS)

# bench/move.lua under each of BENCH_VMS in turn: S.pace's move of one 16x16 box through 1,000
# static boxes beside bump's and slick's world:move (STRIKE_PEERS): µs per move, collisions per
# move, KB per move with the GC stopped; tables printed and saved to bench/results/move-<vm>.csv.
# MOVE_ARGS="--moves 2000" for a shorter run.
MOVE_ARGS ?=

bench-move:
	@status=0; for vm in $(BENCH_VMS); do \
	  echo "== bench/move.lua under $$vm"; $$vm bench/move.lua --save $(MOVE_ARGS) || status=1; echo; \
	done; exit $$status

# bench/movers.lua under each of BENCH_VMS in turn, LuaJIT with LÖVE's JIT limits and with its
# stock ones: every body of a world of 2,000 and 10,000 boxes and capsules moved by space:move
# every frame, beside bump's and slick's world:move (STRIKE_PEERS), with LuaJIT's trace flushes
# during the timed frames; tables printed and saved to bench/results/movers-<vm>.csv.
# MOVERS_ARGS="--n 2000 --frames 9" for a shorter run.
MOVERS_ARGS ?=

bench-movers:
	@status=0; for vm in $(BENCH_VMS); do \
	  for lim in $$(if [ "$$vm" = luajit ]; then echo love stock; else echo love; fi); do \
	    echo "== bench/movers.lua under $$vm (--jit $$lim)"; $$vm bench/movers.lua --save --jit $$lim $(MOVERS_ARGS) || status=1; echo; \
	  done; \
	done; exit $$status

# `make demo`: the interactive LÖVE demo (love demo) where LÖVE and a display are present;
# otherwise, or with HEADLESS=1, the headless example (plain Lua, any VM): a scene's
# collisions, MTVs and contact points, a rectangle query and a ray cast through an S.pace, as
# a table, and a picture of it as SVG (DEMO_SVG=path, default strike-demo.svg).
DEMO_LUA ?= $(firstword $(foreach vm,luajit lua5.4 lua5.3 lua5.2 lua5.1 lua,$(shell command -v $(vm) 2>/dev/null)))
DEMO_SVG ?= strike-demo.svg
HEADLESS ?=

demo:
	@if [ -z "$(HEADLESS)" ] && command -v love >/dev/null 2>&1 && [ -n "$${DISPLAY:-}$${WAYLAND_DISPLAY:-}" ]; then \
	  echo "== love demo (HEADLESS=1 make demo for the headless example)"; love demo; \
	else \
	  $(DEMO_LUA) examples/demo.lua $(DEMO_SVG); \
	fi
