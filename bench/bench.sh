#!/usr/bin/env bash
# strike's benchmarks under several Lua VMs; not part of `make test`.
#
#   make bench                                     LuaJIT and Lua 5.4
#   BENCH_VMS="lua5.1 luajit" make bench           other VMs (make bench BENCH_VMS=... too)
#   STRIKE_PEERS=/path/to/peers make bench         also HC, Strike, slick, bump.lua, from
#                                                  checkouts in that folder (never copied here)
#   BENCH_ARGS="--pairs 2000" bash bench/bench.sh  extra options for bench/run.lua
#
# Runs `bench/run.lua --save`, then `bench/move.lua --save` (space:move beside bump's and
# slick's world:move), then `bench/movers.lua --save` (every body moving), then
# `bench/tiled.lua --save` (S.tiled loading a 200 x 200 map, 40 % solid, with 1,000 objects,
# its first load in fresh processes), then `bench/space.lua --save` (the world: frames, rays,
# build, churn and memory beside HC, bump and Box2D through LÖVE), under each VM in turn (never
# in parallel, so that runs do not share the CPUs); then, once, when love is on the PATH,
# `bench/narrow.lua --save` (the narrow phase at 10,000 pairs, strike beside Box2D, both timed
# inside LÖVE; bench/results/narrow-love.csv). On LuaJIT the move, the movers, the Tiled
# load and the world's frames and rays run a second time with the standalone interpreter's JIT
# limits (--jit stock), their tables counting the trace flushes. Prints each VM's tables and
# writes bench/results/<vm>.csv, move-, movers-, tiled- and space-<vm>.csv (-luajit-stock.csv
# for the stock runs). Progress goes to stderr. Fails when a VM is missing or its run fails;
# the other VMs still run.
set -u
cd "$(dirname "$0")/.." || exit 1
if [ -n "${STRIKE_PEERS:-}" ]; then
  # Absolute, since the runs start from the repository root.
  STRIKE_PEERS=$(cd "$STRIKE_PEERS" 2>/dev/null && pwd) || { echo "STRIKE_PEERS: no such folder" >&2; exit 1; }
  export STRIKE_PEERS
fi
mkdir -p bench/results
status=0; ran=()
start=$(date +%s)
for vm in ${BENCH_VMS:-luajit lua5.4}; do
  if ! command -v "$vm" >/dev/null 2>&1; then
    echo "== $vm: NOT FOUND" >&2; status=1; continue
  fi
  echo "== bench under $vm ($("$vm" -v 2>&1 | head -n 1))"
  t0=$(date +%s)
  # shellcheck disable=SC2086 # BENCH_ARGS is a list of options
  movers="$vm bench/movers.lua --save"
  if [ "$vm" = luajit ]; then movers="$movers --jit love && $vm bench/movers.lua --save --jit stock"; fi
  tiled="$vm bench/tiled.lua --save"
  if [ "$vm" = luajit ]; then tiled="$tiled --jit love && $vm bench/tiled.lua --save --jit stock"; fi
  # (the world: frames, rays, build, churn, memory beside the peers; on LuaJIT the move and
  # the world under the stock limits too, where the tables count the trace flushes)
  space="$vm bench/space.lua --save"
  move="$vm bench/move.lua --save"
  if [ "$vm" = luajit ]; then
    space="$space --jit love && $vm bench/space.lua --save --jit stock --sections frame,rays"
    move="$move --jit love && $vm bench/move.lua --save --jit stock"
  fi
  if "$vm" bench/run.lua --save ${BENCH_ARGS:-} && eval "$move" && eval "$movers" \
    && eval "$tiled" && eval "$space"; then
    ran+=("$vm")
    echo "== $vm: $(( $(date +%s) - t0 )) s"
  else
    echo "== $vm: FAILED" >&2; status=1
  fi
  echo
done
# The narrow phase beside Box2D (issue 21's target 5): once, not per VM, since it is timed in
# LÖVE under LÖVE's LuaJIT; bench/narrow.lua itself runs under the first VM found.
if command -v love >/dev/null 2>&1; then
  lua=""
  for vm in ${BENCH_VMS:-luajit lua5.4}; do
    if command -v "$vm" >/dev/null 2>&1; then lua=$vm; break; fi
  done
  echo "== the narrow phase beside Box2D, inside LÖVE"
  t0=$(date +%s)
  if [ -n "$lua" ] && "$lua" bench/narrow.lua --save; then
    echo "== narrow phase: $(( $(date +%s) - t0 )) s"
  else
    echo "== narrow phase: FAILED" >&2; status=1
  fi
  echo
else
  echo "== the narrow phase beside Box2D: skipped (no love on the PATH)"
fi
echo "== VMs run: ${ran[*]:-none}; $(( $(date +%s) - start )) s in all"
exit $status
