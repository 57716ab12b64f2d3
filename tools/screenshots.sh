#!/usr/bin/env bash
# Screenshots of the LÖVE demo: OUTDIR/scene1.png .. sceneN.png, each scene's scripted frame
# (its initial state, or for a scene with SHOT_FRAMES the state after that many updates:
# demo/util/scene.lua) as `love demo --screenshot FILE --scene N` draws it (800x600, help
# overlay shown), under xvfb-run (a virtual X display; software OpenGL is enough). N is the
# length of demo/scenes/list.lua, read with whichever plain Lua is installed.
#   bash tools/screenshots.sh /tmp/shots
#   STRIKE_SCREENSHOTS=/tmp/shots make spec     # spec/demo_screenshot_spec.lua checks them
set -u
[ $# -eq 1 ] || { echo "usage: $0 OUTDIR" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
for tool in love xvfb-run; do
  command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found (Debian: apt-get install love xvfb)" >&2; exit 1; }
done
lua=
for vm in lua5.4 lua5.3 lua5.2 lua5.1 luajit lua; do
  if command -v "$vm" >/dev/null 2>&1; then lua=$vm; break; fi
done
[ -n "$lua" ] || { echo "$0: no Lua interpreter found to count the scenes" >&2; exit 1; }
count=$(cd "$root" && "$lua" -e "package.path = './?.lua;' .. package.path
  io.write(#require('demo.scenes.list'))")
if ! [[ "$count" =~ ^[1-9][0-9]*$ ]]; then
  echo "$0: could not count the scenes in demo/scenes/list.lua (got '$count')" >&2; exit 1
fi
mkdir -p "$1" || { echo "$0: cannot create $1" >&2; exit 1; }
out=$(cd "$1" && pwd)
status=0
for n in $(seq 1 "$count"); do
  file="$out/scene$n.png"
  rm -f "$file"
  (cd "$root" && xvfb-run -a love demo --screenshot "$file" --scene "$n")
  rc=$?
  if [ $rc -ne 0 ]; then
    echo "$0: scene $n: love exited with code $rc" >&2; status=1
  elif [ ! -s "$file" ]; then
    echo "$0: scene $n: $file is missing or empty" >&2; status=1
  fi
done
[ $status -eq 0 ] && echo "$count screenshots in $out"
exit $status
