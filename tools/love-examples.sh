#!/usr/bin/env bash
# The example games under LÖVE: `love examples/<name> --frames N` for each of them, under
# xvfb-run, must quit by itself with exit code 0 and print its status line. A Lua error in a
# game would show LÖVE's error screen, which never quits: the timeout fails it. The games'
# play is checked headless by spec/examples_spec.lua; this checks them against LÖVE itself.
#   bash tools/love-examples.sh [FRAMES]
set -u
frames=${1:-120}
root=$(cd "$(dirname "$0")/.." && pwd)
for tool in love xvfb-run timeout; do
  command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found (Debian: apt-get install love xvfb)" >&2; exit 1; }
done
status=0; ran=0
for name in platformer shooter tiled; do
  out=$(cd "$root" && timeout 60 xvfb-run -a love "examples/$name" --frames "$frames" 2>&1)
  rc=$?
  last=$(printf '%s\n' "$out" | grep -v '^\s*$' | tail -n 1)
  if [ $rc -ne 0 ]; then
    echo "$0: examples/$name: love exited with code $rc$([ $rc -eq 124 ] && echo ' (timed out: a Lua error?)')" >&2
    printf '%s\n' "$out" >&2; status=1
  elif [ -z "$last" ]; then
    echo "$0: examples/$name: no status line printed" >&2; status=1
  else
    echo "examples/$name after $frames frames: $last"
    ran=$((ran + 1))
  fi
done
[ $status -eq 0 ] && echo "$ran examples ran under LÖVE"
exit $status
